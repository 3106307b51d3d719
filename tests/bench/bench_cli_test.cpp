// `shaderbed bench --quick --json F`: the JSON's structure, and that the accounting adds
// up. No timing thresholds: the numbers depend on the machine and its load.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int status;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

CliRun shaderbed_bench(const std::string& args) {
  const fs::path stem = fs::temp_directory_path() / ("bench_cli_" + std::to_string(::getpid()));
  const fs::path out = stem.string() + ".out", err = stem.string() + ".err";
  const std::string command =
      std::string(SHADERBED_BINARY) + " bench " + args + " > " + out.string() + " 2> " + err.string();
  const int raw = std::system(command.c_str());
  CliRun r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  fs::remove(out);
  fs::remove(err);
  return r;
}

// Relative to the larger side, so sums of many parts compare despite rounding.
void expect_close(double a, double b, const std::string& what) {
  EXPECT_NEAR(a, b, 1e-9 * std::max({1.0, std::abs(a), std::abs(b)})) << what;
}

// One bench run for all of it (a quick bench is the suite in three cache states and more,
// ~15 s): --out makes the images' writing a part of shaderbed's own, counted per cell.
TEST(BenchCli, QuickRunWritesJsonWhosePartsAddUp) {
  const fs::path dir = fs::temp_directory_path() / ("bench_cli_out_" + std::to_string(::getpid()));
  const fs::path json_path = dir / "bench.json";
  const CliRun r = shaderbed_bench("--quick --out " + (dir / "images").string() + " --json " + json_path.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(slurp(json_path));
  EXPECT_TRUE(fs::exists(dir / "images" / "phong"));
  fs::remove_all(dir);

  EXPECT_EQ(j["schema"], 1);
  EXPECT_EQ(j["size"], 64);
  EXPECT_EQ(j["cases"], nlohmann::json::array({"phong"}));
  EXPECT_EQ(j["suite_timing"]["runs"], 0) << "the suite's draws are untimed";

  const nlohmann::json& s = j["suite"];
  EXPECT_GT(s["cells"].get<int>(), 0);
  EXPECT_EQ(s["errors"], 0);
  EXPECT_GT(s["wall_ms"].get<double>(), 0);
  EXPECT_GE(s["workers"].get<int>(), 1);
  expect_close(s["worker_ms"], s["wall_ms"].get<double>() * s["workers"].get<int>(), "worker_ms");

  double driver = 0, own = 0;
  for (const char* name : {"build", "draw", "readback", "compile", "reference", "compare", "io"}) {
    ASSERT_TRUE(s["parts"].contains(name)) << name;
    const nlohmann::json& p = s["parts"][name];
    EXPECT_GE(p["ms"].get<double>(), 0) << name;
    EXPECT_GT(p["count"].get<int>(), 0) << name;
    (p["owner"] == "driver" ? driver : own) += p["ms"].get<double>();
  }
  EXPECT_EQ(s["parts"]["draw"]["owner"], "driver");
  EXPECT_EQ(s["parts"]["compile"]["owner"], "shaderbed");
  EXPECT_EQ(s["parts"]["io"]["owner"], "shaderbed");
  EXPECT_EQ(s["parts"]["io"]["count"], s["cells"]);
  EXPECT_GT(s["parts"]["io"]["ms"].get<double>(), 0);
  EXPECT_EQ(s["parts"]["draw"]["count"], s["cells"]);
  EXPECT_LT(s["parts"]["compile"]["count"].get<int>(), s["cells"].get<int>()) << "one compile per program";
  expect_close(s["driver_ms"], driver, "driver_ms");
  expect_close(s["shaderbed_ms"], own, "shaderbed_ms");
  expect_close(s["summed_ms"], driver + own, "summed_ms");
  expect_close(s["unaccounted_ms"], s["worker_ms"].get<double>() - s["summed_ms"].get<double>(), "unaccounted_ms");
  expect_close(s["shares"]["driver"].get<double>() + s["shares"]["shaderbed"].get<double>(), 1, "shares");

  ASSERT_EQ(j["reference_vs_drivers"].size(), 1u);
  const nlohmann::json& c = j["reference_vs_drivers"][0];
  EXPECT_EQ(c["case"], "phong");
  EXPECT_EQ(c["variant"], "pixel");
  EXPECT_EQ(c["shape"], "sphere");
  EXPECT_EQ(c["runs"], 3);
  const double reference = c["reference_ms"]["median"];
  EXPECT_GT(reference, 0);
  EXPECT_LE(c["reference_ms"]["low"].get<double>(), reference);
  EXPECT_GE(c["reference_ms"]["high"].get<double>(), reference);
  bool lavapipe = false, llvmpipe = false;
  for (const nlohmann::json& d : c["draws"]) {
    lavapipe |= d["driver"] == "lavapipe";
    llvmpipe |= d["driver"] == "llvmpipe";
    const double draw = d["wall_ms"]["median"];
    ASSERT_GT(draw, 0) << d.dump();
    expect_close(d["reference_ratio"], reference / draw, "ratio");
  }
  EXPECT_TRUE(lavapipe && llvmpipe) << c.dump(2);

  EXPECT_NE(r.out.find("reference / lavapipe = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reference / llvmpipe = "), std::string::npos) << r.out;

  // The processes: the suite in three cache states, one cell cold and warm, and start-up,
  // each figure printed beside its goal. Only structure and consistency: no timing bound.
  const nlohmann::json& p = j["processes"];
  for (const char* state : {"cold", "warm", "off"}) {
    const nlohmann::json& suite = p["suite"][state];
    EXPECT_GT(suite["wall_ms"].get<double>(), 0) << state;
    EXPECT_EQ(suite["cells"], s["cells"]) << state << ": the same selection in every state";
    EXPECT_EQ(suite["failures"], 0) << state;
  }
  expect_close(p["ratios"]["warm_of_cold"],
               p["suite"]["warm"]["wall_ms"].get<double>() / p["suite"]["cold"]["wall_ms"].get<double>(), "warm_of_cold");
  for (const char* state : {"cold", "warm"}) {
    const nlohmann::json& cell = p["cell"][state];
    EXPECT_EQ(cell["runs"].size(), 3u) << state;
    EXPECT_NE(cell["command"].get<std::string>().find("--case phong"), std::string::npos) << cell.dump();
    EXPECT_LE(cell["wall_ms"]["low"].get<double>(), cell["wall_ms"]["median"].get<double>());
  }
  for (const char* command : {"--help", "eval", "merge"}) {
    ASSERT_TRUE(p["startup"].contains(command)) << command;
    EXPECT_EQ(p["startup"][command]["runs"].size(), 3u) << command;
    EXPECT_GT(p["startup"][command]["wall_ms"]["median"].get<double>(), 0) << command;
  }
  for (const char* line : {"suite, caches cold", "suite, caches warm", "suite, caches off", "one cell, cold caches",
                           "one cell, warm caches", "--help", "JIT floor", "goal <= 60 ms"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << " missing from:\n" << r.out;
}

TEST(BenchCli, MalformedCompareCellIsBadInput) {
  const CliRun r = shaderbed_bench("--compare phong/pixel");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("case/variant/shape"), std::string::npos) << r.err;
}

}  // namespace
