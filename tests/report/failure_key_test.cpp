// What counts as failing "the same way" (report/CellGroups.h failure_key): one bug in one
// shader fails its paths and shapes with different numbers but one key; another way of
// failing, another attribution or another language gets another key.
#include <gtest/gtest.h>

#include "report/CellGroups.h"

namespace shaderbed {
namespace {

CellResult failing_cell(std::string backend, std::string path, std::string shape, std::string message) {
  CellResult r;
  r.case_name = "lambert_light_register";
  r.variant = "pixel";
  r.language = "hlsl";
  r.backend = std::move(backend);
  r.path = std::move(path);
  r.shape = std::move(shape);
  r.status = CellStatus::fail;
  r.message = std::move(message);
  r.attribution = "front end";
  return r;
}

TEST(FailureKey, SameFailureWithOtherNumbersOnOtherCellsIsOneKey) {
  const CellResult a = failing_cell("vulkan", "spirv", "cube", "interior max error 1.00e+02 > 1.00e-03 (411 pixels)");
  const CellResult b = failing_cell("gl", "cross", "torus", "interior max error 1.10e+02 > 1.00e-03 (1380 pixels)");
  EXPECT_EQ(failure_key(a), failure_key(b));
}

TEST(FailureKey, AnotherWayOfFailingIsAnotherKey) {
  const CellResult a = failing_cell("vulkan", "spirv", "cube", "interior max error 1.00e+02 > 1.00e-03");
  CellResult coverage = failing_cell("vulkan", "spirv", "sphere", "coverage: 12 interior pixels not drawn");
  EXPECT_NE(failure_key(a), failure_key(coverage));
  CellResult other_language = a;
  other_language.language = "cg";
  EXPECT_NE(failure_key(a), failure_key(other_language));
  CellResult driver = a;
  driver.attribution = "driver";
  EXPECT_NE(failure_key(a), failure_key(driver));
  CellResult known = a;
  known.known_failure = true;
  EXPECT_NE(failure_key(a), failure_key(known));
  CellResult explained = a;
  explained.explanations = {{"constant_factor", "x pi", 1e-6, 1e-7, 100, true, "matches the reference x pi"}};
  EXPECT_NE(failure_key(a), failure_key(explained));
  CellResult departs = a, departs_later = a;
  departs.divergence = CellResult::Divergence{.kind = "found", .file = "port.frag", .line = 16};
  departs_later.divergence = CellResult::Divergence{.kind = "found", .file = "port.frag", .line = 17};
  EXPECT_NE(failure_key(departs), failure_key(departs_later));
  // Digits that are part of a word are words: c5 is not c7.
  EXPECT_NE(failure_key(failing_cell("vulkan", "spirv", "cube", "register c5 unbound")),
            failure_key(failing_cell("vulkan", "spirv", "cube", "register c7 unbound")));
}

}  // namespace
}  // namespace shaderbed
