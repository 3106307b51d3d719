#pragma once
// Runs the hard-case suite: for every selected case, scenario, variant (the book's
// `vertex` and `pixel`, and `pixel_robust` where the case has one), language and backend,
// renders the scenario, evaluates the reference in double and measures the numerical
// error (compare/NumericalError.h).
//
// Pixels are judged as follows. Slices: every pixel counts for NaN/Inf; the error is
// measured except within kConditioningMargin of a place where the model is
// discontinuous or undefined (|N.L| or |N.V| small: the hemisphere gates; |L + V| small:
// H undefined), where the fp32 rounding of one dot decides the branch and no shader can
// match the double reference. Mesh scenes: interior pixels measured, the silhouette band
// counted for NaN/Inf only.
//
// A row passes when the render is non-finite nowhere the reference is finite (and the
// reverse) and its max relative error is within kRelativeTolerance.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "compare/NumericalError.h"
#include "core/Error.h"
#include "core/Image.h"
#include "report/Results.h"
#include "twin/SignificanceLoss.h"

namespace shaderbed::hard {

constexpr double kConditioningMargin = 1e-4;
// fp32 against double for well-conditioned pixels is ~1e-6; the sharp lobes lose more
// (a relative error e in a dot becomes n*e in dot^n, and 1 - N.H near the peak of an
// m = 0.001 lobe is itself ~1e-7): 1e-2 separates that from a broken formula.
constexpr double kRelativeTolerance = 1e-2;

struct HardOptions {
  std::vector<std::string> cases, backends, languages, scenarios;   // empty = all
  // Case files of the user's own (`--case path/to/case.toml`): every variant and language of
  // the case on the slices of user_scenarios() (Scenarios.h), judged against the shader's
  // own double twin, each row naming the line that loses significance at its worst pixel.
  std::vector<std::string> user_cases;
  int size = 128;
  bool all_paths = false;                                           // every GL path, not only the first
  std::string out_dir;                                              // slice images, "" = none
  std::string cases_dir;                                            // "" = the library's
  std::function<void(const std::string&)> progress;                 // one line per step
};

struct HardRow {
  std::string case_name, scenario, variant, kind;   // kind: "book" or "robust"
  std::string language, backend, path;
  CellStatus status = CellStatus::error;            // pass, fail or error
  std::string message;
  int width = 0;                                    // of the image, for pixel coordinates
  NumericalError error;
  std::string reference = "model";                  // "model" (the library), "twin-double" (a user case)
  // A user case: at the worst pixel (the largest relative error, else the first NaN/Inf on one
  // side only), the first instruction whose fp32 value departs from the double one by far
  // more than its operands' (twin::significance_loss).
  int worst_x = -1, worst_y = -1;
  std::optional<twin::SignificanceLoss> loss;
  std::string loss_note;                            // why there is none ("" when loss is set)
};

struct ModelSummary {
  std::string case_name;
  bool has_robust = false;
  size_t book_nonfinite = 0, robust_nonfinite = 0;          // render pixels with NaN/Inf, summed over rows
  size_t book_mismatch = 0, robust_mismatch = 0;            // of those, where the reference is finite (or reverse)
  double book_max_relative = 0, robust_max_relative = 0;
  uint64_t book_max_ulps = 0, robust_max_ulps = 0;
  size_t book_failed = 0, robust_failed = 0;                // rows
  bool user = false;                                        // a user case: every variant is "book", against its twin
};

struct HardReport {
  int size = 0;
  std::vector<std::string> scenarios;                        // names in the order run
  std::map<std::string, std::string> scenario_probes;        // name -> what it probes
  std::vector<HardRow> rows;
  std::vector<ModelSummary> summaries;
  double wall_ms = 0;
};

Result<HardReport> run_hard_cases(const HardOptions&);

}  // namespace shaderbed::hard
