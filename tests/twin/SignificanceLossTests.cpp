// twin::significance_loss: the first instruction whose fp32 result departs from the double
// one by far more than its operands do, named by its source line.
#include <cmath>

#include <gtest/gtest.h>

#include "TwinTestSupport.h"
#include "twin/SignificanceLoss.h"

namespace {

using namespace twin_tests;

// Line 5 adds a small b to a big a and line 6 takes a away again: in fp32 b is lost when
// a = 2^24 (the sum rounds to a). Line 8 is 1 - cos(x): for tiny x the fp32 cosine's
// rounding (6e-8) is most of the difference.
constexpr const char* kCancelling = R"(#version 450
layout(std140, set = 0, binding = 0) uniform Inputs { float a; float b; float x; };
layout(location = 0) out vec4 colour;
void main() {
  float sum = a + b;
  float back = sum - a;
  float c = cos(x);
  float lost = 1.0 - c;
  colour = vec4(back, lost, 0.0, 1.0);
}
)";

struct Traced {
  twin::Program program;
  BlockBytes block{16};
  twin::BoundResources resources;
  Mesh quad = full_screen_quad();

  Traced(twin::Program p, float a, float b, float x) : program(std::move(p)) {
    block.put_float(0, a);
    block.put_float(4, b);
    block.put_float(8, x);
    resources.buffers[{0, 0}] = {block.bytes(), {}};
  }
  twin::TwinResult<std::optional<twin::SignificanceLoss>> at(int px, int py) const {
    const twin::DrawInput input{.program = program, .resources = resources, .streams = quad.streams,
                                .vertex_count = quad.vertex_count, .indices = quad.indices, .width = 4, .height = 4};
    return twin::significance_loss(input, px, py);
  }
};

TEST(SignificanceLoss, NamesTheSubtractionThatCancelsAHugeSum) {
  auto program = glsl_program(pass_through_vertex, kCancelling);
  ASSERT_TRUE(program) << program.error();
  const Traced traced(*program, 16777216.0f, 1.0f, 0.5f);
  auto loss = traced.at(1, 2);
  ASSERT_TRUE(loss) << loss.error().to_string();
  ASSERT_TRUE(loss->has_value());
  const twin::SignificanceLoss& l = **loss;
  EXPECT_EQ(l.origin.file, "test.frag");
  EXPECT_EQ(l.origin.line, 6) << l.describe();
  EXPECT_EQ(l.origin.operation, "OpFSub");
  ASSERT_EQ(l.origin.values.size(), 1u);
  EXPECT_EQ(l.origin.values[0], 0.0);   // fp32: 2^24 + 1 rounds to 2^24
  EXPECT_EQ(l.exact_values[0], 1.0);    // double keeps b
  EXPECT_DOUBLE_EQ(l.relative_error, 1.0);
  EXPECT_LT(l.operand_relative_error, 1e-7);   // the sum's own rounding, 2^-24
  // (The test's source is no file on disk and the module carries no text: no source line.)
  EXPECT_NE(l.describe().find("test.frag:6: OpFSub(sum = 16777216 [double 16777217]"),
            std::string::npos)
      << l.describe();
}

TEST(SignificanceLoss, NamesOneMinusCosineOfATinyAngle) {
  auto program = glsl_program(pass_through_vertex, kCancelling);
  ASSERT_TRUE(program) << program.error();
  const Traced traced(*program, 1.0f, 0.5f, 1e-3f);
  auto loss = traced.at(2, 1);
  ASSERT_TRUE(loss) << loss.error().to_string();
  ASSERT_TRUE(loss->has_value());
  const twin::SignificanceLoss& l = **loss;
  EXPECT_EQ(l.origin.line, 8) << l.describe();
  EXPECT_GT(l.relative_error, 1e-2);   // 4.77e-7 against 5.0e-7
  ASSERT_EQ(l.origin.operands.size(), 2u);
  EXPECT_EQ(l.origin.operands[1].first, "c");
}

TEST(SignificanceLoss, NothingWhereNoInstructionLosesSignificance) {
  auto program = glsl_program(pass_through_vertex, kCancelling);
  ASSERT_TRUE(program) << program.error();
  const Traced traced(*program, 1.0f, 0.5f, 0.5f);
  auto loss = traced.at(0, 0);
  ASSERT_TRUE(loss) << loss.error().to_string();
  EXPECT_FALSE(loss->has_value()) << (*loss)->describe();
}

TEST(SignificanceLoss, UncoveredPixelIsAnError) {
  auto program = glsl_program(pass_through_vertex, kCancelling);
  ASSERT_TRUE(program) << program.error();
  const Traced traced(*program, 1.0f, 0.5f, 0.5f);
  EXPECT_FALSE(traced.at(7, 7));
}

TEST(SignificanceLoss, RelativeErrorOfNonFiniteValues) {
  const double inf = INFINITY, nan = NAN;
  EXPECT_EQ(twin::relative_error(nan, 1.0, 1e-30), inf);
  EXPECT_EQ(twin::relative_error(inf, 1.0, 1e-30), inf);
  EXPECT_EQ(twin::relative_error(nan, nan, 1e-30), 0.0);
  EXPECT_EQ(twin::relative_error(inf, inf, 1e-30), 0.0);
  EXPECT_EQ(twin::relative_error(-inf, inf, 1e-30), inf);
  EXPECT_DOUBLE_EQ(twin::relative_error(1.5, 1.0, 1e-30), 0.5);
  EXPECT_DOUBLE_EQ(twin::relative_error(1e-31, 0.0, 1e-30), 0.1);
}

}  // namespace
