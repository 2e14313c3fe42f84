#pragma once
// What an FEBio export cannot hold exactly (FebioExport.h): each gap names the vesica
// parameter with its value and says what FEBio's file writes instead. Without
// `approximate` the first gap is a usage error, before anything is written.
#include <string>
#include <vector>

namespace vesica::simulate {

class FebioGaps {
 public:
  explicit FebioGaps(bool approximate) : approximate_(approximate) {}

  // `what`: the parameter and its value with why FEBio has no equal ("beta_vol = 9: FEBio's
  // uncoupled laws have only K/2 (ln J)^2"); `nearest`: what the file writes instead.
  // Throws vesica::Error (usage) unless approximating.
  void approximate(const std::string& what, const std::string& nearest);

  // Something FEBio's file cannot stand in for at all: always a usage error.
  [[noreturn]] static void refuse(const std::string& what, const std::string& hint);

  // One line per gap: "what; written as nearest".
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  bool approximate_;
  std::vector<std::string> lines_;
};

}  // namespace vesica::simulate
