// Divergence localisation (twin/Divergence.h) on programs small enough to know the answer:
// a port renamed and respelt matches its original everywhere, a planted change is named by
// its line, a varying that departs is followed into the vertex stage, and the pixel listing
// says which values match.
#include <gtest/gtest.h>

#include "tests/twin/TwinTestSupport.h"
#include "twin/Divergence.h"
#include "twin/PixelListing.h"

namespace twin_tests {
namespace {

using namespace twin;

// A varying v = position.xy * 0.5 + 0.5 (line 5), read by the fragment stage.
constexpr const char* vertex = R"(#version 450
layout(location = 0) in vec4 position;
layout(location = 0) out vec2 v;
void main() {
  v = position.xy * 0.5 + 0.5;
  gl_Position = position;
}
)";

constexpr const char* original = R"(#version 450
layout(location = 0) in vec2 v;
layout(location = 0) out vec4 colour;
void main() {
  float a = v.x * v.x + 0.25;
  float b = sqrt(a) * v.y;
  float c = b / (1.0 + a);
  colour = vec4(c, a, b, 1.0);
}
)";

// The same arithmetic, renamed, reordered and respelt: no line departs.
constexpr const char* correct_port = R"(#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
void main() {
  float s = 0.25 + uv.x * uv.x;
  float t = uv.y * sqrt(s);
  result = vec4(t / (s + 1.0), s, t, 1.0);
}
)";

// The correct port with one change on line 6: the planted line.
constexpr const char* planted_port = R"(#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
void main() {
  float s = 0.25 + uv.x * uv.x;
  float t = uv.y * sqrt(s + 1.0);
  result = vec4(t / (s + 1.0), s, t, 1.0);
}
)";

struct Traced {
  Program program;
  BoundResources resources;
  Mesh mesh = full_screen_quad();
  ProgramTrace fragment, vertex;
};

std::vector<PixelAt> spread() {
  std::vector<PixelAt> pixels;
  for (int y = 1; y < 16; y += 5)
    for (int x = 2; x < 16; x += 4) pixels.push_back({x, y});
  return pixels;
}

Traced traced(const char* vs, const char* fs) {
  auto program = glsl_program(vs, fs);
  EXPECT_TRUE(program) << program.error();
  Traced t{*program, {}, full_screen_quad(), {}, {}};
  const DrawInput input{.program = t.program,
                        .resources = t.resources,
                        .streams = t.mesh.streams,
                        .vertex_count = t.mesh.vertex_count,
                        .indices = t.mesh.indices,
                        .width = 16,
                        .height = 16};
  const std::vector<PixelAt> pixels = spread();
  auto fragment = trace_program(input, pixels);
  EXPECT_TRUE(fragment) << fragment.error().to_string();
  auto vertices = trace_vertex_program(input, 4);
  EXPECT_TRUE(vertices) << vertices.error().to_string();
  t.fragment = std::move(*fragment);
  t.vertex = std::move(*vertices);
  return t;
}

TEST(Divergence, ACorrectPortRenamedAndRespeltMatchesItsOriginal) {
  const Traced o = traced(vertex, original), p = traced(vertex, correct_port);
  ASSERT_EQ(p.fragment.pixels.size(), 12u);
  const Divergence d = localise_divergence(p.fragment, counterparts_of(o.fragment));
  EXPECT_EQ(d.kind, Divergence::Kind::output_matches) << d.describe();
}

TEST(Divergence, NamesThePlantedLineItsOperandsAndTheNearestValue) {
  const Traced o = traced(vertex, original), p = traced(vertex, planted_port);
  const Divergence d = localise_divergence(p.fragment, counterparts_of(o.fragment));
  ASSERT_EQ(d.kind, Divergence::Kind::found) << d.describe();
  EXPECT_EQ(d.stage, "fragment");
  EXPECT_EQ(d.file, "test.frag");
  EXPECT_EQ(d.line, 6) << d.describe();
  ASSERT_FALSE(d.operands.empty());
  EXPECT_EQ(d.operands.front().name, "s");
  EXPECT_EQ(d.operands.front().matches.substr(0, 11), "test.frag:5") << "s is the original's a, on its line 5";
  ASSERT_TRUE(d.nearest) << d.describe();
  // (No source text: test.frag is not on disk and the compile stage embeds none.)
  EXPECT_EQ(d.describe().rfind("test.frag:6  s matches test.frag:5", 0), 0u) << d.describe();
  EXPECT_NE(d.describe().find("the result matches nothing in the original"), std::string::npos) << d.describe();
}

TEST(Divergence, AVaryingThatDepartsIsFollowedIntoTheVertexStage) {
  // The port's vertex stage scales the varying (line 5); its fragment stage is correct.
  const std::string scaled = std::string(vertex).replace(std::string(vertex).find("* 0.5 + 0.5"), 11, "* 0.5 + 0.25");
  const Traced o = traced(vertex, original), p = traced(scaled.c_str(), correct_port);
  const Divergence fragment = localise_divergence(p.fragment, counterparts_of(o.fragment));
  ASSERT_EQ(fragment.kind, Divergence::Kind::found) << fragment.describe();
  EXPECT_GE(fragment.varying_location, 0) << fragment.describe();
  const Divergence d = into_vertex_stage(fragment, p.vertex, counterparts_of(o.vertex));
  EXPECT_EQ(d.stage, "vertex") << d.describe();
  EXPECT_EQ(d.file, "test.vert");
  EXPECT_EQ(d.line, 5) << d.describe();
}

TEST(Divergence, ThePixelListingSaysWhatEachLineComputedAndWhatItMatches) {
  const Traced o = traced(vertex, original), p = traced(vertex, planted_port);
  const std::vector<ListedLine> lines = pixel_listing(p.fragment, 0, counterparts_of(o.fragment));
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0].line, 5);
  ASSERT_FALSE(lines[0].values.empty());
  EXPECT_EQ(lines[0].values.back().name, "s");
  EXPECT_FALSE(lines[0].values.back().departs);
  EXPECT_EQ(lines[1].line, 6);
  ASSERT_FALSE(lines[1].values.empty());
  EXPECT_EQ(lines[1].values.back().name, "t");
  EXPECT_TRUE(lines[1].values.back().departs);
  // s = 0.25 + x², x = uv.x at pixel (2, 1) of 16: (2.5 / 16 * 2 - 1) * 0.5 + 0.5.
  const double x = 2.5 / 16;
  EXPECT_NEAR(lines[0].values.back().values[0], 0.25 + x * x, 1e-15);
  const std::string text = listing_text(lines);
  EXPECT_NE(text.find("test.frag:6  \n      t = "), std::string::npos) << text;
  EXPECT_NE(text.find("   matches test.frag:5 a\n"), std::string::npos) << text;
  EXPECT_NE(text.find("   matches nothing\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace twin_tests
