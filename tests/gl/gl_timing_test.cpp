// Programs are linked once per path and reused; timed draws repeat with GL_TIME_ELAPSED
// and a wall clock, and a cached program draws the same image.
#include <gtest/gtest.h>

#include "GlTestSupport.h"

namespace shaderbed::gl_test {
namespace {

// A colour no other GL test draws, so no earlier test has linked this program.
const char* const kTimedColour = R"(#version 450
layout(location = 0) out vec4 colour;
void main() { colour = vec4(0.5, 0.25, 2.0, 0.375); }
)";

class GlTiming : public ::testing::TestWithParam<ShaderPath> {};

TEST_P(GlTiming, LinksOnceAndTimesRepeatedDraws) {
  auto backend = gl_backend();
  ASSERT_TRUE(backend) << backend.error().to_string();
  auto program = compile_glsl(kPassThroughVertex, kTimedColour);
  ASSERT_TRUE(program) << program.error().to_string();
  const MapResolver none;
  const Mesh quad = ndc_rectangle(-1, -1, 1, 1);
  const DrawJob job{.program = *program, .path = GetParam(), .mesh = quad, .uniforms = none, .width = 128,
                    .height = 128, .timing = {.warmup = 1, .runs = 3}};
  auto first = (*backend)->render(job);
  ASSERT_TRUE(first) << first.error().to_string();
  auto second = (*backend)->render(job);
  ASSERT_TRUE(second) << second.error().to_string();

  EXPECT_FALSE(first->timings.program_cached);
  EXPECT_GT(first->timings.build_ms, 0.0);
  EXPECT_TRUE(second->timings.program_cached);
  EXPECT_EQ(second->timings.build_ms, 0.0);
  EXPECT_EQ(first->image.rgba, second->image.rgba);
  EXPECT_EQ(second->image.rgba[2], 2.0f);   // the repeats did not disturb the image read back
  for (const RenderTimings* t : {&first->timings, &second->timings}) {
    EXPECT_EQ(t->gpu_clock, "GL_TIME_ELAPSED");
    ASSERT_EQ(t->gpu_ms.size(), 3u);
    ASSERT_EQ(t->wall_ms.size(), 3u);
    for (double ms : t->wall_ms) EXPECT_GT(ms, 0.0);
    for (double ms : t->gpu_ms) EXPECT_GE(ms, 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, GlTiming,
                         ::testing::Values(ShaderPath::native_glsl, ShaderPath::spirv, ShaderPath::cross_glsl),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace shaderbed::gl_test
