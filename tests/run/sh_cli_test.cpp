// `shaderbed sh project|transfer|eval` through the binary: the book's Fig. 8.14 coefficients
// (jittered within 5e-3 of the exact ones, the book's printed values within 2e-3), the
// transfer served from the cache the second time, the error of per-vertex SH lighting
// falling with the band count, and bad input as exit 2 with a line naming what is wrong.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::shaderbed_cli;

using shaderbed::test::TempDir;
using nlohmann::json;

// stdout and stderr together, as a user sees them.
// stdout alone, parsed as JSON (progress, if any, goes to stderr).
json shaderbed_json(const std::string& args) {
  const auto [status, out] = shaderbed::test::run_shell("(" + std::string(SHADERBED_BINARY) + " " + args + " 2>/dev/null)");
  EXPECT_EQ(status, 0) << args << "\n" << out;
  const json j = json::parse(out, nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << "not JSON:\n" << out;
  return j;
}

TEST(ShCli, ProjectPrintsTheBooksFig814Coefficients) {
  const json j = shaderbed_json("sh project --light book --bands 5 --grid 100 --json");
  ASSERT_TRUE(j.contains("coefficients")) << j.dump(2);
  const json& c = j["coefficients"];
  ASSERT_EQ(c.size(), 25u);
  double worst_jittered = 0, worst_book = 0;
  for (size_t i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c[i]["i"].get<int>(), int(i));
    const int l = c[i]["l"].get<int>(), m = c[i]["m"].get<int>();
    EXPECT_EQ(l * (l + 1) + m, int(i));
    const double exact = c[i]["exact"].get<double>();
    EXPECT_NEAR(c[i]["jittered"].get<double>(), exact, 5e-3) << "i = " << i;
    EXPECT_NEAR(c[i]["book"].get<double>(), exact, 2e-3) << "i = " << i;
    worst_jittered = std::max(worst_jittered, std::abs(c[i]["jittered"].get<double>() - exact));
    worst_book = std::max(worst_book, std::abs(c[i]["book"].get<double>() - exact));
  }
  // c_0 = 0.225 sqrt(pi) exactly (docs/sh.md), and the book's first printed value.
  EXPECT_NEAR(c[0]["exact"].get<double>(), 0.225 * std::sqrt(M_PI), 1e-12);
  EXPECT_DOUBLE_EQ(c[0]["book"].get<double>(), 0.399249);
  EXPECT_DOUBLE_EQ(j["max_jittered_vs_exact"]["value"].get<double>(), worst_jittered);
  EXPECT_DOUBLE_EQ(j["max_book_vs_exact"]["value"].get<double>(), worst_book);
  EXPECT_EQ(j["samples"].get<int>(), 10000);

  // The text form states both differences.
  const auto [status, out] = shaderbed_cli("sh project --light book --bands 5 --grid 100");
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("max |jittered - exact|"), std::string::npos) << out;
  EXPECT_NE(out.find("max |book - exact|"), std::string::npos) << out;
}

// A Radiance .hdr of constant radiance (r, g, b) = (1, 1/2, 1/4), written by hand: flat RGBE
// pixels (128, 64, 32, 129), which readers take as uncompressed since the width is below 8.
std::string write_constant_probe(const TempDir& dir, const std::string& name, int width, int height) {
  std::string text = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
  for (int p = 0; p < width * height; ++p) text += std::string{char(128), char(64), char(32), char(129)};
  return dir.write(name, text);
}

TEST(ShCli, ProjectAProbeFile) {
  TempDir dir("sh_cli_probe");
  const std::string probe = write_constant_probe(dir, "constant.hdr", 4, 2);
  const json j = shaderbed_json("sh project --light probe --probe " + probe + " --bands 3 --grid 20 --json");
  ASSERT_EQ(j["coefficients"].size(), 9u) << j.dump(2);
  // A constant L has c_0 = sqrt(4 pi) L and nothing else, by the quadrature and by the jittered set.
  const double colour[3] = {1.0, 0.5, 0.25};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(j["coefficients"][0]["exact"][k].get<double>(), std::sqrt(4 * M_PI) * colour[k], 1e-2 * colour[k]);
    EXPECT_NEAR(j["coefficients"][0]["jittered"][k].get<double>(), std::sqrt(4 * M_PI) * colour[k], 1e-2 * colour[k]);
  }
  for (size_t i = 1; i < 9; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(j["coefficients"][i]["exact"][k].get<double>(), 0.0, 1e-9) << i;
}

TEST(ShCli, TransferComesFromTheCacheTheSecondTime) {
  TempDir dir("sh_cli_cache");
  const std::string args = "sh transfer --shape sphere --ground --grid 10 --bands 3 --json --cache-dir " + dir.path().string();
  const json first = shaderbed_json(args);
  EXPECT_FALSE(first["from_cache"].get<bool>()) << first.dump(2);
  EXPECT_EQ(first["vertices"].get<int>(), 153 + 289) << "the low sphere (17 x 9) and the 16 x 16 ground's 17 x 17";
  EXPECT_GT(first["rays_cast"].get<double>(), 0.0);
  EXPECT_FALSE(first.contains("transfer")) << "coefficients only with --coefficients";
  const std::string file = first["cache_file"].get<std::string>();
  EXPECT_EQ(file.rfind((dir.path() / "sh").string(), 0), 0u) << file;
  EXPECT_TRUE(std::filesystem::exists(file)) << file;

  const json second = shaderbed_json(args);
  EXPECT_TRUE(second["from_cache"].get<bool>()) << second.dump(2);
  EXPECT_EQ(second["cache_file"].get<std::string>(), file);
  EXPECT_EQ(second["rays_cast"].get<double>(), 0.0);
  EXPECT_EQ(second["rays"], first["rays"]);

  // --no-cache computes again; --coefficients gives every vertex's bands² RGB values.
  const json fresh = shaderbed_json(args + " --no-cache --coefficients");
  EXPECT_FALSE(fresh["from_cache"].get<bool>());
  ASSERT_EQ(fresh["transfer"].size(), 2u);
  EXPECT_EQ(fresh["transfer"][0].size(), 153u);
  EXPECT_EQ(fresh["transfer"][0][0].size(), 9u);
}

TEST(ShCli, EvalErrorFallsWithBandsForADirectionalLight) {
  const json j = shaderbed_json("sh eval --shape sphere --light directional --bands-list 1,2,4 --grid 20 --no-cache --json");
  const json& rows = j["rows"];
  ASSERT_EQ(rows.size(), 3u) << j.dump(2);
  EXPECT_EQ(rows[0]["bands"].get<int>(), 1);
  EXPECT_EQ(rows[2]["bands"].get<int>(), 4);
  for (size_t r = 1; r < rows.size(); ++r) {
    EXPECT_LT(rows[r]["max_abs"].get<double>(), rows[r - 1]["max_abs"].get<double>()) << j.dump(2);
    EXPECT_LT(rows[r]["rms"].get<double>(), rows[r - 1]["rms"].get<double>()) << j.dump(2);
  }
  // A unit delta: the facing vertex reflects exactly 1, and 4 bands are within 0.15 of it.
  EXPECT_NEAR(j["max_exact"].get<double>(), 1.0, 1e-6);
  EXPECT_LT(rows[2]["max_abs"].get<double>(), 0.15);
}

TEST(ShCli, BadInputIsExit2NamingTheOption) {
  const std::pair<std::string, std::string> cases[] = {
      {"sh project --bands 0", "--bands"},
      {"sh project --bands 13", "--bands"},
      {"sh project --grid 0", "--grid"},
      {"sh project --light moon", "--light"},
      {"sh project --light probe", "--probe"},
      {"sh transfer --shape teapot", "--shape"},
      {"sh transfer --shape sphere --kind glossy", "--kind"},
      {"sh transfer --shape sphere --bands 13", "--bands"},
      {"sh transfer --shape sphere --grid 0", "--grid"},
      {"sh transfer --shape sphere --tessellation medium", "--tessellation"},
      {"sh eval --shape sphere --kind interreflected", "--kind"},
      {"sh eval --shape sphere --light probe", "--probe"},
      {"sh eval --shape sphere --bands-list 1,0", "--bands-list"},
      {"sh eval --shape sphere --light moon", "--light"},
  };
  for (const auto& [args, option] : cases) {
    const auto [status, out] = shaderbed_cli(args);
    EXPECT_EQ(status, 2) << args << "\n" << out;
    EXPECT_NE(out.find(option), std::string::npos) << args << "\n" << out;
  }
}

TEST(ShCli, AMissingOrUnreadableProbeNamesTheFile) {
  TempDir dir("sh_cli_bad_probe");
  const std::string missing = dir / "no_such_probe.hdr";
  for (const std::string command : {"sh project --light probe --probe ", "sh eval --shape sphere --light probe --probe "}) {
    const auto [status, out] = shaderbed_cli(command + missing);
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find(missing), std::string::npos) << out;
  }
  const std::string garbage = dir.write("garbage.exr", "not an image");
  const auto [status, out] = shaderbed_cli("sh project --light probe --probe " + garbage);
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find(garbage), std::string::npos) << out;
}

}  // namespace
