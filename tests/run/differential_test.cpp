// Differential cases through the CLI: a case without a model is judged against a render of
// the original (tests/differential/), or against the images a known-good run stored.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::read_json;
using shaderbed::test::read_text;
using shaderbed::test::shaderbed_cli;

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kCorpus = fs::path(SHADERBED_SOURCE_DIR) / "tests" / "differential";

void replace_once(const fs::path& file, const std::string& from, const std::string& to) {
  std::string text = read_text(file);
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << file;
  text.replace(at, from.size(), to);
  std::ofstream(file) << text;
}

// A copy of the corpus a test may change.
fs::path copy_corpus(const shaderbed::test::TempDir& dir) {
  fs::copy(kCorpus, dir.path() / "differential", fs::copy_options::recursive);
  return dir.path() / "differential";
}

TEST(Differential, OriginalAndCorrectPortPassOnEveryBackendAndPath) {
  shaderbed::test::TempDir dir("differential");
  for (const char* name : {"tinted_diffuse", "glossy"}) {
    const std::string results = dir / (std::string(name) + ".json");
    const auto [status, out] = shaderbed_cli("run --case " + (kCorpus / "cases" / (std::string(name) + ".toml")).string() +
                                             " --variant original,port --size 48 --repeat 0 -q --json " + results);
    ASSERT_EQ(status, 0) << out;
    const json j = read_json(results);
    std::map<std::string, int> paths;   // language/backend/path -> cells
    int references = 0;
    for (const json& r : j["results"]) {
      EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
      EXPECT_EQ(r["reference"]["kind"], "render");
      EXPECT_EQ(r["reference"]["label"], "hlsl vulkan/spirv (variant original)");
      ++paths[r["language"].get<std::string>() + "/" + r["backend"].get<std::string>() + "/" + r["path"].get<std::string>()];
      if (r["reference"]["is_reference"].get<bool>()) {
        ++references;
        EXPECT_EQ(r["language"], "hlsl");
        EXPECT_EQ(r["backend"], "vulkan");
        EXPECT_EQ(r["metrics"]["max_abs"], 0.0);   // judged against itself
      }
      // The documented fp32 bound, with its reason, is in every cell.
      EXPECT_GT(r["tolerance"]["interior_rel"].get<double>(), 0.0);
      EXPECT_NE(r["tolerance"]["reason"].get<std::string>().find("differential default"), std::string::npos);
    }
    EXPECT_EQ(references, 4) << "the original on vulkan/spirv is each shape's reference";
    // hlsl on vulkan/spirv, gl/spirv, gl/cross; glsl on those and gl/glsl: four shapes each.
    EXPECT_EQ(paths.size(), 7u);
    for (const auto& [path, cells] : paths) EXPECT_EQ(cells, 4) << path;
  }
}

TEST(Differential, PortsWithAPlantedConventionFailAndBlameThePort) {
  shaderbed::test::TempDir dir("differential");
  const std::string results = dir / "planted.json";
  const auto [status, out] =
      shaderbed_cli("run --case " + (kCorpus / "cases" / "tinted_diffuse.toml").string() +
                    " --variant factor_pi,gamma,light_negated --shape sphere --size 48 --repeat 0 -q --json " + results);
  EXPECT_EQ(status, 1) << out;
  const json j = read_json(results);
  ASSERT_EQ(j["results"].size(), 12u);
  for (const json& r : j["results"]) {
    EXPECT_EQ(r["status"], "fail") << r["id"];
    EXPECT_EQ(r["attribution"]["verdict"], "port") << r["id"] << ": " << r["attribution"]["reason"];
  }
  EXPECT_NE(out.find("judged against: the original, hlsl vulkan/spirv"), std::string::npos) << out;
}

// Each planted convention, on the sphere and every backend and path: the cell fails and
// the convention it plants is the first explanation, and it fits. The residuals are
// printed for the record (the issue's closing note quotes them).
TEST(Differential, EachPlantedConventionIsNamedFirst) {
  const std::pair<const char*, std::map<std::string, std::string>> corpus[] = {
      {"tinted_diffuse",
       {{"factor_pi", "constant_factor"},
        {"extra_n_dot_l", "extra_n_dot_l"},
        {"light_negated", "negated_light"},
        {"unnormalised_normal", "unnormalised_normal"},
        {"gamma", "gamma_encoded_render"},
        {"half_pixel", "half_pixel_offset_redrawn"},
        {"transposed_matrix", "transposed_matrices"}}},
      {"glossy", {{"ungated_specular", "not_gated_by_n_dot_l"}, {"clamped", "render_clamps"}}},
      {"textured", {{"flipped_v", "flipped_texture_v"}}},
  };
  shaderbed::test::TempDir dir("planted");
  for (const auto& [name, planted] : corpus) {
    std::string variants;
    for (const auto& [variant, convention] : planted) variants += (variants.empty() ? "" : ",") + variant;
    const std::string results = dir / (std::string(name) + ".json");
    const auto [status, out] = shaderbed_cli("run --case " + (kCorpus / "cases" / (std::string(name) + ".toml")).string() +
                                             " --variant " + variants + " --shape sphere --size 64 --repeat 0 -q --json " +
                                             results);
    EXPECT_EQ(status, 1) << out;
    const json j = read_json(results);
    ASSERT_EQ(j["results"].size(), 4 * planted.size()) << out;
    for (const json& r : j["results"]) {
      const std::string variant = r["variant"];
      EXPECT_EQ(r["status"], "fail") << r["id"];
      ASSERT_FALSE(r["explanations"].empty()) << r["id"] << ": " << r["message"];
      const json& best = r["explanations"][0];
      EXPECT_EQ(best["name"], planted.at(variant)) << r["id"] << ": " << best["summary"];
      EXPECT_TRUE(best["fits"].get<bool>()) << r["id"] << ": " << best["summary"];
      if (r["backend"] == "vulkan")
        std::printf("%-32s %-28s residual %.2g  (%s)\n", (std::string(name) + "/" + variant).c_str(),
                    best["name"].get<std::string>().c_str(), best["residual"].get<double>(),
                    best["summary"].get<std::string>().c_str());
    }
    // The console names it too.
    EXPECT_NE(out.find("      explained: matches the reference"), std::string::npos) << out;
  }
}

// Against a model, the reference re-rendered under each convention does the same.
TEST(Differential, ModelCasesNameTheConventionToo) {
  shaderbed::test::TempDir dir("planted_model");
  const std::string results = dir / "mutants.json";
  const auto [status, out] = shaderbed_cli(
      "run --cases-dir " + (fs::path(SHADERBED_SOURCE_DIR) / "tests" / "mutants" / "cases").string() +
      " --case phong_reflect_sign,lambert_no_normalize,lambert_unclamped,phong_vertex_light_eye,lambert_derivative_normal"
      " --shape sphere --backend vulkan --size 64 --repeat 0 -q --json " + results);
  EXPECT_EQ(status, 1) << out;
  const std::map<std::string, std::string> expected{{"phong_reflect_sign", "negated_eye"},
                                                    {"lambert_no_normalize", "unnormalised_normal"},
                                                    {"lambert_unclamped", "not_gated_by_n_dot_l"},
                                                    {"phong_vertex_light_eye", "interpolated_light_eye"},
                                                    {"lambert_derivative_normal", "faceted_normal"}};
  int failing = 0;
  const json j1 = read_json(results);
  for (const json& r : j1["results"]) {
    if (r["status"] != "fail") continue;
    ++failing;
    ASSERT_FALSE(r["explanations"].empty()) << r["id"];
    EXPECT_EQ(r["explanations"][0]["name"], expected.at(r["case"])) << r["id"] << ": " << r["explanations"][0]["summary"];
    EXPECT_TRUE(r["explanations"][0]["fits"].get<bool>()) << r["id"];
    std::printf("%-28s %-24s residual %.2g\n", r["case"].get<std::string>().c_str(),
                r["explanations"][0]["name"].get<std::string>().c_str(), r["explanations"][0]["residual"].get<double>());
  }
  EXPECT_GE(failing, 5);
  EXPECT_NE(out.find("      explained: matches the reference re-rendered with L and V normalised per vertex"), std::string::npos)
      << out;
}

// NaN/Inf pixels: no convention fitted on the finite rest is offered (minnaert_pow_nan's
// finite pixels fit a plain factor); the console says why instead.
TEST(Differential, NoConventionOfferedBesideNaN) {
  shaderbed::test::TempDir dir("nan_fits");
  const std::string results = dir / "nan.json";
  const auto [status, out] = shaderbed_cli(
      "run --cases-dir " + (fs::path(SHADERBED_SOURCE_DIR) / "tests" / "mutants" / "cases").string() +
      " --case minnaert_pow_nan --shape sphere --backend vulkan --size 64 --repeat 0 -q --json " + results);
  EXPECT_EQ(status, 1) << out;
  int nonfinite = 0;
  const json j = read_json(results);
  for (const json& r : j["results"]) {
    if (r["status"] != "fail" || r["metrics"]["nonfinite_mismatch"].get<size_t>() == 0) continue;
    ++nonfinite;
    EXPECT_TRUE(r["explanations"].empty()) << r["id"] << ": " << r["explanations"][0]["summary"];
  }
  EXPECT_GE(nonfinite, 1) << out;
  EXPECT_NE(out.find("pixels are NaN/Inf"), std::string::npos) << out;
  EXPECT_EQ(out.find("explained: "), std::string::npos) << out;
}

// The original and a correct port that shade by the window position: GL's window y runs
// the other way, so on GL both differ from the original's Vulkan render alike. A run filtered
// to GL sees no render that passes; still, neither the original's own renders nor a port
// that agrees with the original on the same backend is blamed on the port's source.
TEST(Differential, APortIsNotBlamedForWhatTheOriginalDoesOnTheSameBackend) {
  shaderbed::test::TempDir dir("differential_same_backend");
  dir.write("bands.hlsl", R"(// Horizontal bands by window position (a screen-space pattern, not a book model): the original.
float4x4 Transform;
struct VSOut { float4 pos : SV_Position; };
VSOut vs_main(float4 pos : POSITION) { VSOut o; o.pos = mul(Transform, pos); return o; }
float4 ps_main(VSOut i) : SV_Target { return float4(frac(i.pos.y / 16.0).xxx, 1); }
)");
  dir.write("bands.vert", R"(// Horizontal bands by window position (a screen-space pattern): the port's vertex stage.
#version 330
in vec3 position;
uniform mat4 transform;
void main() { gl_Position = transform * vec4(position, 1.0); }
)");
  dir.write("bands.frag", R"(// Horizontal bands by window position (a screen-space pattern): the port.
#version 330
out vec4 color;
void main() { color = vec4(vec3(fract(gl_FragCoord.y / 16.0)), 1.0); }
)");
  const std::string the_case = dir.write("bands.toml", R"(reference = { language = "hlsl", backend = "vulkan", path = "spirv" }
[variants.pixel]
hlsl = { vertex = "bands.hlsl", fragment = "bands.hlsl", vertex_entry = "vs_main", fragment_entry = "ps_main" }
glsl = { vertex = "bands.vert", fragment = "bands.frag" }
[bindings.hlsl]
Transform = "transform"
[bindings.glsl]
transform = "transform"
[attributes.glsl]
position = "position"
)");
  const std::string results = dir / "gl.json";
  const auto [status, out] = shaderbed_cli("run --case " + the_case + " --backend gl --shape sphere --size 48 --repeat 0 -q --json " + results);
  ASSERT_EQ(status, 1) << out;
  int failing = 0;
  const json j = read_json(results);
  for (const json& r : j["results"]) {
    if (r["status"] != "fail") continue;
    ++failing;
    EXPECT_NE(r["attribution"]["verdict"], "port") << r["id"] << ": " << r["attribution"]["reason"];
    if (r["language"] == "glsl") {
      EXPECT_NE(r["attribution"]["reason"].get<std::string>().find("the original drawn on gl/"), std::string::npos)
          << r["id"] << ": " << r["attribution"]["reason"];
    }
  }
  EXPECT_EQ(failing, 5);   // glsl on gl/glsl, gl/spirv, gl/cross; the original on gl/spirv, gl/cross
}

TEST(Differential, TheReferenceIsDrawnEvenWhenItsBackendIsFilteredOut) {
  const auto [status, out] = shaderbed_cli("run --case " + (kCorpus / "cases" / "glossy.toml").string() +
                                           " --variant port --backend gl --shape torus --size 48 --repeat 0 -q");
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("3 cells: 3 passed"), std::string::npos) << out;
}

TEST(Differential, StoredImagesPassOnARerunAndFailAfterAOneLineChange) {
  shaderbed::test::TempDir dir("stored");
  const fs::path corpus = copy_corpus(dir);
  const std::string the_case = (corpus / "cases" / "glossy.toml").string();
  const std::string stored = dir / "known_good";
  const std::string common = " --variant port --shape sphere,cone --size 48 --repeat 0 -q";
  {
    const auto [status, out] = shaderbed_cli("run --case " + the_case + common + " --save-images " + stored);
    ASSERT_EQ(status, 0) << out;
    EXPECT_TRUE(fs::exists(fs::path(stored) / "manifest.json"));
    EXPECT_TRUE(fs::exists(fs::path(stored) / "glossy" / "port" / "sphere" / "glsl-vulkan-spirv.exr"));
  }
  const std::string results = dir / "against.json";
  {
    const auto [status, out] = shaderbed_cli("run --case " + the_case + common + " --against " + stored + " --json " + results);
    EXPECT_EQ(status, 0) << out;
    const json j = read_json(results);
    ASSERT_EQ(j["results"].size(), 8u);
    for (const json& r : j["results"]) {
      EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
      EXPECT_EQ(r["reference"]["kind"], "images");
      EXPECT_EQ(r["reference"]["toolchain_note"], "") << "the same toolchain drew both";
      EXPECT_EQ(r["metrics"]["max_abs"], 0.0) << "the same drivers draw the same image, bit for bit";
    }
  }
  // One line of the port changes: every cell fails against the stored run.
  replace_once(corpus / "glsl" / "glossy.frag", "Base * clamp(nl, 0.0, 1.0)", "Base * clamp(nl, 0.0, 1.0) * 0.98");
  {
    const auto [status, out] = shaderbed_cli("run --case " + the_case + common + " --against " + stored + " --json " + results);
    EXPECT_EQ(status, 1) << out;
    const json j2 = read_json(results);
    for (const json& r : j2["results"]) EXPECT_EQ(r["status"], "fail") << r["id"];
  }
  // A case may name the stored run as its reference; a different toolchain is reported beside the verdict.
  const fs::path manifest = fs::path(stored) / "manifest.json";
  replace_once(manifest, "\"glslang\": \"", "\"glslang\": \"0.0-stored-");
  replace_once(corpus / "glsl" / "glossy.frag", "Base * clamp(nl, 0.0, 1.0) * 0.98", "Base * clamp(nl, 0.0, 1.0)");
  replace_once(corpus / "cases" / "glossy.toml",
               "reference = { language = \"hlsl\", backend = \"vulkan\", path = \"spirv\", variant = \"original\" }",
               "reference = { images = \"known_good\" }");   // from the folder above cases/, as shader paths
  fs::rename(stored, corpus / "known_good");
  {
    const auto [status, out] = shaderbed_cli("run --case " + the_case + common + " --json " + results);
    EXPECT_EQ(status, 0) << out;
    const json j3 = read_json(results);
    for (const json& r : j3["results"]) {
      EXPECT_EQ(r["status"], "pass") << r["id"];
      EXPECT_NE(r["reference"]["toolchain_note"].get<std::string>().find("glslang 0.0-stored-"), std::string::npos);
    }
  }
}

TEST(Differential, StoredImagesOfAnotherSizeOrSceneAreClearErrors) {
  shaderbed::test::TempDir dir("stored");
  const fs::path corpus = copy_corpus(dir);
  const std::string the_case = (corpus / "cases" / "glossy.toml").string();
  const std::string stored = dir / "known_good";
  const std::string common = " --variant port --lang glsl --backend vulkan --shape sphere --repeat 0 -q";
  ASSERT_EQ(shaderbed_cli("run --case " + the_case + common + " --size 48 --save-images " + stored).first, 0);
  {
    const auto [status, out] = shaderbed_cli("run --case " + the_case + common + " --size 32 --against " + stored);
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find("the stored images are 48x48; this run draws 32x32 (run with --size 48)"), std::string::npos) << out;
  }
  {
    const auto [status, out] =
        shaderbed_cli("run --case " + the_case + common + " --size 48 --param sharpness=30 --against " + stored);
    EXPECT_EQ(status, 1) << out;
    EXPECT_NE(out.find("drawn with another scene"), std::string::npos) << out;
  }
  {
    const auto [status, out] = shaderbed_cli("run --case " + the_case + common + " --size 48 --against " + (dir / "nowhere"));
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find("no manifest.json"), std::string::npos) << out;
  }
}

}  // namespace
