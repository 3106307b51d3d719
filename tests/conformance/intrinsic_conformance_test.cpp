// Every intrinsic of the conformance table (IntrinsicChecks.cpp), evaluated on the GPU
// through each language's front end, on every backend and path, against its definition in
// double. A compiler bug must not reach a user's verdict as the user's bug: a
// disagreement here is fixed in the front end's dialect layer or refused by name there.
#include <cmath>
#include <cstdlib>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "ConformanceShaders.h"
#include "IntrinsicChecks.h"
#include "MapResolvers.h"
#include "backends/Backend.h"

namespace shaderbed::conformance {
namespace {

struct Cell {
  Language language;
  std::string backend;  // "vulkan", "gl"
  ShaderPath path;
};

std::string cell_name(const Cell& c) {
  return std::string(to_string(c.language)) + "_" + c.backend + "_" + to_string(c.path);
}

Result<Backend*> backend_named(const std::string& name) {
  // One per process, each made by its own static's initialiser: its destructor is then
  // registered after the driver's own exit handlers and runs before them (a GL renderer
  // torn down after OSMesa's teardown crashes in OSMesaMakeCurrent).
  if (name == "vulkan") {
    static Result<std::unique_ptr<Backend>> vulkan = make_vulkan_backend();
    if (!vulkan) return std::unexpected(vulkan.error());
    return vulkan->get();
  }
  static Result<std::unique_ptr<Backend>> gl = make_gl_backend();
  if (!gl) return std::unexpected(gl.error());
  return gl->get();
}

Mesh full_screen_quad() {
  Mesh mesh;
  mesh.name = "full-screen quad";
  const glm::vec3 n(0, 0, 1), t(1, 0, 0);
  for (auto [x, y] : {std::pair{-1.5f, -1.5f}, {1.5f, -1.5f}, {1.5f, 1.5f}, {-1.5f, 1.5f}})
    mesh.vertices.push_back(Vertex{.position = {x, y, 0.5f}, .normal = n, .tangent = t, .uv = {0, 0}});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

std::string values(const float* p, size_t n) {
  std::string s = "(";
  for (size_t i = 0; i < n; ++i) s += (i ? ", " : "") + fmt::format("{:.9g}", p[i]);
  return s + ")";
}

std::string values(const std::vector<double>& v) {
  std::string s = "(";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + fmt::format("{:.9g}", v[i]);
  return s + ")";
}

// Tex for every sampler the program declares, sampled as conformance_sampler() says.
class ConformanceTextures final : public TextureResolver {
 public:
  Result<const Texture*> texture(const SamplerBinding&) const override { return &texture_; }
  Result<SamplerSettings> settings(const SamplerBinding&) const override { return conformance_sampler(); }

 private:
  Texture texture_ = conformance_texture();
};

class IntrinsicConformance : public ::testing::TestWithParam<Cell> {};

TEST_P(IntrinsicConformance, EveryIntrinsicMatchesItsDefinition) {
  const Cell cell = GetParam();
  const std::vector<Check>& checks = intrinsic_checks();
  auto program = compile_program(conformance_program(checks, cell.language));
  ASSERT_TRUE(program) << program.error().to_string();
  auto backend = backend_named(cell.backend);
  ASSERT_TRUE(backend) << backend.error().to_string();
  const test::MapResolver uniforms({{"One", {1.0f}}});
  const ConformanceTextures textures;
  const Mesh quad = full_screen_quad();
  auto out = (*backend)->render(DrawJob{.program = *program, .path = cell.path, .mesh = quad, .uniforms = uniforms,
                                        .width = image_width(checks), .height = kImageHeight, .textures = &textures});
  ASSERT_TRUE(out) << out.error().to_string();

  // CONFORMANCE_DUMP=1 prints every pixel (the check at pixel p is check p / 2), for
  // telling a wrong intrinsic from a wrong draw.
  if (std::getenv("CONFORMANCE_DUMP"))
    for (int x = 0; x < out->image.width; ++x) std::cout << x << ": " << values(out->image.pixel(x, 0), 4) << (out->image.covered(x, 0) ? "" : " uncovered") << "\n";
  int evaluated = 0;
  std::ostringstream disagreements;
  int disagreeing = 0;
  for (size_t k = 0; k < checks.size(); ++k) {
    const Check& c = checks[k];
    if (!runs_in(c, cell.language)) continue;
    for (int runtime = 0; runtime < 2; ++runtime) {
      if (c.literal_only && runtime) continue;
      const float* p = out->image.pixel(int(2 * k) + runtime, 0);
      ++evaluated;
      bool agrees = true;
      for (size_t i = 0; i < c.expected.size(); ++i) {
        const double bound = c.tolerance * std::max(std::abs(c.expected[i]), c.scale);
        if (!(std::abs(double(p[i]) - c.expected[i]) <= bound)) agrees = false;
      }
      if (agrees) continue;
      ++disagreeing;
      disagreements << "  " << c.intrinsic << " " << describe_args(c.args) << " [pixel " << 2 * k + size_t(runtime) << ", "
                    << (c.literal_only ? "position-dependent" : runtime ? "run time" : "constant-folded")
                    << "]: GPU " << values(p, c.expected.size()) << ", definition " << values(c.expected) << "\n";
    }
  }
  std::cout << cell_name(cell) << ": " << evaluated << " evaluations, " << disagreeing << " disagree\n";
  EXPECT_EQ(disagreeing, 0) << to_string(cell.language) << " on " << cell.backend << "/" << to_string(cell.path)
                            << ", intrinsics that disagree with their definition:\n"
                            << disagreements.str();
  // Not vacuous: every check of the language was drawn.
  EXPECT_GT(evaluated, 200);
}

std::vector<Cell> every_cell() {
  std::vector<Cell> cells;
  for (Language language : {Language::hlsl, Language::cg, Language::glsl})
    for (const char* backend : {"vulkan", "gl"})
      for (ShaderPath path : backend_paths(backend, language)) cells.push_back({language, backend, path});
  return cells;
}

INSTANTIATE_TEST_SUITE_P(EveryPath, IntrinsicConformance, ::testing::ValuesIn(every_cell()),
                         [](const auto& info) { return cell_name(info.param); });

}  // namespace
}  // namespace shaderbed::conformance
