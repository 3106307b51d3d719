// The mutant corpus (tests/mutants/): deliberately broken versions of library shaders.
// Every mutant must be caught on the cells tests/mutants/expectations.toml names, and for
// the reason it names (an error, NaNs, a blank image); the library shaders that share its
// case must still pass; every failure must carry the attribution the manifest expects;
// and the library cases the mutants derive from must still pass at the same image size.
//
// One test per mutant (MutantCorpus/MutantCase.IsCaughtAndAttributed/<case>), so ctest can run
// them in parallel and a report names the mutant. 96x96 keeps the corpus quick: the
// mutants are gross or, for the precision one, still 50x over the tolerance.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "SourceTree.h"
#include "run/Runner.h"
#include "scene/CaseFile.h"
#include "scene/Primitives.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using shaderbed::test::kSource;
const fs::path kMutants = kSource / "tests" / "mutants";
const fs::path kMutantCases = kMutants / "cases";
const fs::path kManifest = kMutants / "expectations.toml";
constexpr int kSize = 96;

const std::set<std::string> kAttributions{"front end", "cross-compiler", "driver", "model/reference", "unclear"};
const std::set<std::string> kEvidence{"error", "nonfinite", "blank"};

struct Mutant {
  std::string name;           // case file stem in tests/mutants/cases
  std::string derived_from;   // library case in shaders/cases
  std::string breaks;
  std::vector<std::string> shapes;
  std::vector<std::string> fail;   // language/backend/path patterns
  std::string evidence;
  double min_error = 0;
  std::string attribution;
  std::string reason;
};

// For gtest's parameter printing.
void PrintTo(const Mutant& m, std::ostream* os) { *os << m.name; }

struct Manifest {
  std::vector<Mutant> mutants;
  std::vector<std::string> problems;   // what is wrong with the file, one line each
};

std::vector<std::string> strings(const toml::node_view<const toml::node>& node) {
  std::vector<std::string> out;
  if (const toml::array* a = node.as_array())
    for (const toml::node& e : *a)
      if (auto s = e.value<std::string>()) out.push_back(*s);
  return out;
}

Manifest load_manifest() {
  Manifest m;
  toml::table root;
  try {
    root = toml::parse_file(kManifest.string());
  } catch (const toml::parse_error& e) {
    m.problems.push_back(fmt::format("{}:{}: {}", kManifest.string(), e.source().begin.line, e.description()));
    return m;
  }
  const toml::array* entries = root["mutant"].as_array();
  if (!entries) {
    m.problems.push_back(kManifest.string() + ": no [[mutant]] entries");
    return m;
  }
  for (const toml::node& node : *entries) {
    const toml::table* t = node.as_table();
    if (!t) continue;
    auto e = [t](const char* key) { return (*t)[key]; };
    Mutant mu;
    mu.name = e("case").value_or(std::string{});
    mu.derived_from = e("derived_from").value_or(std::string{});
    mu.breaks = e("breaks").value_or(std::string{});
    mu.shapes = strings(e("shapes"));
    mu.fail = strings(e("fail"));
    mu.evidence = e("evidence").value_or(std::string{});
    mu.min_error = e("min_error").value_or(0.0);
    mu.attribution = e("attribution").value_or(std::string{});
    mu.reason = e("reason").value_or(std::string{});
    const std::string where = fmt::format("{}:{}: mutant '{}'", kManifest.string(), t->source().begin.line, mu.name);
    if (mu.name.empty() || mu.derived_from.empty() || mu.breaks.empty() || mu.reason.empty())
      m.problems.push_back(where + ": case, derived_from, breaks and reason are required");
    if (mu.shapes.empty() || mu.fail.empty()) m.problems.push_back(where + ": shapes and fail must list something");
    if (!kEvidence.contains(mu.evidence)) m.problems.push_back(where + ": evidence must be error, nonfinite or blank");
    if (mu.evidence == "error" && !(mu.min_error > 0)) m.problems.push_back(where + ": evidence \"error\" needs min_error > 0");
    if (!kAttributions.contains(mu.attribution)) m.problems.push_back(where + ": unknown attribution '" + mu.attribution + "'");
    for (const std::string& s : mu.shapes)
      if (std::ranges::find(shape_names(), s) == shape_names().end()) m.problems.push_back(where + ": unknown shape " + s);
    for (const std::string& p : mu.fail)
      if (std::ranges::count(p, '/') != 2) m.problems.push_back(where + ": fail pattern '" + p + "' is not language/backend/path");
    m.mutants.push_back(std::move(mu));
  }
  return m;
}

const Manifest& manifest() {
  static const Manifest m = load_manifest();
  return m;
}

// "glsl/*/*" against a cell: each of language, backend and path is a name or "*".
bool matches(const std::string& pattern, const CellResult& r) {
  std::vector<std::string> parts;
  std::stringstream in(pattern);
  for (std::string part; std::getline(in, part, '/');) parts.push_back(part);
  if (parts.size() != 3) return false;
  const std::string cell[3] = {r.language, r.backend, r.path};
  for (int i = 0; i < 3; ++i)
    if (parts[i] != "*" && parts[i] != cell[i]) return false;
  return true;
}

bool expected_to_fail(const Mutant& m, const CellResult& r) {
  return std::ranges::any_of(m.fail, [&](const std::string& p) { return matches(p, r); });
}

std::string cell_name(const CellResult& r) {
  return fmt::format("{}/{}/{} {} {}", r.language, r.backend, r.path, r.variant, r.shape);
}

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// ---- the manifest and the case files agree ------------------------------------------

TEST(MutantCorpus, ManifestDescribesEveryMutantCase) {
  const Manifest& m = manifest();
  for (const std::string& p : m.problems) ADD_FAILURE() << p;
  EXPECT_GE(m.mutants.size(), 12u) << "the issue asks for at least twelve mutants";

  std::set<std::string> listed;
  for (const Mutant& mu : m.mutants) EXPECT_TRUE(listed.insert(mu.name).second) << mu.name << " is listed twice";
  auto files = list_case_files(kMutantCases.string());
  ASSERT_TRUE(files) << files.error().to_string();
  std::set<std::string> on_disk;
  for (const std::string& f : *files) on_disk.insert(fs::path(f).stem().string());
  for (const std::string& name : on_disk)
    EXPECT_TRUE(listed.contains(name)) << "tests/mutants/cases/" << name << ".toml has no entry in " << kManifest;
  for (const std::string& name : listed)
    EXPECT_TRUE(on_disk.contains(name)) << kManifest << " lists " << name << ", which has no case file";

  std::set<std::string> attributions;
  for (const Mutant& mu : m.mutants) {
    if (!on_disk.contains(mu.name)) continue;
    attributions.insert(mu.attribution);
    const fs::path file = kMutantCases / (mu.name + ".toml");
    // The first line says what is broken and which attribution is expected.
    const std::string line = first_line(file);
    EXPECT_TRUE(line.starts_with("# MUTANT of " + mu.derived_from + ".toml")) << file << ": " << line;
    EXPECT_NE(line.find("Expected attribution: " + mu.attribution), std::string::npos)
        << file << " line 1 should say \"Expected attribution: " << mu.attribution << "\"";
    // A mutant is one variant of a library case, with the same model and all three
    // languages (the unbroken ones are what attribution compares against).
    auto mutant = load_case(file.string());
    ASSERT_TRUE(mutant) << mutant.error().to_string();
    auto library = load_case((kSource / "shaders" / "cases" / (mu.derived_from + ".toml")).string());
    ASSERT_TRUE(library) << mu.name << ": derived_from " << mu.derived_from << ": " << library.error().to_string();
    EXPECT_EQ(mutant->model, library->model) << mu.name;
    ASSERT_EQ(mutant->variants.size(), 1u) << mu.name << ": one variant per mutant";
    const Variant& v = mutant->variants.front();
    EXPECT_TRUE(std::ranges::any_of(library->variants, [&](const Variant& lv) { return lv.name == v.name; }))
        << mu.name << ": variant " << v.name << " is not one of " << mu.derived_from << "'s";
    EXPECT_EQ(v.shaders.size(), 3u) << mu.name << ": keep HLSL, GLSL and Cg in every mutant case";
  }
  // The corpus exercises more than one verdict: single-language bugs, bugs shared by every
  // port, and a backend that disagrees with the other.
  for (const char* a : {"front end", "model/reference", "driver"})
    EXPECT_TRUE(attributions.contains(a)) << "no mutant expects the attribution \"" << a << "\"";
}

// ---- every mutant is caught, for the right reason, with the right attribution -------

class MutantCase : public ::testing::TestWithParam<Mutant> {};

TEST_P(MutantCase, IsCaughtAndAttributed) {
  const Mutant& m = GetParam();
  RunOptions o;
  o.select.cases_dir = kMutantCases.string();
  o.select.cases = {m.name};
  o.select.shapes = m.shapes;
  o.cell.size = kSize;
  auto report = run_suite(o);
  ASSERT_TRUE(report) << report.error().to_string();
  ASSERT_FALSE(report->results.empty());

  std::set<std::string> languages, backends, caught_shapes;
  std::map<std::string, std::vector<std::string>> verdicts;   // attribution -> failing cells
  size_t expected = 0, caught = 0;
  double largest = 0, smallest = INFINITY;
  for (const CellResult& r : report->results) {
    const std::string cell = cell_name(r);
    languages.insert(r.language);
    backends.insert(r.backend);
    if (r.status == CellStatus::error) {
      ADD_FAILURE() << m.name << " " << cell << " could not be drawn: " << r.message;
      continue;
    }
    if (!expected_to_fail(m, r)) {
      // The library's unbroken shaders in the same case: untouched by the mutant.
      EXPECT_EQ(r.status, CellStatus::pass) << m.name << " " << cell << ": this cell runs an unbroken shader (or a backend "
                                  << "the mutant should not affect) and must pass: " << r.message;
      continue;
    }
    ++expected;
    if (r.status != CellStatus::fail) {
      ADD_FAILURE() << "NOT CAUGHT: " << m.name << " (" << m.breaks << ") passes on " << cell << ", max error "
                    << r.metrics.max_abs << " against the tolerance " << r.interior_threshold;
      continue;
    }
    ++caught;
    caught_shapes.insert(r.shape);
    largest = std::max(largest, r.metrics.max_abs);
    smallest = std::min(smallest, r.metrics.max_abs);
    // Caught for the reason the mutant plants, not by accident.
    if (m.evidence == "error") {
      EXPECT_GE(r.metrics.max_abs, m.min_error)
          << m.name << " " << cell << " fails (" << r.message << ") but with a smaller error than the manifest's floor";
      EXPECT_GE(m.min_error, 10 * r.interior_threshold)
          << m.name << ": min_error must stay far above the tolerance " << r.interior_threshold
          << ", or a marginal catch would count";
    } else if (m.evidence == "nonfinite") {
      EXPECT_GT(r.metrics.nonfinite, 0u) << m.name << " " << cell << " should fail on NaN/Inf pixels: " << r.message;
    } else if (m.evidence == "blank") {
      EXPECT_GT(r.metrics.interior_pixels, 0u);
      EXPECT_GE(r.metrics.coverage_mismatch, r.metrics.interior_pixels)
          << m.name << " " << cell << " should draw none of the reference's interior: " << r.message;
      EXPECT_GT(r.metrics.reference_covered_pixels, 0u);
      EXPECT_EQ(r.metrics.covered_pixels, 0u) << m.name << " " << cell << " should draw nothing: " << r.message;
    }
    verdicts[r.attribution].push_back(cell);
  }
  EXPECT_EQ(languages, (std::set<std::string>{"cg", "glsl", "hlsl"})) << m.name;
  EXPECT_EQ(backends, (std::set<std::string>{"gl", "vulkan"})) << m.name;
  EXPECT_GT(expected, 0u) << m.name << ": the fail patterns match no cell";
  EXPECT_EQ(caught_shapes, std::set<std::string>(m.shapes.begin(), m.shapes.end()))
      << m.name << ": not caught on every listed shape";

  // Attribution: every failing cell gets the manifest's verdict.
  if (verdicts.size() == 1 && verdicts.begin()->first.empty()) {
    ADD_FAILURE() << "ATTRIBUTION MISSING: " << m.name << ": the runner left CellResult::attribution empty on all "
                  << caught << " failing cells; expected \"" << m.attribution << "\" (" << m.reason
                  << ") (compare/Attribution.h).";
  } else {
    for (const auto& [verdict, cells] : verdicts)
      if (verdict != m.attribution) {
        std::string list;
        for (const std::string& c : cells) list += "\n    " + c;
        ADD_FAILURE() << "WRONG ATTRIBUTION: " << m.name << ": " << cells.size() << " failing cells attributed to \""
                      << (verdict.empty() ? "(none)" : verdict) << "\", expected \"" << m.attribution << "\" (" << m.reason << "):" << list;
      }
  }

  std::printf("[ mutant   ] %-30s %zu/%zu expected cells caught on %s, max error %.3g..%.3g, attribution %s\n",
              m.name.c_str(), caught, expected, fmt::format("{}", fmt::join(m.shapes, ",")).c_str(),
              std::isfinite(smallest) ? smallest : 0.0, largest, m.attribution.c_str());
}

INSTANTIATE_TEST_SUITE_P(MutantCorpus, MutantCase, ::testing::ValuesIn(manifest().mutants),
                         [](const ::testing::TestParamInfo<Mutant>& info) { return info.param.name; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(MutantCase);   // a broken manifest is reported above

// ---- the shaders the mutants break still pass, at the same size ---------------------

TEST(MutantCorpus, LibraryShadersTheMutantsDeriveFromPass) {
  // Each library case and variant a mutant breaks, on the shapes that mutant is tested on.
  std::map<std::pair<std::string, std::string>, std::set<std::string>> runs;
  for (const Mutant& m : manifest().mutants) {
    auto mutant = load_case((kMutantCases / (m.name + ".toml")).string());
    ASSERT_TRUE(mutant) << mutant.error().to_string();
    for (const Variant& v : mutant->variants) runs[{m.derived_from, v.name}].insert(m.shapes.begin(), m.shapes.end());
  }
  ASSERT_FALSE(runs.empty());
  for (const auto& [case_variant, shapes] : runs) {
    RunOptions o;
    o.select.cases_dir = (kSource / "shaders" / "cases").string();
    o.select.cases = {case_variant.first};
    o.select.variants = {case_variant.second};
    o.select.shapes.assign(shapes.begin(), shapes.end());
    o.cell.size = kSize;
    auto report = run_suite(o);
    ASSERT_TRUE(report) << case_variant.first << "/" << case_variant.second << ": " << report.error().to_string();
    EXPECT_EQ(report->results.size(), shapes.size() * 10) << "HLSL, GLSL and Cg on every backend and path";
    for (const CellResult& r : report->results)
      EXPECT_EQ(r.status, CellStatus::pass) << "library " << r.case_name << " " << cell_name(r) << " at " << kSize << "x" << kSize
                                  << ": " << r.message;
  }
}

}  // namespace
}  // namespace shaderbed
