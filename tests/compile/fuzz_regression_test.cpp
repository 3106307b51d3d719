// Inputs the fuzz targets (fuzz/) found crashing the text layers before glslang; each is
// also in the target's corpus as fuzz/corpus/<target>/crash_*. Each must now be an error
// naming its line, or pass through, never an exception or a sanitizer report.
#include <string>

#include <gtest/gtest.h>

#include "compile/Compiler.h"
#include "compile/GlslDialect.h"

namespace shaderbed {
namespace {

Result<PreparedGlsl> prepare(std::string vertex, std::string fragment) {
  return prepare_glsl_program(ProgramSource{
      .language = Language::glsl,
      .vertex = {.stage = Stage::vertex, .path = "fuzz.vert", .text = std::move(vertex)},
      .fragment = {.stage = Stage::fragment, .path = "fuzz.frag", .text = std::move(fragment)}});
}

const std::string kVertex =
    "#version 330\n"
    "layout(location = 0) in vec3 position;\n"
    "out vec3 color;\n"
    "void main() { color = position; gl_Position = vec4(position, 1.0); }\n";

// legacy_glsl_fuzzer: `layout(location =.0)` lexes .0 as a number; std::stoi threw
// std::invalid_argument out of assign_varying_locations.
TEST(FuzzRegression, NonIntegerVaryingLocationIsAnError) {
  const std::string fragment =
      "#version 330\n"
      "layout(location =.0) in vec3 color;\n"
      "out vec4 result;\n"
      "void main() { result = vec4(color, 1.0); }\n";
  auto prepared = prepare(kVertex, fragment);
  ASSERT_FALSE(prepared);
  EXPECT_EQ(prepared.error().line, 2);
  EXPECT_NE(prepared.error().message.find("'.0'"), std::string::npos) << prepared.error().message;
}

// The same parse on a location or array size out of int's range (std::out_of_range), and on
// sizes that would overflow the location arithmetic.
TEST(FuzzRegression, OutOfRangeVaryingLocationIsAnError) {
  const std::string fragment =
      "#version 330\n"
      "layout(location = 99999999999) in vec3 color;\n"
      "out vec4 result;\n"
      "void main() { result = vec4(color, 1.0); }\n";
  auto prepared = prepare(kVertex, fragment);
  ASSERT_FALSE(prepared);
  EXPECT_EQ(prepared.error().line, 2);
}

TEST(FuzzRegression, HugeVaryingArrayIsAnError) {
  const std::string fragment =
      "#version 330\n"
      "in vec3 color;\n"
      "in vec4 extra[2147483647];\n"
      "out vec4 result;\n"
      "void main() { result = vec4(color, 1.0); }\n";
  auto prepared = prepare(kVertex, fragment);
  ASSERT_FALSE(prepared);
  EXPECT_EQ(prepared.error().line, 3);
}

TEST(FuzzRegression, LiteralLocationsStillParse) {
  const std::string fragment =
      "#version 330\n"
      "layout(location = 0x0) in vec3 color;\n"
      "out vec4 result;\n"
      "void main() { result = vec4(color, 1.0); }\n";
  EXPECT_TRUE(prepare(kVertex, fragment));
}

}  // namespace
}  // namespace shaderbed
