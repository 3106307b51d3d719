// Matrix conventions through the runner: an HLSL shader that multiplies row vectors,
// mul(v, M), with its matrix bound as layout = "row_vector", renders the same pixels as its
// column-vector twin mul(M, v) on every HLSL path; without the layout its cells fail and
// the attribution names the matrix convention; a D3D11-style shader with separate
// world, view and projection matrices, a point light, an ambient colour and a literal
// padding member passes unchanged.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "TempDir.h"
#include "imageio/ImageIoModule.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

RunOptions small_run(const std::string& cases_dir, std::vector<std::string> cases, const std::string& out = "") {
  RunOptions o;
  o.select.cases_dir = cases_dir;
  o.select.cases = std::move(cases);
  o.cell.size = 48;
  o.select.shapes = {"cube", "torus"};
  o.cell.out_dir = out;
  o.cell.keep_images = "all";
  o.cell.timing = {.warmup = 0, .runs = 0};
  return o;
}

// The case file `name` of the corpus with each (from, to) edit applied, in a private tree
// that sees the corpus's shaders.
std::string edited_case(const test::TempDir& dir, const std::string& name,
                        const std::vector<std::pair<std::string, std::string>>& edits) {
  std::ifstream in(kRealWorld / "cases" / (name + ".toml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& [from, to] : edits) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  if (!fs::exists(dir.path() / "hlsl")) fs::create_directory_symlink(kRealWorld / "hlsl", dir.path() / "hlsl");
  dir.write("cases/" + name + ".toml", text);
  return (dir.path() / "cases").string();
}

TEST(MatrixConventions, RowVectorTwinRendersTheSamePixelsOnEveryHlslPath) {
  const test::TempDir out("matrix_conventions");
  auto report = run_suite(small_run((kRealWorld / "cases").string(), {"hlsl_lambert_two_entries", "hlsl_lambert_row_vector"},
                                    out.path().string()));
  ASSERT_TRUE(report) << report.error().to_string();
  std::map<std::string, std::vector<const CellResult*>> by_case;
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message << " / " << r.attribution_reason;
    by_case[r.case_name].push_back(&r);
  }
  ASSERT_EQ(by_case["hlsl_lambert_two_entries"].size(), 6u);   // vulkan/spirv, gl/spirv, gl/cross x 2 shapes
  ASSERT_EQ(by_case["hlsl_lambert_row_vector"].size(), 6u);
  for (const CellResult* column : by_case["hlsl_lambert_two_entries"]) {
    const std::string stem = column->shape + "/hlsl-" + column->backend + "-" + column->path + ".exr";
    auto a = read_image_file((out.path() / "hlsl_lambert_two_entries" / "pixel" / stem).string());
    auto b = read_image_file((out.path() / "hlsl_lambert_row_vector" / "pixel" / stem).string());
    ASSERT_TRUE(a) << a.error().to_string();
    ASSERT_TRUE(b) << b.error().to_string();
    ASSERT_EQ(a->values.size(), b->values.size()) << stem;
    // mul(v, M) and mul(M, v) are different SPIR-V instructions (OpVectorTimesMatrix,
    // OpMatrixTimesVector), which the drivers may sum in another order: clip positions
    // can differ in the last float bit. Coverage must be identical; colours within a
    // small fraction of the case's interior tolerance (1e-5).
    const int channels = a->channels;
    size_t coverage_differs = 0;
    double largest = 0;
    for (size_t i = 0; i < a->values.size(); ++i) {
      if (channels == 4 && i % 4 == 3) coverage_differs += (a->values[i] != 0) != (b->values[i] != 0);
      else largest = std::max(largest, double(std::abs(a->values[i] - b->values[i])));
    }
    EXPECT_EQ(coverage_differs, 0u) << stem << ": mul(v, M) with the transposed upload covers other pixels";
    EXPECT_LE(largest, 1e-6) << stem << ": mul(v, M) with the transposed upload differs from mul(M, v)";
  }
}

TEST(MatrixConventions, ARowVectorShaderGivenTheColumnVectorMatrixIsBlamedOnTheConvention) {
  const test::TempDir dir("matrix_conventions_bug");
  const std::string cases = edited_case(dir, "hlsl_lambert_row_vector",
                                        {{"{ value = \"transform\", layout = \"row_vector\" }", "\"transform\""}});
  auto report = run_suite(small_run(cases, {}));
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_EQ(report->results.size(), 6u);
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::fail) << r.id();
    EXPECT_EQ(r.attribution, "matrix convention") << r.id() << ": " << r.message << " / " << r.attribution_reason;
    EXPECT_NE(r.attribution_reason.find("row-vector shader (mul(v, M)) given a column-vector matrix"),
              std::string::npos)
        << r.attribution_reason;
    EXPECT_NE(r.attribution_reason.find("layout = \"row_vector\""), std::string::npos) << r.attribution_reason;
  }
}

TEST(MatrixConventions, SeparateRowVectorMatricesPointLightAmbientAndPaddingPass) {
  auto report = run_suite(small_run((kRealWorld / "cases").string(), {"hlsl_lambert_point_ambient"}));
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_EQ(report->results.size(), 6u);
  for (const CellResult& r : report->results)
    EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message << " / " << r.attribution_reason;
}

TEST(MatrixConventions, WithoutThePointLightTheSameShaderFails) {
  // The reference lights Lambert with its directional light: the port's point light differs.
  const test::TempDir dir("matrix_conventions_light");
  const std::string cases = edited_case(dir, "hlsl_lambert_point_ambient", {{"light = \"point\"\n", ""}});
  auto report = run_suite(small_run(cases, {}));
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) EXPECT_EQ(r.status, CellStatus::fail) << r.id();
}

TEST(MatrixConventions, APaddingLiteralOfTheWrongLengthNamesTheUniformAndTheLine) {
  const test::TempDir dir("matrix_conventions_padding");
  const std::string cases = edited_case(dir, "hlsl_lambert_point_ambient", {{"padding = 0.0", "padding = [0.0, 0.0]"}});
  auto report = run_suite(small_run(cases, {}));
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::error) << r.id();
    EXPECT_NE(r.message.find("uniform 'padding' (float) needs 1 value, the case gives 2"), std::string::npos)
        << r.message;
    EXPECT_NE(r.message.find("hlsl_lambert_point_ambient.toml:21"), std::string::npos) << r.message;
  }
}

}  // namespace
}  // namespace shaderbed
