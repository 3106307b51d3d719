// The whole real-world corpus (tests/realworld/) in one run, as a user would run it:
// `shaderbed run --cases tests/realworld/cases --expectations tests/realworld/planted_bugs.toml`.
// Every correct port passes (or is skipped, with a reason, where a path does not apply);
// every planted-bug port fails on every cell it draws, and the expectations file names
// exactly the bug cases. Prints the per-style counts the closing note quotes.
#include <filesystem>
#include <map>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "RealWorldRuns.h"
#include "run/Expectations.h"
#include "run/Runner.h"
#include "scene/CaseFile.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kRealWorld;

bool is_bug_case(const std::string& name) { return name.ends_with("_bug"); }

// "fx_phong" -> "fx"; the corpus names cases <style>_<name>.
std::string style_of(const std::string& case_name) { return case_name.substr(0, case_name.find('_')); }

TEST(RealWorldCorpus, ExpectationsNameExactlyThePlantedBugCases) {
  auto known = load_expectations((kRealWorld / "planted_bugs.toml").string());
  ASSERT_TRUE(known) << known.error().to_string();
  std::set<std::string> listed;
  for (const KnownFailure& k : *known) {
    EXPECT_FALSE(k.reason.empty()) << k.pattern;
    listed.insert(k.pattern.substr(0, k.pattern.find('/')));
  }
  auto files = list_case_files((kRealWorld / "cases").string());
  ASSERT_TRUE(files) << files.error().to_string();
  std::set<std::string> bugs;
  for (const std::string& f : *files)
    if (const std::string name = fs::path(f).stem().string(); is_bug_case(name)) bugs.insert(name);
  EXPECT_EQ(listed, bugs);
}

TEST(RealWorldCorpus, CorrectPortsPassAndPlantedBugsFailOnEveryPath) {
  RunOptions o;
  o.select.cases_dir = (kRealWorld / "cases").string();
  o.expectations = (kRealWorld / "planted_bugs.toml").string();
  o.cell.size = 48;
  o.cell.timing = {.warmup = 0, .runs = 0};
  auto report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  EXPECT_TRUE(report->acceptable());

  struct Counts {
    size_t cells = 0, pass = 0, fail = 0, error = 0, skipped = 0;
    std::map<std::string, size_t> skip_reasons;
  };
  std::map<std::string, Counts> styles;
  for (const CellResult& r : report->results) {
    Counts& c = styles[style_of(r.case_name)];
    ++c.cells;
    if (r.status == CellStatus::pass) ++c.pass;
    else if (r.status == CellStatus::fail) ++c.fail;
    else if (r.status == CellStatus::skipped) ++c.skipped, ++c.skip_reasons[r.backend + "/" + r.path + ": " + r.message];
    else ++c.error;
    if (r.status == CellStatus::skipped) {
      EXPECT_FALSE(r.message.empty()) << r.id();
    } else if (is_bug_case(r.case_name)) {
      EXPECT_EQ(r.status, CellStatus::fail) << r.id() << ": " << r.message;
      EXPECT_TRUE(r.known_failure) << r.id();
      EXPECT_FALSE(r.message.empty()) << r.id();
    } else {
      EXPECT_EQ(r.status, CellStatus::pass) << r.id() << ": " << r.message;
    }
  }
  for (const char* style : {"cg", "fx", "glsl110", "glsl330", "hlsl", "hlsl5"}) EXPECT_TRUE(styles.contains(style)) << style;
  for (const auto& [style, c] : styles) {
    fmt::print("corpus {:8} {:3} cells: {:3} pass, {:3} fail (planted bugs), {} error, {} skipped\n", style, c.cells,
               c.pass, c.fail, c.error, c.skipped);
    for (const auto& [reason, n] : c.skip_reasons) fmt::print("    skipped {}x {}\n", n, reason);
  }
}

}  // namespace
}  // namespace shaderbed
