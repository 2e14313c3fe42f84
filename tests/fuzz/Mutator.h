#pragma once
// Deterministic mutations of a file's bytes, as a fuzzer makes them: bits flipped, bytes
// and integers overwritten with boundary values, chunks cut, repeated or inserted, the
// file truncated, and in text files numbers replaced by extremes (nan, inf, -1, 0, 1e308,
// huge counts). Case i of a run is a pure function of (seed, i), so a failure can be
// reproduced from its number alone.
#include <cstdint>
#include <string>

namespace vesica::fuzz {

// `original` mutated 1-4 times, chosen by the generator seeded with (seed, case_index).
std::string mutate(const std::string& original, std::uint64_t seed, std::uint64_t case_index);

}  // namespace vesica::fuzz
