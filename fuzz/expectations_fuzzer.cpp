// libFuzzer target: the expectations matcher (run/Expectations.h). The input is an
// expectations file (load_expectations reads a path, so it is written to a scratch file);
// its patterns are then matched against a few cells, and its first two lines are also
// matched directly as a pattern and a cell id, so the glob sees any bytes.
#include <cstddef>
#include <cstdint>

#include "FuzzSupport.h"
#include "run/Expectations.h"

namespace {

shaderbed::CellResult cell(shaderbed::CellStatus status, std::string case_name, std::string shape) {
  shaderbed::CellResult r;
  r.case_name = std::move(case_name);
  r.variant = "pixel";
  r.language = "hlsl";
  r.backend = "gl";
  r.path = "spirv";
  r.shape = std::move(shape);
  r.status = status;
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace shaderbed;
  const std::string_view text = fuzz::as_text(data, size);

  const size_t first = text.find('\n');
  if (first != std::string_view::npos) {
    const size_t second = text.find('\n', first + 1);
    const std::string pattern(text.substr(0, first));
    const std::string id(text.substr(first + 1, second == std::string_view::npos ? std::string_view::npos
                                                                               : second - first - 1));
    (void)matches(pattern, id);
  }

  const std::string path = fuzz::write_scratch(text, "expectations", "expectations.toml");
  auto known = load_expectations(path);
  if (!known) {
    (void)known.error().to_string();
    return 0;
  }
  RunReport report;
  report.results = {cell(CellStatus::fail, "warn", "torus"), cell(CellStatus::pass, "phong", "cube"), cell(CellStatus::error, "a*b", "*")};
  for (const KnownFailure& k : *known)
    for (const CellResult& r : report.results) (void)matches(k.pattern, r.id());
  (void)apply_expectations(*known, report);
  return 0;
}
