// `shaderbed sweep` end to end: real renders on lavapipe, the JSON shape, error that
// falls as the LUT grows and as the mesh gets finer, a chart from gnuplot, clear bad input.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct CliRun {
  int status;
  std::string output;
};

CliRun shaderbed(const std::string& args) {
  const std::string command = std::string(SHADERBED_BINARY) + " " + args + " 2>&1";
  CliRun run{0, ""};
  FILE* pipe = popen(command.c_str(), "r");
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) run.output.append(buffer, n);
  const int status = pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed-sweep-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

json read(const fs::path& file) {
  std::ifstream f(file);
  return json::parse(f);
}

TEST(SweepCli, LutSizeSweepWritesPointsWithFallingErrorAndAChart) {
  const fs::path dir = fresh("lut");
  const CliRun run = shaderbed("sweep oren_nayar --param lut_size=8:256:6 --size 96 --repeat 3 --json " +
                            (dir / "o.json").string() + " --chart " + (dir / "chart").string());
  ASSERT_EQ(run.status, 0) << run.output;
  const json j = read(dir / "o.json");
  std::map<double, double> lut_rmse;   // lut_size -> rmse of the LUT variant
  size_t arithmetic = 0, on_front = 0;
  for (const json& p : j.at("points")) {
    for (const char* key : {"params", "rmse", "max_abs", "time_ms", "instructions"}) ASSERT_TRUE(p.contains(key)) << key;
    EXPECT_GT(p.at("time_ms").get<double>(), 0.0);
    EXPECT_GT(p.at("instructions").get<int>(), 0);
    on_front += p.at("pareto").get<bool>();
    const json& params = p.at("params");
    if (params.at("variant") == "pixel_lut") lut_rmse[params.at("lut_size").get<double>()] = p.at("rmse").get<double>();
    else {
      EXPECT_FALSE(params.contains("lut_size")) << "an arithmetic variant does not read the LUT size";
      ++arithmetic;
    }
  }
  ASSERT_EQ(lut_rmse.size(), 6u);
  EXPECT_EQ(lut_rmse.begin()->first, 8);
  EXPECT_EQ(lut_rmse.rbegin()->first, 256);
  for (auto it = std::next(lut_rmse.begin()); it != lut_rmse.end(); ++it)
    EXPECT_LT(it->second, std::prev(it)->second) << "lut_size " << it->first;
  EXPECT_EQ(arithmetic, 2u);   // vertex and pixel, drawn once each
  EXPECT_GE(on_front, 1u);
  EXPECT_GT(fs::file_size(dir / "chart.png"), 1000u);
  EXPECT_GT(fs::file_size(dir / "chart.svg"), 1000u);
  ASSERT_EQ(j.at("charts").size(), 1u);   // LUT sizes are ways of drawing one scene
  EXPECT_EQ(j.at("charts")[0].at("png"), (dir / "chart.png").string());
}

TEST(SweepCli, PerVertexErrorFallsAsTheMeshGetsFiner) {
  const fs::path dir = fresh("tess");
  const CliRun run = shaderbed("sweep phong --variant vertex --param tessellation=8:64:4 --size 96 --repeat 1 --json " +
                            (dir / "p.json").string());
  ASSERT_EQ(run.status, 0) << run.output;
  double previous = 1e9;
  size_t points = 0;
  const json j = read(dir / "p.json");
  for (const json& p : j.at("points")) {
    const double rmse = p.at("rmse").get<double>();
    EXPECT_LT(rmse, previous) << p.at("params").dump();
    previous = rmse;
    ++points;
  }
  EXPECT_EQ(points, 4u);
}

TEST(SweepCli, EachSceneHasItsOwnParetoFrontAndChart) {
  const fs::path dir = fresh("scenes");
  const CliRun run = shaderbed("sweep ward_iso --variant pixel,pixel_robust --param roughness=0.01:0.5:2 --size 64 "
                               "--repeat 1 --json " + (dir / "w.json").string() + " --chart " + (dir / "w").string());
  ASSERT_EQ(run.status, 0) << run.output;
  const json j = read(dir / "w.json");
  std::map<std::string, int> fronts;   // scene -> points on its front
  for (const json& p : j.at("points")) fronts[p.at("scene").get<std::string>()] += p.at("pareto").get<bool>();
  ASSERT_EQ(fronts.size(), 2u);
  for (const auto& [scene, on_front] : fronts) EXPECT_GE(on_front, 1) << scene;
  ASSERT_EQ(j.at("charts").size(), 2u);
  EXPECT_TRUE(fs::exists(dir / "w-1.svg"));
  EXPECT_TRUE(fs::exists(dir / "w-2.png"));
}

TEST(SweepCli, BadInputIsOneLineAndStatusTwo) {
  for (const char* args : {"sweep no_such_case", "sweep phong --param no_such=1:2:2", "sweep phong --param power=1:2",
                           "sweep phong --precision fp64", "sweep phong --param diffuse=0:1:2"}) {
    const CliRun run = shaderbed(args);
    EXPECT_EQ(run.status, 2) << args << "\n" << run.output;
    EXPECT_NE(run.output.find("shaderbed: "), std::string::npos) << args << "\n" << run.output;
  }
}

}  // namespace
