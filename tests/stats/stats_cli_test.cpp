// `shaderbed stats` end to end: JSON out, a baseline comparison whose exit status gates
// CI (--fail-above), a table that fits 120 columns (--wide for all of them), progress on
// stderr only.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

std::pair<int, std::string> cli(const std::string& args) {
  std::string out;
  FILE* p = popen((std::string(SHADERBED_BINARY) + " " + args + " 2>&1").c_str(), "r");
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

TEST(StatsCli, BaselineReportsHelpedAndHurtAndGatesOnThreshold) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_stats_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string now = (dir / "now.json").string(), old = (dir / "old.json").string();
  auto [status, out] = cli("stats --no-nir --case phong --lang glsl,hlsl --quiet --json " + now);
  ASSERT_EQ(status, 0) << out;
  // The baseline: every fragment shader 25% smaller, so the current run is HURT.
  nlohmann::json j = nlohmann::json::parse(std::ifstream(now));
  ASSERT_FALSE(j["entries"].empty());
  for (auto& e : j["entries"])
    if (e["stage"] == "fragment") e["spirv_opt"]["total"] = int(e["spirv_opt"]["total"].get<int>() * 0.75);
  std::ofstream(old) << j.dump();

  auto [hurt_status, hurt] = cli("stats --from " + now + " --baseline " + old + " --fail-above 5");
  EXPECT_EQ(hurt_status, 1) << hurt;
  EXPECT_NE(hurt.find("HURT"), std::string::npos) << hurt;
  auto [lenient_status, lenient] = cli("stats --from " + now + " --baseline " + old + " --fail-above 80");
  EXPECT_EQ(lenient_status, 0) << lenient;
  auto [helped_status, helped] = cli("stats --from " + old + " --baseline " + now + " --fail-above 5");
  EXPECT_EQ(helped_status, 0) << helped;
  EXPECT_NE(helped.find("helped"), std::string::npos) << helped;
  fs::remove_all(dir);
}

struct Output {
  int status = -1;
  std::string out, err;
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// stdout and stderr apart (stderr a file, not a terminal).
Output cli_split(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const int status = std::system((std::string(SHADERBED_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string()).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_all(out), read_all(err)};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shaderbed_stats_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(StatsCli, DefaultTableFits120ColumnsWithDistinctHeadersAndWideHasEveryColumn) {
  const fs::path dir = fresh_dir("table");
  const std::string json = (dir / "counts.json").string();
  const Output run = cli_split("stats --no-nir --case phong,oren_nayar --json " + json, dir);
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  const std::vector<std::string> lines = lines_of(run.out);
  ASSERT_GT(lines.size(), 10u) << run.out;
  for (const std::string& line : lines) EXPECT_LE(line.size(), 120u) << line;
  // The header names every column once; the NIR columns say which driver.
  const std::string& header = lines.front();
  for (const char* column : {"lang", "spirv", "-O", "-Os", "glsl", "nir vk", "nir gl", "book"})
    EXPECT_NE(header.find(column), std::string::npos) << column << " missing from: " << header;
  std::istringstream words(header);
  std::set<std::string> seen;
  for (std::string word; words >> word;)
    if (word != "nir") {
      EXPECT_TRUE(seen.insert(word).second) << "header '" << word << "' twice in: " << header;
    }
  EXPECT_NE(run.out.find("oren_nayar/"), std::string::npos);
  EXPECT_NE(run.out.find("phong/"), std::string::npos);

  const Output wide = cli_split("stats --wide --from " + json, dir);
  ASSERT_EQ(wide.status, 0) << wide.out << wide.err;
  const std::vector<std::string> wide_lines = lines_of(wide.out);
  ASSERT_GT(wide_lines.size(), 2u);
  for (const char* column : {" tot ", " mem ", " cv ", " ot ", " -Os ", " glsl ", " nir vk ", " nir gl"})
    EXPECT_NE(wide_lines[1].find(column), std::string::npos) << column << " missing from: " << wide_lines[1];
  EXPECT_GT(wide_lines[1].size(), 120u) << "the wide form is the full one";
  fs::remove_all(dir);
}

TEST(StatsCli, ProgressGoesToStderrAndStdoutKeepsOnlyTheTable) {
  const fs::path dir = fresh_dir("progress");
  const std::string json = (dir / "counts.json").string();
  const Output run = cli_split("stats --case phong --variant pixel --lang glsl --json " + json, dir);
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  // Off a terminal: a plain line per tenth of the steps (compiles, then NIR reads), the last at 100%.
  EXPECT_NE(run.err.find("progress: "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(" steps (100%)"), std::string::npos) << run.err;
  EXPECT_LE(lines_of(run.err).size(), 10u) << run.err;
  EXPECT_EQ(run.out.find("progress"), std::string::npos) << run.out;
  // stdout is the table the same counts print from the JSON, then the timing line.
  const Output again = cli_split("stats --from " + json, dir);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(run.out.starts_with(again.out)) << run.out << "\n---\n" << again.out;
  EXPECT_EQ(lines_of(run.out).size(), lines_of(again.out).size() + 1);
  EXPECT_NE(lines_of(run.out).back().find(" entries in "), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
