#include "vesica/core/Suggest.h"

#include <algorithm>
#include <numeric>

namespace vesica {
namespace {

// "mu" is "mu_kpa" (or "mu-kpa") without its unit: the candidate continues the word
// after a separator.
bool cut_short(const std::string& word, const std::string& candidate) {
  return !word.empty() && candidate.size() > word.size() + 1 &&
         candidate.compare(0, word.size(), word) == 0 &&
         (candidate[word.size()] == '_' || candidate[word.size()] == '-');
}

}  // namespace

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  // A third of the word's letters (at least one, at most three) may differ: beyond that
  // the suggestion is more confusing than helpful.
  const std::size_t allowed = std::clamp<std::size_t>(word.size() / 3, 1, 3);
  if (best_distance <= allowed) return best;
  // Else the shortest candidate the word is a cut-short form of.
  std::string shortest;
  for (const auto& c : candidates)
    if (cut_short(word, c) && (shortest.empty() || c.size() < shortest.size())) shortest = c;
  return shortest;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string m = closest_match(word, candidates);
  return m.empty() ? std::string() : " (did you mean '" + m + "'?)";
}

}  // namespace vesica
