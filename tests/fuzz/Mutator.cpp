#include "Mutator.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <random>

namespace vesica::fuzz {
namespace {

using Random = std::mt19937_64;

std::size_t position(Random& rng, std::size_t size) {
  return size == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, size - 1)(rng);
}

// A chunk length, mostly short: long cuts remove whole sections too often to be useful.
std::size_t chunk(Random& rng, std::size_t size) {
  const std::size_t limit = std::max<std::size_t>(1, std::min<std::size_t>(size, 64));
  return std::uniform_int_distribution<std::size_t>(1, limit)(rng);
}

void flip_bits(Random& rng, std::string& s) {
  if (s.empty()) return;
  const int flips = std::uniform_int_distribution<int>(1, 8)(rng);
  for (int k = 0; k < flips; ++k)
    s[position(rng, s.size())] ^=
        static_cast<char>(1u << std::uniform_int_distribution<int>(0, 7)(rng));
}

void random_bytes(Random& rng, std::string& s) {
  if (s.empty()) return;
  const std::size_t at = position(rng, s.size()), n = std::min(chunk(rng, s.size()), s.size() - at);
  for (std::size_t k = 0; k < n; ++k) s[at + k] = static_cast<char>(rng() & 0xFF);
}

// Boundary integers written over the bytes (little-endian): header counts and sizes.
void boundary_integer(Random& rng, std::string& s) {
  static constexpr std::array<std::uint64_t, 10> values = {
      0, 1, 0x7F, 0xFF, 0x7FFF, 0xFFFF, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0xFFFFFFFFFFFFFFFF};
  if (s.empty()) return;
  const std::uint64_t v = values[position(rng, values.size())];
  const std::size_t width = std::size_t{1} << std::uniform_int_distribution<int>(0, 3)(rng);
  const std::size_t at = position(rng, s.size());
  for (std::size_t k = 0; k < width && at + k < s.size(); ++k)
    s[at + k] = static_cast<char>((v >> (8 * k)) & 0xFF);
}

void truncate(Random& rng, std::string& s) {
  s.resize(position(rng, s.size() + 1));
}

void cut(Random& rng, std::string& s) {
  if (s.empty()) return;
  const std::size_t at = position(rng, s.size());
  s.erase(at, chunk(rng, s.size()));
}

void repeat(Random& rng, std::string& s) {
  if (s.empty()) return;
  const std::size_t at = position(rng, s.size());
  const std::string piece = s.substr(at, chunk(rng, s.size()));
  const int times = std::uniform_int_distribution<int>(1, 16)(rng);
  std::string block;
  for (int k = 0; k < times; ++k) block += piece;
  s.insert(position(rng, s.size() + 1), block);
}

void insert_bytes(Random& rng, std::string& s) {
  std::string block(chunk(rng, 64), '\0');
  for (char& c : block) c = static_cast<char>(rng() & 0xFF);
  s.insert(position(rng, s.size() + 1), block);
}

// A number in a text file replaced by one a reader must not trust.
void extreme_number(Random& rng, std::string& s) {
  static constexpr std::array<const char*, 12> values = {
      "nan",         "inf",        "-inf",
      "-1",          "0",          "1e308",
      "-1e308",      "4294967295", "18446744073709551616",
      "99999999999", "1e-320",     "2147483648"};
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (std::isdigit(static_cast<unsigned char>(s[i])) &&
        (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '-'))
      starts.push_back(i);
  if (starts.empty()) return insert_bytes(rng, s);
  const std::size_t at = starts[position(rng, starts.size())];
  std::size_t end = at;
  while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '.' ||
                            s[end] == '-' || s[end] == '+'))
    ++end;
  s.replace(at, end - at, values[position(rng, values.size())]);
}

}  // namespace

std::string mutate(const std::string& original, std::uint64_t seed, std::uint64_t case_index) {
  Random rng(seed * 0x9E3779B97F4A7C15ull + case_index);
  using Mutation = void (*)(Random&, std::string&);
  static constexpr std::array<Mutation, 9> mutations = {
      flip_bits, random_bytes, boundary_integer, truncate,      cut,
      repeat,    insert_bytes, extreme_number,   extreme_number};
  std::string s = original;
  const int count = std::uniform_int_distribution<int>(1, 4)(rng);
  for (int k = 0; k < count; ++k) mutations[position(rng, mutations.size())](rng, s);
  return s;
}

}  // namespace vesica::fuzz
