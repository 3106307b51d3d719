// The HLSL SM5 corpus style (tests/realworld/hlsl5/): a D3D11-tutorial shader with
// cbuffers, row-vector matrices, padding and Texture2D + SamplerState, bound to an image
// file, passes on every path; its planted bug fails. Also what the case's [textures]
// table promises: image files as textures (formats, sRGB, mip levels, cube faces), and
// one readable error, with the case file's line, for each way a binding can be wrong.
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "ShellCommand.h"
#include "TempDir.h"
#include "imageio/ImageIoModule.h"
#include "report/JsonReport.h"
#include "run/Runner.h"
#include "run/TextureFiles.h"
#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

RunOptions quick_32(const std::string& cases_dir, const std::string& case_name) {
  return test::quick_run(cases_dir, case_name, 32);
}

TEST(RealWorldHlsl5, TutorialShaderPassesOnEveryHlslPath) {
  auto report = run_suite(quick_32((kRealWorld / "cases").string(), "hlsl5_textured_diffuse"));
  ASSERT_TRUE(report) << report.error().to_string();
  std::set<std::string> paths;
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message;
    // Every report says the reference did not see the image.
    EXPECT_NE(r.reference_note.find("the reference ignores textures"), std::string::npos) << r.reference_note;
    EXPECT_NE(r.reference_note.find("'shaderTexture'"), std::string::npos) << r.reference_note;
    paths.insert(r.backend + "/" + r.path);
  }
  EXPECT_EQ(paths, (std::set<std::string>{"vulkan/spirv", "gl/spirv", "gl/cross"}));
  EXPECT_EQ(report->results.size(), 6u);
  // The note survives the JSON results file (merge reads it back).
  test::TempDir dir("hlsl5_json");
  ASSERT_TRUE(write_json(*report, dir / "r.json"));
  auto read = read_json(dir / "r.json");
  ASSERT_TRUE(read) << read.error().to_string();
  ASSERT_FALSE(read->results.empty());
  EXPECT_EQ(read->results.front().reference_note, report->results.front().reference_note);
}

TEST(RealWorldHlsl5, SwizzledTexelBugFailsOnEveryPath) {
  auto report = run_suite(quick_32((kRealWorld / "cases").string(), "hlsl5_textured_diffuse_bug"));
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_EQ(report->results.size(), 6u);
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::fail) << r.id() << ": " << r.message;
    // Red and blue are off by 0.4 x N.L at most: the largest error is that of a swap.
    EXPECT_NE(r.message.find("interior pixels over"), std::string::npos) << r.message;
    EXPECT_GT(r.metrics.max_abs, 0.3) << r.id();
    EXPECT_LT(r.metrics.max_abs, 0.41) << r.id();
  }
}

// A case tree in a temporary folder: cases/NAME.toml next to hlsl5/ with the corpus shader.
class CaseTree {
 public:
  CaseTree() {
    fs::create_directories(dir_.path() / "hlsl5");
    fs::create_directories(dir_.path() / "cases");
    fs::copy_file(kRealWorld / "hlsl5" / "textured_diffuse.hlsl", dir_.path() / "hlsl5" / "textured_diffuse.hlsl");
    fs::copy_file(kRealWorld / "hlsl5" / "tan_constant.png", dir_.path() / "hlsl5" / "tan_constant.png");
  }
  // The corpus case with its [textures] table replaced.
  void write_case(const std::string& textures) const {
    std::ifstream in(kRealWorld / "cases" / "hlsl5_textured_diffuse.toml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t start = text.find("[textures]"), end = text.find("[tolerance]");
    text = text.substr(0, start) + textures + "\n" + text.substr(end);
    dir_.write("cases/t.toml", text);
  }
  std::string cases() const { return dir_ / "cases"; }
  const test::TempDir& dir() const { return dir_; }

  // The one Vulkan cell's error (the texture errors are the same on every path).
  std::string first_error(const std::string& textures) const {
    write_case(textures);
    RunOptions o = quick_32(cases(), "t");
    o.select.backends = {"vulkan"};
    o.select.shapes = {"sphere"};
    auto report = run_suite(o);
    if (!report) return "run failed: " + report.error().to_string();
    if (report->results.empty()) return "no cells";
    const CellResult& r = report->results.front();
    return std::string(to_string(r.status)) + ": " + r.message;
  }

 private:
  test::TempDir dir_{"hlsl5_cases"};
};

// The line of the case file that holds `needle`.
int line_of(const std::string& file, const std::string& needle) {
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(needle) != std::string::npos) return n;
  return 0;
}

TEST(RealWorldHlsl5, MissingImageFileIsOneLineWithTheCaseFileLine) {
  CaseTree tree;
  const std::string e = tree.first_error("[textures]\nshaderTexture = { file = \"hlsl5/nowhere.png\" }\n");
  const int line = line_of(tree.cases() + "/t.toml", "nowhere.png");
  EXPECT_NE(e.find("t.toml:" + std::to_string(line) + ":"), std::string::npos) << e;
  EXPECT_NE(e.find("no image file 'hlsl5/nowhere.png'"), std::string::npos) << e;
  EXPECT_NE(e.find("'shaderTexture'"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(RealWorldHlsl5, UnreadableImageNamesTheFile) {
  CaseTree tree;
  tree.dir().write("hlsl5/broken.png", "this is not a PNG");
  const std::string e = tree.first_error("[textures]\nshaderTexture = { file = \"hlsl5/broken.png\" }\n");
  EXPECT_TRUE(e.starts_with("error: ")) << e;
  EXPECT_NE(e.find("cannot read 'hlsl5/broken.png'"), std::string::npos) << e;
  EXPECT_NE(e.find("t.toml:"), std::string::npos) << e;
}

TEST(RealWorldHlsl5, UnboundTextureNamesIt) {
  CaseTree tree;
  const std::string e = tree.first_error("");
  EXPECT_NE(e.find("'shaderTexture' has no binding in the case"), std::string::npos) << e;
}

TEST(RealWorldHlsl5, BindingToASamplerTheShaderLacksNamesItAndWhatExists) {
  CaseTree tree;
  const std::string e = tree.first_error(
      "[textures]\nshaderTexture = { file = \"hlsl5/tan_constant.png\" }\nnormalMap = { file = \"hlsl5/tan_constant.png\" }\n");
  const int line = line_of(tree.cases() + "/t.toml", "normalMap");
  EXPECT_NE(e.find("t.toml:" + std::to_string(line) + ":"), std::string::npos) << e;
  EXPECT_NE(e.find("binds 'normalMap', which the shader does not declare"), std::string::npos) << e;
  EXPECT_NE(e.find("'shaderTexture'"), std::string::npos) << e;
}

TEST(RealWorldHlsl5, CubeMapOnA2DTextureIsAnError) {
  CaseTree tree;
  const std::string face = "\"hlsl5/tan_constant.png\"";
  const std::string e = tree.first_error("[textures]\nshaderTexture = { file = [" + face + ", " + face + ", " + face +
                                         ", " + face + ", " + face + ", " + face + "] }\n");
  EXPECT_NE(e.find("binds a cube map (six files) to 'shaderTexture', which the shader samples as 2D"),
            std::string::npos)
      << e;
}

TEST(RealWorldHlsl5, AFileOnTheSamplerStateIsAnErrorNamingTheTexture) {
  CaseTree tree;
  const std::string e = tree.first_error("[textures]\nshaderTexture = { file = \"hlsl5/tan_constant.png\" }\n"
                                         "SampleType = { file = \"hlsl5/tan_constant.png\" }\n");
  EXPECT_NE(e.find("'SampleType', a SamplerState: bind the file to the texture it samples ('shaderTexture')"),
            std::string::npos)
      << e;
}

// The sampler state's settings reach the draw: with a texture that is not constant, a
// nearest SamplerState and a linear one render differently, and the texture's own entry
// overrides its sampler state's.
TEST(RealWorldHlsl5, SamplerStateSettingsReachEveryPath) {
  CaseTree tree;
  // An 8 x 8 red/blue checker of one-texel squares: filtering shows everywhere.
  std::vector<uint8_t> texels;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) texels.insert(texels.end(), {uint8_t((x + y) % 2 ? 255 : 0), 0, uint8_t((x + y) % 2 ? 0 : 255)});
  ASSERT_TRUE(write_image_file(tree.dir() / "hlsl5/two.png", 8, 8, 3, PixelType::uint8, texels.data()));
  const auto render = [&](const std::string& textures) {
    tree.write_case(textures);
    RunOptions o = quick_32(tree.cases(), "t");
    o.select.shapes = {"sphere"};
    return run_suite(o);
  };
  auto nearest = render("[textures]\nshaderTexture = { file = \"hlsl5/two.png\" }\nSampleType = { filter = \"nearest\" }\n");
  auto linear = render("[textures]\nshaderTexture = { file = \"hlsl5/two.png\" }\nSampleType = { filter = \"linear\" }\n");
  auto overridden = render("[textures]\nshaderTexture = { file = \"hlsl5/two.png\", filter = \"linear\" }\n"
                           "SampleType = { filter = \"nearest\" }\n");
  ASSERT_TRUE(nearest && linear && overridden);
  ASSERT_EQ(nearest->results.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    // Neither matches the constant-texture reference; what differs is how far off.
    const CellResult &n = nearest->results[i], &l = linear->results[i], &o = overridden->results[i];
    EXPECT_EQ(n.status, CellStatus::fail) << n.id();
    EXPECT_NE(n.metrics.rmse, l.metrics.rmse) << n.id() << ": the SamplerState's filter made no difference";
    EXPECT_EQ(o.metrics.rmse, l.metrics.rmse) << o.id() << ": the texture's own filter did not override";
  }
}

// --- image files as textures -------------------------------------------------------

TextureBinding binding_of(const std::string& file) {
  TextureBinding b;
  b.files = {file};
  b.line = 7;
  return b;
}

TEST(TextureFiles, EightBitPngKeepsItsBytesAndGreyBecomesRgba) {
  test::TempDir dir("texture_files");
  const std::vector<uint8_t> grey = {0, 51, 204, 255};
  ASSERT_TRUE(write_image_file(dir / "grey.png", 2, 2, 1, PixelType::uint8, grey.data()));
  auto t = load_texture_file("g", binding_of(dir / "grey.png"), dir / "cases/c.toml");
  ASSERT_TRUE(t) << t.error().to_string();
  EXPECT_EQ((*t)->format, TexelFormat::rgba8_unorm);
  EXPECT_EQ((*t)->width, 2u);
  ASSERT_EQ((*t)->texels.size(), 16u);
  for (size_t i = 0; i < 4; ++i) {
    // OpenImageIO's byte -> float conversion may differ from n / 255.0f by an ulp; the
    // upload rounds v * 255 back to the byte.
    for (size_t c = 0; c < 3; ++c) EXPECT_FLOAT_EQ((*t)->texels[i * 4 + c], float(grey[i]) / 255.0f);
    EXPECT_EQ((*t)->texels[i * 4 + 3], 1.0f);
  }
}

TEST(TextureFiles, SrgbEightBitStaysEncodedForTheSamplerAndFloatIsDecodedHere) {
  test::TempDir dir("texture_files");
  const std::vector<uint8_t> bytes = {188, 64, 8};
  ASSERT_TRUE(write_image_file(dir / "c.png", 1, 1, 3, PixelType::uint8, bytes.data()));
  const std::vector<float> values = {0.5f, 0.25f, 1.0f, 0.5f};
  ASSERT_TRUE(write_image_file(dir / "c.exr", 1, 1, 4, PixelType::float32, values.data()));
  TextureBinding png = binding_of(dir / "c.png"), exr = binding_of(dir / "c.exr");
  png.settings.srgb = exr.settings.srgb = true;
  auto t8 = load_texture_file("a", png, dir / "cases/c.toml");
  auto tf = load_texture_file("b", exr, dir / "cases/c.toml");
  ASSERT_TRUE(t8 && tf);
  EXPECT_EQ((*t8)->format, TexelFormat::rgba8_srgb);
  EXPECT_FLOAT_EQ((*t8)->texels[0], 188.0f / 255.0f);
  EXPECT_EQ((*tf)->format, TexelFormat::rgba32_float);
  EXPECT_FLOAT_EQ((*tf)->texels[0], float(srgb_to_linear(0.5)));
  EXPECT_FLOAT_EQ((*tf)->texels[1], float(srgb_to_linear(0.25)));
  EXPECT_EQ((*tf)->texels[3], 0.5f);   // alpha is never sRGB
}

TEST(TextureFiles, GeneratedMipLevelsAverageInLinearLight) {
  test::TempDir dir("texture_files");
  const std::vector<float> values = {0, 0, 0, 1, 1, 1, 1, 1, 0.5f, 0.5f, 0.5f, 1, 0.25f, 0.25f, 0.25f, 0};
  ASSERT_TRUE(write_image_file(dir / "m.exr", 2, 2, 4, PixelType::float32, values.data()));
  TextureBinding b = binding_of(dir / "m.exr");
  b.mipmaps = MipSource::generate;
  auto t = load_texture_file("m", b, dir / "cases/c.toml");
  ASSERT_TRUE(t) << t.error().to_string();
  ASSERT_EQ((*t)->mip_levels.size(), 1u);
  ASSERT_EQ((*t)->mip_levels[0].size(), 4u);
  EXPECT_FLOAT_EQ((*t)->mip_levels[0][0], (0 + 1 + 0.5f + 0.25f) / 4);
  EXPECT_FLOAT_EQ((*t)->mip_levels[0][3], 0.75f);
}

TEST(TextureFiles, MipmapsFromAFileWithoutLevelsIsAnErrorAtTheLine) {
  test::TempDir dir("texture_files");
  const std::vector<uint8_t> bytes = {1, 2, 3};
  ASSERT_TRUE(write_image_file(dir / "one.png", 1, 1, 3, PixelType::uint8, bytes.data()));
  TextureBinding b = binding_of(dir / "one.png");
  b.mipmaps = MipSource::file;
  auto t = load_texture_file("x", b, dir / "cases/c.toml");
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error().line, 7);
  EXPECT_NE(t.error().message.find("has no mip levels of its own"), std::string::npos) << t.error().to_string();
}

// A file's own levels (mipmaps = "file"): a tiled, mipmapped EXR as OpenImageIO's maketx
// writes it (openimageio-tools, which scripts/install-deps installs).
TEST(TextureFiles, MipLevelsFromTheFileItself) {
  test::TempDir dir("texture_files");
  const std::vector<float> values = {0.0f, 0.25f, 0.5f, 1.0f, 1.0f, 0.75f, 0.5f, 1.0f,
                                     0.5f, 0.5f, 0.5f, 1.0f, 0.25f, 0.0f, 1.0f, 1.0f};
  ASSERT_TRUE(write_image_file(dir / "flat.exr", 2, 2, 4, PixelType::float32, values.data()));
  const auto [status, output] = test::run_shell("maketx --filter box " + (dir / "flat.exr") + " -o " + (dir / "mipped.exr"));
  if (status == 127) GTEST_SKIP() << "maketx is not installed (openimageio-tools)";
  ASSERT_EQ(status, 0) << output;
  TextureBinding b = binding_of(dir / "mipped.exr");
  b.mipmaps = MipSource::file;
  auto t = load_texture_file("m", b, dir / "cases/c.toml");
  ASSERT_TRUE(t) << t.error().to_string();
  ASSERT_EQ((*t)->mip_levels.size(), 1u);
  ASSERT_EQ((*t)->mip_levels[0].size(), 4u);
  EXPECT_NEAR((*t)->mip_levels[0][0], (0.0 + 1.0 + 0.5 + 0.25) / 4, 1e-3);
  EXPECT_NEAR((*t)->mip_levels[0][1], (0.25 + 0.75 + 0.5 + 0.0) / 4, 1e-3);
}

TEST(TextureFiles, SixFilesMakeACubeMap) {
  test::TempDir dir("texture_files");
  TextureBinding b;
  for (int face = 0; face < 6; ++face) {
    const std::vector<uint8_t> texel = {uint8_t(face * 40), 0, 0};
    const std::string file = dir / ("f" + std::to_string(face) + ".png");
    ASSERT_TRUE(write_image_file(file, 1, 1, 3, PixelType::uint8, texel.data()));
    b.files.push_back(file);
  }
  auto t = load_texture_file("sky", b, dir / "cases/c.toml");
  ASSERT_TRUE(t) << t.error().to_string();
  EXPECT_TRUE((*t)->cube);
  ASSERT_EQ((*t)->texels.size(), 24u);
  for (int face = 0; face < 6; ++face) EXPECT_FLOAT_EQ((*t)->texels[size_t(face) * 4], float(face * 40) / 255.0f);
}

// --- the [textures] table -----------------------------------------------------------

TEST(CaseTexturesTable, EntriesSettingsAndLanguageTables) {
  test::TempDir dir("texture_table");
  const std::string path = dir.write("cases/c.toml", R"(model = "lambert"
[variants.pixel]
hlsl = { vertex = "a.hlsl", fragment = "a.hlsl" }
[textures]
diffuseMap = { file = "img/checker.png", filter = "nearest", address = "wrap", mipmaps = true, color = "srgb" }
edge = { address_u = "border", address_v = "mirror", border = [1, 1, 1, 1], mip_filter = "none" }
[textures.glsl]
diffuseMap = { file = "img/other.png" }
[tolerance]
interior = { max_abs = 1e-5, reason = "r" }
silhouette = { max_abs = 1e-4, reason = "r" }
)");
  auto c = load_case(path);
  ASSERT_TRUE(c) << c.error().to_string();
  const auto hlsl = c->textures.for_language(Language::hlsl);
  const TextureBinding& d = hlsl.at("diffuseMap");
  EXPECT_EQ(d.files, std::vector<std::string>{(dir.path() / "img/checker.png").string()});
  EXPECT_EQ(d.line, 5);
  EXPECT_EQ(d.mipmaps, MipSource::generate);
  const SamplerSettings s = d.settings.applied_to({});
  EXPECT_EQ(s.min_filter, TextureFilter::nearest);
  EXPECT_EQ(s.mag_filter, TextureFilter::nearest);
  EXPECT_EQ(s.mip_filter, MipFilter::nearest);   // mipmaps filter between levels as the texels are filtered
  EXPECT_EQ(s.address_u, AddressMode::wrap);
  EXPECT_EQ(s.address_v, AddressMode::wrap);
  EXPECT_TRUE(s.srgb);
  const SamplerSettings e = hlsl.at("edge").settings.applied_to({});
  EXPECT_EQ(e.address_u, AddressMode::border);
  EXPECT_EQ(e.address_v, AddressMode::mirror);
  EXPECT_EQ(e.border_color[3], 1.0f);
  EXPECT_TRUE(hlsl.at("edge").files.empty());
  EXPECT_EQ(c->textures.for_language(Language::glsl).at("diffuseMap").files,
            std::vector<std::string>{(dir.path() / "img/other.png").string()});
}

TEST(CaseTexturesTable, UnknownKeyIsAnErrorAtItsLine) {
  test::TempDir dir("texture_table");
  const std::string path = dir.write("cases/c.toml", R"(model = "lambert"
[variants.pixel]
hlsl = { vertex = "a.hlsl", fragment = "a.hlsl" }
[textures]
diffuseMap = { file = "x.png", filtre = "linear" }
[tolerance]
interior = { max_abs = 1e-5, reason = "r" }
silhouette = { max_abs = 1e-4, reason = "r" }
)");
  auto c = load_case(path);
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().line, 5);
  EXPECT_NE(c.error().message.find("unknown key 'filtre'"), std::string::npos) << c.error().to_string();
}

}  // namespace
}  // namespace shaderbed
