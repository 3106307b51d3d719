// A failing cell's convention fits and what it was judged against reach every report: the
// console and JUnit carry the best fitting explanation in the failure, the HTML card the
// whole table of fits with their residuals (the JSON's are in json_report_test).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "ReportTestSupport.h"
#include "report/ConsoleReport.h"
#include "report/HtmlReport.h"
#include "report/JunitReport.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

RunReport explained_failure() {
  RunReport report;
  CellResult r;
  r.case_name = "tinted_diffuse";
  r.variant = "factor_pi";
  r.language = "glsl";
  r.backend = "vulkan";
  r.path = "spirv";
  r.shape = "sphere";
  r.status = CellStatus::fail;
  r.message = "666 interior pixels over 1e-05 + 0.000122|ref| (max 0.604)";
  r.attribution = "port";
  r.interior_threshold = 1e-5;
  r.interior_threshold_rel = 0x1p-13;
  r.tolerance_reason = "differential default: two fp32 renders";
  r.reference = {"render", "hlsl vulkan/spirv (variant original)", false, ""};
  r.explanations = {{"gamma_encoded_render", "encoded", 0.28, 0.1, 816, false, "encoded with gamma 2.2 fits only to 0.28 (incomplete)"},
                    {"constant_factor", "× 1/π", 7.2e-8, 3e-8, 816, true,
                     "matches the reference × 1/π (1/π normalisation in the render only) to 7.2e-8"}};
  report.results.push_back(r);
  return report;
}

std::string explained(const RunReport& report) {
  std::FILE* out = std::tmpfile();
  print_console_report(report, out, {});
  std::string s(size_t(std::ftell(out)), '\0');
  std::rewind(out);
  s.resize(std::fread(s.data(), 1, s.size(), out));
  std::fclose(out);
  return s;
}

TEST(ExplanationReports, ConsoleNamesTheFittingConventionAndTheOriginal) {
  const std::string text = explained(explained_failure());
  EXPECT_NE(text.find("      explained: matches the reference × 1/π (1/π normalisation in the render only) to 7.2e-8"),
            std::string::npos) << text;
  EXPECT_NE(text.find("      judged against: the original, hlsl vulkan/spirv (variant original)"), std::string::npos) << text;
}

TEST(ExplanationReports, ConsoleShowsTheClosestWhenNoneFits) {
  RunReport report = explained_failure();
  report.results[0].explanations.pop_back();
  const std::string text = explained(report);
  EXPECT_NE(text.find("no convention explains it; closest: encoded with gamma 2.2 fits only to 0.28 (incomplete)"),
            std::string::npos) << text;
}

TEST(ExplanationReports, JunitFailureMessageCarriesTheBestExplanation) {
  const std::string xml = to_junit(explained_failure());
  EXPECT_NE(xml.find("message=\"666 interior pixels over 1e-05 + 0.000122|ref| (max 0.604); explained: matches the "
                     "reference × 1/π"),
            std::string::npos) << xml;
  EXPECT_NE(xml.find("threshold 1e-05 + 0.000122|ref|"), std::string::npos) << xml;
  EXPECT_NE(xml.find("convention fits: matches the reference × 1/π"), std::string::npos) << xml;
  EXPECT_NE(xml.find("tolerance: differential default"), std::string::npos) << xml;
}

TEST(ExplanationReports, HtmlCardHasTheFitsTableAndTheOriginalsCaption) {
  const fs::path dir = test::fresh_dir("explanation_html");
  ASSERT_TRUE(write_html(explained_failure(), dir.string()));
  std::ifstream in(dir / "index.html");
  std::stringstream html;
  html << in.rdbuf();
  const std::string page = html.str();
  for (const char* needle : {"<th>convention</th>", "matches the reference × 1/π (1/π normalisation in the render only)",
                             "judged against", "the original, hlsl vulkan/spirv (variant original)",
                             "differential default: two fp32 renders"})
    EXPECT_NE(page.find(needle), std::string::npos) << needle;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace shaderbed
