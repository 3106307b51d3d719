// Driver counts of the library's literal-vs-uniform pairs (book §7.6: a literal lets the
// compiler fold terms): recorded per backend so the report shows them; the literal
// variant never needs more ALU than the uniform one after Mesa's constant folding.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "compile/Compiler.h"
#include "stats/nir/NirDump.h"

namespace shaderbed {
namespace {

Result<CompiledProgram> library_program(Language language, const std::string& vertex, const std::string& fragment) {
  const std::string dir = std::string(SHADERBED_SOURCE_DIR) + "/shaders/";
  auto v = load_shader_source(Stage::vertex, dir + vertex);
  auto f = load_shader_source(Stage::fragment, dir + fragment);
  if (!v || !f) return std::unexpected(!v ? v.error() : f.error());
  return compile_program(ProgramSource{language, std::move(*v), std::move(*f)});
}

struct Pair {
  const char* name;
  Language language;
  const char* vertex;
  const char* uniform;
  const char* literal;
};

class NirLiteral : public testing::TestWithParam<Pair> {};

TEST_P(NirLiteral, LiteralNeedsNoMoreAluThanUniform) {
  const Pair& p = GetParam();
  auto uniform = library_program(p.language, p.vertex, p.uniform);
  auto literal = library_program(p.language, p.vertex, p.literal);
  ASSERT_TRUE(uniform) << uniform.error().to_string();
  ASSERT_TRUE(literal) << literal.error().to_string();
  for (NirBackend backend : {NirBackend::vulkan, NirBackend::gl}) {
    const NirRequest request{.backend = backend, .path = ShaderPath::spirv};
    auto u = nir_counts(*uniform, Stage::fragment, request);
    auto l = nir_counts(*literal, Stage::fragment, request);
    ASSERT_TRUE(u) << u.error().to_string();
    ASSERT_TRUE(l) << l.error().to_string();
    std::printf("%s %s %s fragment NIR: uniform alu %d tex %d control %d | literal alu %d tex %d control %d\n", p.name,
                to_string(p.language), to_string(backend), u->alu, u->tex, u->control, l->alu, l->tex, l->control);
    EXPECT_LE(l->alu, u->alu) << to_string(backend);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Library, NirLiteral,
    testing::Values(Pair{"phong", Language::hlsl, "hlsl/setup_vs.hlsl", "hlsl/phong_ps.hlsl", "hlsl/phong_literal_ps.hlsl"},
                    Pair{"phong", Language::glsl, "glsl/setup.vert", "glsl/phong.frag", "glsl/phong_literal.frag"},
                    Pair{"phong", Language::cg, "cg/setup_vp.cg", "cg/phong_fp.cg", "cg/phong_literal_fp.cg"},
                    Pair{"ward_iso", Language::hlsl, "hlsl/setup_vs.hlsl", "hlsl/ward_iso_ps.hlsl",
                         "hlsl/ward_iso_literal_ps.hlsl"},
                    Pair{"ward_iso", Language::glsl, "glsl/setup.vert", "glsl/ward_iso.frag", "glsl/ward_iso_literal.frag"},
                    Pair{"ward_iso", Language::cg, "cg/setup_vp.cg", "cg/ward_iso_fp.cg", "cg/ward_iso_literal_fp.cg"}),
    [](const auto& info) { return std::string(info.param.name) + "_" + to_string(info.param.language); });

}  // namespace
}  // namespace shaderbed
