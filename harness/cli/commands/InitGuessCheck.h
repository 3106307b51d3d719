#pragma once
// `shaderbed init` checks its own guesses: it runs the case it drafted, and when that run
// shows a blank or misplaced original or a port that disagrees, it switches each guess it
// was unsure of (author/CaseDraft.h GuessDoubt: row or column vectors, position or
// direction, what a w holds), one at a time, the original's first, and keeps a switch when
// the original then makes a valid reference or more cells agree. What it changed, and the
// doubts no run confirmed, are in the result, with their case-file lines.
#include <optional>
#include <string>
#include <vector>

#include "author/CaseDraft.h"
#include "report/Results.h"

namespace shaderbed {

// What one run of the drafted case says about its guesses.
struct GuessRunScore {
  bool loads = false;
  size_t cells = 0;
  size_t no_reference = 0;   // cells judged against an original that drew no valid reference
  size_t not_passed = 0;     // failed or error cells (known failures and skips aside)
  double rmse = 0;           // summed over the cells, to tell two failing runs apart
  std::vector<Language> failing;   // languages with a cell that did not pass
  bool all_pass() const { return loads && not_passed == 0; }
  std::string text() const;        // "every cell passes", "the original is no reference (28 cells)", "12 of 28 cells differ"
};

struct GuessCheck {
  CaseDraft draft;                       // as written last (the kept switches)
  std::optional<RunReport> report;       // its run; nullopt when it does not load
  std::string load_error;
  GuessRunScore score;
  std::vector<std::string> changed;      // "lines 12, 13: 'g_WorldViewProj', 'g_World' now ...: before ..., after ..."
  std::vector<std::string> tried;        // switches tried and not kept, with what they gave
  // Guesses no run confirmed while cells still fail, and the TODOs: "line 9: 'g_LightPos' = ...".
  std::vector<std::string> check_first;
};

struct GuessCheckInput {
  std::vector<SurveyedLanguage> languages;
  std::string case_path;
  std::vector<std::string> images;
  int size = 64;
};

// Writes the case (each switch rewrites it whole) and runs it; the first run shows progress
// on stderr, the trials print one line each on stdout. Errors: the case cannot be written.
Result<GuessCheck> check_guesses(const GuessCheckInput& input);

}  // namespace shaderbed
