// End to end on the real drivers: the default suite passes on every backend and GL
// path, a planted bug fails, and the CLI's exit codes and JSON are what CI relies on.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <tuple>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "SourceTree.h"
#include "ShellCommand.h"
#include "run/Runner.h"

namespace shaderbed {
namespace {

using shaderbed::test::shaderbed_cli;

namespace fs = std::filesystem;
using shaderbed::test::kSource;

// Runs the CLI; returns the exit status and stdout+stderr.
TEST(EndToEnd, DefaultSuitePassesOnEveryBackendAndGlPath) {
  auto report = run_suite(RunOptions{});
  ASSERT_TRUE(report) << report.error().to_string();
  std::set<std::tuple<std::string, std::string, std::string>> language_backend_path;
  std::set<std::string> cases, shapes;
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::pass) << r.case_name << " " << r.variant << " " << r.language << " " << r.backend << "/"
                                << r.path << " " << r.shape << ": " << r.message;
    language_backend_path.insert({r.language, r.backend, r.path});
    cases.insert(r.case_name);
    shapes.insert(r.shape);
    EXPECT_GT(r.metrics.interior_pixels, 1000u) << "a blank or tiny image would compare trivially";
  }
  // GLSL runs on Vulkan and all three GL paths; HLSL and Cg everywhere but native GLSL.
  const std::set<std::tuple<std::string, std::string, std::string>> expected{
      {"glsl", "vulkan", "spirv"}, {"glsl", "gl", "glsl"},  {"glsl", "gl", "spirv"}, {"glsl", "gl", "cross"},
      {"hlsl", "vulkan", "spirv"}, {"hlsl", "gl", "spirv"}, {"hlsl", "gl", "cross"}, {"cg", "vulkan", "spirv"},
      {"cg", "gl", "spirv"},       {"cg", "gl", "cross"}};
  EXPECT_EQ(language_backend_path, expected);
  EXPECT_EQ(shapes.size(), 4u);
  // The whole library, with the LUT variants where the book has them.
  const std::set<std::string> library{"ambient",  "lambert",    "warn",     "phong",      "blinn_phong",
                                      "oren_nayar", "minnaert", "ward_iso", "ward_aniso", "schlick",
                                      "cook_torrance", "point_attenuated", "spot", "sh", "sh_cpca", "sh_irradiance",
                                      "sh_specular"};
  EXPECT_EQ(cases, library);
  std::map<std::pair<std::string, std::string>, double> lut_error;   // largest over shapes and paths
  for (const CellResult& r : report->results)
    if (r.variant == "pixel_lut") {
      EXPECT_FALSE(r.lut_derivation.empty()) << "a LUT threshold is derived, not typed in";
      double& e = lut_error[{r.case_name, r.language}];
      e = std::max(e, r.metrics.max_abs);
    }
  EXPECT_EQ(lut_error.size(), 3u * 3u) << "warn, oren_nayar and ward_iso in hlsl, cg and glsl";
  for (const auto& [key, error] : lut_error)
    EXPECT_GT(error, 1e-4) << key.first << "/" << key.second << ": LUT renders equal to the analytic model mean no LUT";
}

TEST(EndToEnd, EvalPrintsTheReferenceValue) {
  auto [status, out] = shaderbed_cli("eval phong --L 0,1,0 --V 1,1,0");
  ASSERT_EQ(status, 0) << out;
  // N = +Y = L, so R = L and R.V = cos 45: 1 (diffuse) + cos(45)^7 (specular).
  const double expected = 1 + std::pow(std::sqrt(0.5), 7);
  const size_t at = out.find("rgb = ");
  ASSERT_NE(at, std::string::npos) << out;
  EXPECT_NEAR(std::stod(out.substr(at + 6)), expected, 1e-15);
  auto [bad_status, bad] = shaderbed_cli("eval phong --L 0,1,0 --V 1,1,0 --param pwer=3");
  EXPECT_EQ(bad_status, 2);
  EXPECT_NE(bad.find("pwer"), std::string::npos) << bad;
}

TEST(EndToEnd, ParamOverrideReachesShadersAndReference) {
  // A different exponent changes both sides; they must still agree.
  RunOptions o;
  o.select.cases = {"phong"};
  o.select.variants = {"pixel"};
  o.select.shapes = {"sphere"};
  o.select.params = {"power=30", "diffuse=0.5,0.25,1"};
  auto report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  for (const CellResult& r : report->results) EXPECT_EQ(r.status, CellStatus::pass) << r.language << " " << r.message;
}

TEST(EndToEnd, PlantedReflectionSignBugFailsEveryCell) {
  RunOptions o;
  o.select.cases_dir = (kSource / "tests" / "mutants" / "cases").string();
  o.select.cases = {"phong_reflect_sign"};
  auto report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());
  for (const CellResult& r : report->results) {
    EXPECT_EQ(r.status, CellStatus::fail) << r.language << " " << r.backend << "/" << r.path << " " << r.shape;
    EXPECT_GT(r.metrics.max_abs, 100 * r.interior_threshold) << "the misplaced highlight is no rounding error";
  }
}

TEST(EndToEnd, CliPassesWritesJsonAndImages) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const fs::path json = dir / "r.json";
  auto [status, out] = shaderbed_cli("run --case lambert --shape cube,torus --backend vulkan --backend gl --size 64 "
                                     "--keep-images all --out " +
                                     dir.string() + " --json " + json.string());
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("lambert"), std::string::npos);
  std::ifstream in(json);
  ASSERT_TRUE(in) << out;
  const nlohmann::json j = nlohmann::json::parse(in);
  for (const char* key : {"glslang", "spirv_tools", "spirv_cross", "mesa"}) EXPECT_TRUE(j["tools"].contains(key)) << key;
  EXPECT_NE(j["tools"]["mesa"]["vulkan"].get<std::string>().find("Mesa"), std::string::npos);
  // 2 variants x 2 shapes x (GLSL: 4 paths, HLSL: 3, Cg: 3).
  ASSERT_EQ(j["results"].size(), 2u * 2u * (4u + 3u + 3u));
  for (const auto& r : j["results"]) {
    for (const char* key : {"case", "variant", "language", "backend", "path", "shape", "status", "metrics", "time_ms"})
      EXPECT_TRUE(r.contains(key)) << key;
    for (const char* key : {"max_abs", "rmse", "psnr", "bad_pixels", "nonfinite"})
      EXPECT_TRUE(r["metrics"].contains(key)) << key;
    EXPECT_EQ(r["status"], "pass");
    EXPECT_TRUE(fs::exists(r["image"].get<std::string>()));
  }
  EXPECT_TRUE(fs::exists(dir / "lambert" / "pixel" / "cube" / "reference.exr"));
  EXPECT_TRUE(fs::exists(dir / "lambert" / "pixel" / "cube" / "hlsl-gl-cross.error.png"));
  fs::remove_all(dir);
}

TEST(EndToEnd, CliExitCodes) {
  EXPECT_EQ(shaderbed_cli("run --backend metal").first, 2);
  EXPECT_EQ(shaderbed_cli("run --case no_such_case").first, 2);
  EXPECT_EQ(shaderbed_cli("run --size abc").first, 2);
  EXPECT_EQ(shaderbed_cli("frobnicate").first, 2);
  auto [status, out] = shaderbed_cli("run --cases-dir " + (kSource / "tests" / "mutants" / "cases").string() +
                                     " --case phong_reflect_sign --shape sphere --size 64");
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("FAIL"), std::string::npos) << out;
  auto [help_status, help] = shaderbed_cli("run --help");
  EXPECT_EQ(help_status, 0);
  EXPECT_NE(help.find("--backend"), std::string::npos);
}

// Lines of `text` that end with `suffix`.
size_t lines_ending(const std::string& text, const std::string& suffix) {
  size_t n = 0;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) n += line.ends_with(suffix);
  return n;
}

TEST(EndToEnd, ConsoleShowsTheSummaryTheTableOrOnlyTheProblems) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_console_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string json = (dir / "r.json").string();
  const std::string run = "run --case phong --shape sphere --size 32 --repeat 0";   // 3 variants x 10 paths
  const std::regex totals("\n30 cells: 30 passed, 0 failed, 0 known, 0 errors in [0-9.]+ s\n");

  // Default: progress (a line per tenth off a terminal), the matrix, the totals; no cell rows.
  auto [status, out] = shaderbed_cli(run + " --json " + json);
  ASSERT_EQ(status, 0) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex("\nphong +pixel +(1/1 +){10}[0-9.e+-]+ +[0-9<]+%\n +pixel_literal +(1/1 +){10}"))) << out;
  EXPECT_NE(out.find("max err"), std::string::npos) << out;
  EXPECT_EQ(out.find("min pass"), std::string::npos) << out;
  EXPECT_EQ(lines_ending(out, "  pass"), 0u) << out;
  EXPECT_NE(out.find("progress: 30/30 cells (100%)"), std::string::npos) << out;
  size_t progress_lines = 0;
  for (size_t at = out.find("progress: "); at != std::string::npos; at = out.find("progress: ", at + 1)) ++progress_lines;
  EXPECT_LE(progress_lines, 10u) << out;
  EXPECT_TRUE(std::regex_search(out, totals)) << out;

  // --table (and -v): a row per cell; --timing alone shows the table too.
  for (const char* flag : {" --table", " -v", " --timing"}) {
    auto [table_status, table] = shaderbed_cli(run + flag);
    EXPECT_EQ(table_status, 0) << flag << "\n" << table;
    EXPECT_NE(table.find("min pass"), std::string::npos) << flag << "\n" << table;
    EXPECT_EQ(table.find("worst"), std::string::npos) << flag << "\n" << table;
    EXPECT_TRUE(std::regex_search(table, totals)) << flag << "\n" << table;
  }
  EXPECT_EQ(lines_ending(shaderbed_cli(run + " --table").second, "  pass"), 30u);

  // --quiet: the totals only, when everything passed (and no progress off a terminal).
  auto [quiet_status, quiet] = shaderbed_cli(run + " -q");
  EXPECT_EQ(quiet_status, 0);
  EXPECT_TRUE(std::regex_match(quiet, std::regex("30 cells: 30 passed, 0 failed, 0 known, 0 errors in [0-9.]+ s\n"))) << quiet;
  EXPECT_EQ(shaderbed_cli(run + " -q --table").first, 2) << "--quiet and --table contradict";

  // A failing run, quiet: the failures with their attribution, then the verdict.
  auto [fail_status, failing] = shaderbed_cli("run --cases-dir " + (kSource / "tests" / "mutants" / "cases").string() +
                                              " --case phong_reflect_sign --shape sphere --size 32 --repeat 0 --lang glsl -q");
  EXPECT_EQ(fail_status, 1);
  EXPECT_TRUE(failing.starts_with("failures:\n  phong_reflect_sign ")) << failing;
  EXPECT_NE(failing.find("      attribution: "), std::string::npos) << failing;
  EXPECT_TRUE(std::regex_search(failing, std::regex("\nFAIL: [0-9]+ cells: 0 passed, [0-9]+ failed, 0 known, 0 errors in [0-9.]+ s\n$")))
      << failing;

  // merge prints the same views.
  auto [merged_status, merged] = shaderbed_cli("merge " + json);
  EXPECT_EQ(merged_status, 0) << merged;
  EXPECT_NE(merged.find("max err"), std::string::npos) << merged;
  EXPECT_EQ(merged.find("min pass"), std::string::npos) << merged;
  EXPECT_EQ(lines_ending(shaderbed_cli("merge " + json + " --table").second, "  pass"), 30u);
  EXPECT_TRUE(std::regex_match(shaderbed_cli("merge " + json + " --quiet").second,
                               std::regex("30 cells: 30 passed, 0 failed, 0 known, 0 errors in [0-9.]+ s\n")));
  fs::remove_all(dir);
}

TEST(EndToEnd, TwoShardsMergedByTheCliEqualOneRun) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_merge_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string common = " --case lambert,spot --shape cube,torus --size 48 ";
  ASSERT_EQ(shaderbed_cli("run" + common + "--json " + (dir / "whole.json").string()).first, 0);
  ASSERT_EQ(shaderbed_cli("run" + common + "--shard 1/2 --json " + (dir / "a.json").string()).first, 0);
  ASSERT_EQ(shaderbed_cli("run" + common + "--shard 2/2 --json " + (dir / "b.json").string()).first, 0);
  auto [status, out] = shaderbed_cli("merge " + (dir / "a.json").string() + " " + (dir / "b.json").string() +
                                     " --json " + (dir / "merged.json").string() + " --junit " +
                                     (dir / "merged.xml").string());
  ASSERT_EQ(status, 0) << out;
  auto load = [&](const char* name) { return nlohmann::json::parse(std::ifstream(dir / name)); };
  const nlohmann::json whole = load("whole.json"), merged = load("merged.json");
  ASSERT_EQ(whole["results"].size(), merged["results"].size());
  for (size_t i = 0; i < whole["results"].size(); ++i) {
    nlohmann::json a = whole["results"][i], b = merged["results"][i];
    // Timings differ run to run, and which cell first builds a shared pipeline depends on
    // how the cells were split; everything else must not differ.
    for (const char* timing : {"time_ms", "gpu_ms", "program_cached"}) {
      a.erase(timing);
      b.erase(timing);
    }
    EXPECT_EQ(a, b) << i;
  }
  EXPECT_TRUE(fs::exists(dir / "merged.xml"));
  EXPECT_EQ(shaderbed_cli("merge " + (dir / "a.json").string() + " " + (dir / "a.json").string()).first, 2)
      << "the same cells twice is bad input";
  fs::remove_all(dir);
}

TEST(EndToEnd, OneWorkerAndThreeWorkersGiveTheSameResults) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_jobs_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string common = " --case lambert,phong,warn --shape sphere,cone --size 40 --repeat 2 ";
  ASSERT_EQ(shaderbed_cli("run" + common + "--jobs 1 --json " + (dir / "one.json").string()).first, 0);
  ASSERT_EQ(shaderbed_cli("run" + common + "--jobs 3 --json " + (dir / "three.json").string()).first, 0);
  auto load = [&](const char* name) { return nlohmann::json::parse(std::ifstream(dir / name)); };
  const nlohmann::json one = load("one.json"), three = load("three.json");
  EXPECT_EQ(one["workers"], 1);
  EXPECT_EQ(three["workers"], 3);
  ASSERT_EQ(one["results"].size(), three["results"].size());
  for (size_t i = 0; i < one["results"].size(); ++i) {
    nlohmann::json a = one["results"][i], b = three["results"][i];
    // Every cell was timed (2 runs) and, with a worker per case x variant, each program's
    // pipeline was built exactly where the single worker built it too.
    EXPECT_EQ(a["gpu_ms"]["runs"], 2) << i;
    EXPECT_EQ(a["program_cached"], b["program_cached"]) << i;
    for (const char* timing : {"time_ms", "gpu_ms"}) {
      a.erase(timing);
      b.erase(timing);
    }
    EXPECT_EQ(a, b) << i;   // images, metrics and verdicts do not depend on the workers
  }
  fs::remove_all(dir);
}

// --html alone still shows the pictures: the renders go beside index.html.
TEST(EndToEnd, AnHtmlReportWithoutOutHasItsImages) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_html_only_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  auto [status, out] = shaderbed_cli("run --case lambert --shape cube --variant pixel --lang glsl --size 32 "
                                     "--keep-images all --html " + (dir / "html").string());
  ASSERT_EQ(status, 0) << out;
  std::ifstream in(dir / "html" / "index.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(html.find("Images: 0 embedded"), std::string::npos) << "a report without pictures";
  EXPECT_TRUE(fs::exists(dir / "html" / "lambert" / "pixel" / "cube")) << "the renders beside index.html";
  fs::remove_all(dir);
}

TEST(EndToEnd, ChartsFromSweepsGoIntoTheHtmlReport) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_chart_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "lut_trade_off.svg") << "<svg viewBox=\"0 0 4 4\"><rect id=\"marker-1234\"/></svg>\n";
  std::ofstream(dir / "page.svg") << "<svg><script>alert(1)</script></svg>\n";
  const std::string common = " --case lambert --shape cube --variant pixel --lang glsl --size 32 --html " + (dir / "html").string();
  ASSERT_EQ(shaderbed_cli("run" + common + " --chart " + (dir / "lut_trade_off.svg").string()).first, 0);
  std::ifstream in(dir / "html" / "index.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("<rect id=\"marker-1234\"/>"), std::string::npos);
  EXPECT_NE(html.find("lut_trade_off"), std::string::npos);
  auto [status, out] = shaderbed_cli("run" + common + " --chart " + (dir / "page.svg").string());
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("page.svg"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(EndToEnd, BadCaseFileIsOneLineWithFileAndLine) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_badcase_" + std::to_string(::getpid()));
  fs::create_directories(dir / "cases");
  std::ofstream(dir / "cases" / "bad.toml") << "model = \"phong\"\n[params]\npower = = 7\n";
  auto [status, out] = shaderbed_cli("run --cases-dir " + (dir / "cases").string());
  EXPECT_EQ(status, 2);
  EXPECT_NE(out.find("bad.toml:3:"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(EndToEnd, UnwritableOutputsAreBadInputBeforeAnythingRuns) {
  const fs::path file = fs::temp_directory_path() / ("shaderbed_plain_file_" + std::to_string(::getpid()));
  std::ofstream(file) << "a file, not a folder\n";
  for (const std::string option : {"--json", "--junit", "--html", "--out"}) {
    auto [status, out] = shaderbed_cli("run --case phong --shape sphere " + option + " " + (file / "sub" / "x").string());
    EXPECT_EQ(status, 2) << option << "\n" << out;
    EXPECT_NE(out.find(option + ": cannot write into"), std::string::npos) << out;
    EXPECT_EQ(out.find("cells:"), std::string::npos) << "nothing ran\n" << out;
  }
  fs::remove(file);
}

// A case's own mistakes are bad input (exit 2), each said once with its line: a binding name
// that is no quantity (before anything is drawn, with "did you mean"), a missing shader file,
// and a uniform the shader reads that the case leaves unbound.
TEST(EndToEnd, ACasesOwnMistakesAreBadInputWithTheirLine) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_case_mistakes_" + std::to_string(::getpid()));
  fs::create_directories(dir / "cases");
  fs::create_directories(dir / "glsl");
  for (const char* f : {"setup.vert", "lambert.frag"}) fs::copy_file(kSource / "shaders/glsl" / f, dir / "glsl" / f);
  const auto write_case = [&](const std::string& fragment, const std::string& bindings) {
    std::ofstream(dir / "cases" / "mine.toml", std::ios::trunc)
        << "model = \"lambert\"\n[variants.pixel]\nglsl = { vertex = \"glsl/setup.vert\", fragment = \"glsl/" << fragment
        << "\" }\n[bindings.glsl]\nmodelViewProjection = \"transform\"\n" << bindings;
    return "run --shape sphere --case " + (dir / "cases" / "mine.toml").string();
  };
  auto [typo_status, typo] = shaderbed_cli(write_case("lambert.frag", "lightDirection = \"light_vectr\"\ndiffuseColor = \"diffuse\"\n"));
  EXPECT_EQ(typo_status, 2) << typo;
  EXPECT_NE(typo.find("mine.toml:6:"), std::string::npos) << typo;
  EXPECT_NE(typo.find("lightDirection = 'light_vectr': neither a scene quantity nor a parameter of the case (did you mean "
                      "'light_vector'?)"),
            std::string::npos)
      << typo;
  EXPECT_EQ(typo.find("cells:"), std::string::npos) << "nothing ran\n" << typo;

  auto [missing_status, missing] = shaderbed_cli(write_case("lambrt.frag", "lightDirection = \"light_vector\"\n"));
  EXPECT_EQ(missing_status, 2) << missing;
  EXPECT_NE(missing.find("the glsl fragment shader " + (dir / "glsl" / "lambrt.frag").string() + " does not exist"),
            std::string::npos)
      << missing;
  EXPECT_EQ(missing.find("cells:"), std::string::npos) << "nothing ran\n" << missing;

  auto [unbound_status, unbound] = shaderbed_cli(write_case("lambert.frag", "lightDirection = \"light_vector\"\n"));
  EXPECT_EQ(unbound_status, 2) << unbound;
  EXPECT_NE(unbound.find("bind: uniform 'diffuseColor'"), std::string::npos) << unbound;
  EXPECT_NE(unbound.find("4 cells could not be bound"), std::string::npos) << unbound;
  fs::remove_all(dir);
}

TEST(EndToEnd, UnknownModelIsBadInputAtItsLineBeforeAnythingRuns) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_badmodel_" + std::to_string(::getpid()));
  fs::create_directories(dir / "cases");
  std::ofstream(dir / "cases" / "typo.toml")
      << "# a typo in the model\nmodel = \"phongg\"\n[variants.pixel]\nhlsl = { vertex = \"a.hlsl\", fragment = \"a.hlsl\" }\n"
         "[tolerance]\ninterior = { max_abs = 1e-5, reason = \"r\" }\nsilhouette = { max_abs = 1e-4, reason = \"r\" }\n";
  auto [status, out] = shaderbed_cli("run --cases-dir " + (dir / "cases").string());
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("typo.toml:2:"), std::string::npos) << out;
  EXPECT_NE(out.find("unknown model 'phongg' (did you mean 'phong'?)"), std::string::npos) << out;
  EXPECT_EQ(out.find("cells:"), std::string::npos) << "nothing ran\n" << out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace shaderbed
