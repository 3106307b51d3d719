#include "backends/gl/MesaInfoLog.h"

#include <gtest/gtest.h>

namespace shaderbed::gl {
namespace {

TEST(MesaInfoLog, TakesLineAndColumnOfTheFirstError) {
  const MesaLogError e = first_mesa_error(
      "0:12(3): warning: unused\n0:14(7): error: `x' undeclared\n0:15(2): error: type mismatch\n");
  EXPECT_EQ(e.line, 14);
  EXPECT_EQ(e.column, 7);
  EXPECT_EQ(e.message, "`x' undeclared (+1 more errors)");
}

TEST(MesaInfoLog, ReadsPreprocessorErrors) {
  const MesaLogError e = first_mesa_error("0:2(1): preprocessor error: Invalid tokens after #\n");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.message, "Invalid tokens after #");
}

TEST(MesaInfoLog, LinkerErrorsHaveNoPosition) {
  const MesaLogError e = first_mesa_error("error: fragment shader input `uv' has no matching output\n");
  EXPECT_EQ(e.line, 0);
  EXPECT_EQ(e.message, "fragment shader input `uv' has no matching output");
}

TEST(MesaInfoLog, KeepsAnUnknownFormatAsText) {
  EXPECT_EQ(first_mesa_error("\n  something odd happened\nmore").message, "something odd happened");
  EXPECT_EQ(first_mesa_error("").message, "");
}

}  // namespace
}  // namespace shaderbed::gl
