#pragma once
// "Did you mean" suggestions for misspelt keys, options, commands and stage names.
#include <string>
#include <vector>

namespace vesica {

// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b);

// The closest candidate when it is close enough to be a likely typo, else "". A word
// that is a candidate cut short before its unit or qualifier ("mu" for "mu_kpa",
// "edge" for "edge-mm") counts as close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" or "" — ready to append to a message.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace vesica
