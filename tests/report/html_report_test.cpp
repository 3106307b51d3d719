// The HTML report, checked structurally and then in a real browser: Debian's headless
// Chromium loads the page, runs its script and dumps the DOM; the test checks the table,
// that every shown image decoded, sorting and the file fallback, and keeps a screenshot
// (build/tests/report/report.png) and the page (build/tests/report/html/) as artefacts.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "HeadlessChromium.h"
#include "ReportTestSupport.h"
#include "report/HtmlReport.h"
#include "report/Markup.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::body_attr;
using test::Chromium;
using test::chromium_path;
using test::count;
using test::file_url;
using test::slurp;

// The cards the page keeps in its JSON store (put into the page when a row is opened).
std::vector<std::string> stored_cards(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"sb-cards\">";
  const size_t start = html.find(open);
  if (start == std::string::npos) return {};
  const size_t body = start + open.size();
  return nlohmann::json::parse(html.substr(body, html.find("</script>", body) - body)).get<std::vector<std::string>>();
}

// The page's markup followed by its stored cards: everything a reader can get to.
std::string page_text(const std::string& html) {
  std::string text = html;
  for (const std::string& card : stored_cards(html)) text += "\n" + card;
  return text;
}

// ---- without a browser ----

TEST(HtmlReport, WritesOneSelfContainedPageAndCopiesSources) {
  const fs::path dir = test::fresh_dir("html");
  const RunReport report = test::sample_report(dir / "out");
  auto summary = write_html(report, (dir / "html").string(), HtmlOptions{});
  ASSERT_TRUE(summary) << summary.error().to_string();
  const std::string html = slurp(dir / "html" / "index.html");
  const std::string text = page_text(html);
  EXPECT_EQ(summary->html_bytes, html.size());
  EXPECT_EQ(count(html, "<tbody class=\"cell "), report.results.size());
  EXPECT_EQ(stored_cards(html).size(), report.results.size()) << "a card per cell, in the store";
  EXPECT_EQ(html.find("<tbody class=\"cell pass\" id=\"c0\" data-i=\"0\" data-id=\"/lambert/pixel/glsl/vulkan/spirv/sphere/\">"),
            html.find("<tbody class=\"cell pass\" id=\"c0\""))
      << "a small table is shown as it is";
  // Nothing from the network: no external scripts, styles or images.
  for (const char* external : {"src=\"http", "href=\"http", "src=\"//", "<link", "@import", "url("})
    EXPECT_EQ(html.find(external), std::string::npos) << external;
  EXPECT_NE(html.find("Content-Security-Policy"), std::string::npos);
  // Distinct PNGs: 2 references (sphere, cone) + renders and error maps of 4 cells.
  EXPECT_EQ(summary->images_embedded, 2u + 4u * 2u);
  EXPECT_EQ(count(html, "data:image/png;base64,"), summary->images_embedded);
  EXPECT_EQ(summary->images_missing, 3u);   // the torus cell's files
  EXPECT_EQ(summary->images_linked, 0u);
  // Sources copied under sources/, mirroring the run's folder, and linked relatively.
  EXPECT_EQ(summary->sources_copied, 3u);
  EXPECT_EQ(slurp(dir / "html/sources/lambert/pixel/glsl.frag.spvasm.txt"), "; SPIR-V\n; Version: 1.0\nOpCapability Shader\n");
  EXPECT_TRUE(fs::exists(dir / "html/sources/lambert/pixel/hlsl.frag.cross.glsl.txt"));
  EXPECT_NE(text.find("href=\"sources/lambert/pixel/glsl.frag.spvasm.txt\""), std::string::npos);
  EXPECT_NE(text.find("vertex GLSL (SPIRV-Cross): missing"), std::string::npos);
  // Text is escaped; the header has the toolchain and totals.
  EXPECT_EQ(text.find("<script>alert"), std::string::npos);
  EXPECT_NE(text.find("&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;quotes&quot; \\x01 control \xef\xbf\xbd byte"),
            std::string::npos);
  for (const char* needle : {"glslang 11:12.0.0", "SPIRV-Tools v2022.4", "spirv-cross 2022.12.01", "Mesa 22.3.6 llvmpipe",
                             "<b>6</b> cells", "<b>2</b> passed", "<b>2</b> failed", "<b>1</b> known failures",
                             "<b>1</b> errors", "known failure</b>: SPIRV-Cross 2022 drops precise",
                             "wall 0.750 [0.688, 1.125], timestamp queries 0.625 [0.500, 0.875]",
                             "vertex 10, fragment 34"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle;
  EXPECT_EQ(html.find("</script", html.find("id=\"sb-cards\"")),
            html.find("</script>\n<script type=\"application/json\" id=\"sb-groups\">", html.find("id=\"sb-cards\"")))
      << "nothing in the card store closes its script element early";
  EXPECT_EQ(html.find("</script", html.find("id=\"sb-groups\"")), html.find("</script>\n<script>\n", html.find("id=\"sb-groups\"")))
      << "nor in the store of cards that several cells share";
  // The same report gives the same page.
  ASSERT_TRUE(write_html(report, (dir / "html2").string()));
  EXPECT_EQ(slurp(dir / "html2" / "index.html"), html);
  fs::remove_all(dir);
}

TEST(HtmlReport, ImageBudgetKeepsFailuresFirst) {
  const fs::path dir = test::fresh_dir("html_budget");
  const RunReport report = test::sample_report(dir / "out", 32);
  // Room for three images: the failing cell's reference, render and error map.
  const size_t one = fs::file_size(report.results[1].artefacts.render_png);
  auto summary = write_html(report, (dir / "html").string(), HtmlOptions{.image_budget = 3 * ((one + 2) / 3 * 4 + 22)});
  ASSERT_TRUE(summary) << summary.error().to_string();
  EXPECT_EQ(summary->images_embedded, 3u);
  EXPECT_EQ(summary->images_linked, 10u - 3u);
  const std::string html = slurp(dir / "html" / "index.html");
  const size_t card = html.find("id=\"f1\"");
  ASSERT_NE(card, std::string::npos);
  const std::string failure = html.substr(card, html.find("</details>\n", card) - card);   // the card, its own <details> inside
  EXPECT_EQ(count(failure, "data-img=\""), 3u) << "reference, render and error of the failure are embedded";
  EXPECT_GE(count(failure, "data-file=\""), 2u) << "the other renders are linked";
  fs::remove_all(dir);
}

TEST(HtmlReport, OpensWithTheSummaryMatrixLinkedToTheTable) {
  const fs::path dir = test::fresh_dir("html_matrix");
  const RunReport report = test::sample_report(dir / "out");
  ASSERT_TRUE(write_html(report, (dir / "html").string()));
  const std::string html = slurp(dir / "html" / "index.html");
  const size_t matrix = html.find("<section id=\"matrix\">");
  ASSERT_NE(matrix, std::string::npos);
  EXPECT_LT(html.find("Mesa 22.3.6 llvmpipe"), matrix) << "after the toolchain and totals";
  EXPECT_LT(matrix, html.find("id=\"sec-fail\"")) << "before the failures";
  EXPECT_NE(html.find("<a href=\"#matrix\">summary</a>"), std::string::npos);
  const std::string m = html.substr(matrix, html.find("</section>", matrix) - matrix);
  // Columns only where cells exist, headed by language, backend and path.
  EXPECT_NE(m.find("<th>hlsl</th><th>cg</th><th colspan=\"3\">glsl</th>"), std::string::npos) << m;
  // Each count links to its cells (the table's data-id prefixes), with what it counts.
  EXPECT_NE(m.find("<td class=\"mx fail\"><a class=\"mxl\" href=\"#filter=/lambert/pixel/glsl/vulkan/spirv/&amp;status=\" "
                   "title=\"lambert pixel glsl vulkan/spirv: 1 of 2 passed, 1 failed\">1/2!</a></td>"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find(">0/1*</a>"), std::string::npos) << m;
  EXPECT_NE(m.find("<td class=\"mx error\">"), std::string::npos) << m;
  EXPECT_NE(m.find("href=\"#filter=/phong%3C%26%3E%22%27/pixel/glsl/gl/spirv/&amp;status=\""), std::string::npos)
      << "names are percent-encoded in the link\n" << m;
  EXPECT_NE(m.find("href=\"#filter=/lambert/pixel/&amp;status=\""), std::string::npos) << "the row's own link";
  EXPECT_NE(m.find("<td class=\"n\">nan</td><td class=\"n\">nan</td></tr>"), std::string::npos)
      << "the worst error of lambert/pixel, and its share of the threshold";
  EXPECT_NE(m.find("<td class=\"n\">1.00e-05</td><td class=\"n\">&lt;1%</td></tr>"), std::string::npos) << m;
  for (const CellResult& r : report.results)
    EXPECT_NE(html.find("data-id=\"" + markup::escape("/" + r.id() + "/", true) + "\""), std::string::npos) << r.id();
  fs::remove_all(dir);
}

TEST(HtmlReport, ManyCellsEmbedFailuresAndExamplesAndLinkTheRest) {
  // 960 cells (8 cases x 3 variants x 10 columns x 4 shapes): embedding every PNG would make
  // a page of ~9 MB of images alone.
  const fs::path dir = test::fresh_dir("html_many");
  const RunReport report = test::many_cell_report(dir / "out", 8);
  ASSERT_EQ(report.results.size(), 960u);
  const HtmlOptions defaults;
  auto summary = write_html(report, (dir / "out").string(), defaults);   // next to the images, as scripts/demo does
  ASSERT_TRUE(summary) << summary.error().to_string();
  const std::string html = slurp(dir / "out" / "index.html");
  EXPECT_LE(summary->image_bytes, defaults.image_budget);
  EXPECT_GT(summary->images_linked, 1500u);
  EXPECT_EQ(summary->images_missing, 0u);
  // The size bound: the markup (the table, and every card in the store) and the budget.
  EXPECT_LT(summary->html_bytes, size_t(6) << 20) << "a default-suite-sized page stays small enough to open at once";
  EXPECT_LE(summary->html_bytes, defaults.max_page_bytes);
  std::cout << "[ report   ] " << report.results.size() << " cells: index.html " << summary->html_bytes << " bytes, "
            << summary->images_embedded << " images embedded (" << summary->image_bytes << " bytes), "
            << summary->images_linked << " linked\n";

  // The failing cell's images are embedded; so are one passing example's per case/variant.
  const std::vector<std::string> cards = stored_cards(html);
  ASSERT_EQ(cards.size(), report.results.size());
  EXPECT_EQ(count(cards[0], "data-img=\""), 3u + 9u) << "its own, and the other renders of its shape\n" << cards[0];
  EXPECT_EQ(count(cards[1], "data-img=\""), 3u) << "the first passing cell of case0/pixel is its example\n" << cards[1];
  // Another passing cell's render and error map come from the run's files, by relative path.
  const size_t last = report.results.size() - 1;
  const CellResult& plain = report.results[last];
  EXPECT_EQ(plain.status, CellStatus::pass);
  const std::string stem = plain.case_name + "/" + plain.variant + "/" + plain.shape + "/" + plain.language + "-" +
                           plain.backend + "-" + plain.path;
  EXPECT_NE(cards[last].find("data-file=\"" + stem + ".png\""), std::string::npos) << cards[last];
  EXPECT_NE(cards[last].find("data-file=\"" + stem + ".error.png\""), std::string::npos) << cards[last];
  // A big table starts with its rows hidden, so the page is quick to lay out.
  EXPECT_EQ(count(html, "<tbody class=\"cell "), report.results.size());
  EXPECT_EQ(count(html, "\" hidden><tr class=\"row\""), report.results.size());
  EXPECT_NE(html.find("<p id=\"collapsed\">960 cells: click a count in the summary"), std::string::npos);
  fs::remove_all(dir);
}

TEST(HtmlReport, ChartsAreInlinedBeforeTheFailures) {
  const fs::path dir = test::fresh_dir("html_chart");
  const RunReport report = test::sample_report(dir / "out");
  HtmlOptions options;
  options.charts.push_back({"oren_nayar", "<svg viewBox=\"0 0 10 10\"><circle r=\"1\"/></svg>", "time <against> error"});
  ASSERT_TRUE(write_html(report, (dir / "html").string(), options));
  const std::string html = slurp(dir / "html" / "index.html");
  const size_t chart = html.find("<svg viewBox=\"0 0 10 10\"><circle r=\"1\"/></svg>");
  ASSERT_NE(chart, std::string::npos);
  EXPECT_LT(chart, html.find("id=\"sec-fail\""));
  EXPECT_NE(html.find("time &lt;against&gt; error"), std::string::npos);
  EXPECT_NE(html.find("href=\"#charts\""), std::string::npos);
  fs::remove_all(dir);
}

TEST(HtmlReport, UnwritableFolderIsAnError) {
  auto r = write_html(RunReport{}, "/proc/shaderbed-report");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().file, "/proc/shaderbed-report");
}

// ---- in Chromium ----

class HtmlInChromium : public ::testing::Test {
 protected:
  void SetUp() override {
    // Not a skip: the report is only known to work if a real browser shows it.
    ASSERT_TRUE(fs::exists(chromium_path()))
        << chromium_path()
        << " is missing: run scripts/install-deps (it installs Debian's 'chromium' package) to test the HTML report "
           "in a real browser";
  }
};

TEST_F(HtmlInChromium, TableImagesSortingAndScreenshot) {
  const fs::path keep = test::artefact_dir();
  const fs::path run = keep / "run", html = keep / "html";
  fs::remove_all(run);
  fs::remove_all(html);
  const RunReport report = test::sample_report(run, 96);
  auto summary = write_html(report, html.string(), HtmlOptions{});
  ASSERT_TRUE(summary) << summary.error().to_string();
  const fs::path index = html / "index.html";
  Chromium chromium;

  // As opened: the failure cards' images are set from the page's store and decode.
  const std::string dom = chromium.dump_dom(file_url(index), "default");
  ASSERT_NE(dom.find("<table id=\"cells\""), std::string::npos) << chromium.last_command() << "\n" << dom.substr(0, 2000);
  EXPECT_EQ(count(dom, "<tbody class=\"cell "), report.results.size());
  EXPECT_EQ(body_attr(dom, "data-cells"), std::to_string(report.results.size()));
  EXPECT_EQ(body_attr(dom, "data-images-ready"), "all") << chromium.last_command();
  // Failure card: reference, render, error + the two other renders of lambert/pixel/sphere.
  EXPECT_EQ(body_attr(dom, "data-images-total"), "5");
  EXPECT_EQ(body_attr(dom, "data-images-decoded"), "5");
  EXPECT_EQ(count(dom, "src=\"data:image/png;base64,"), 5u);
  EXPECT_NE(dom.find("<span id=\"shown\">6 of 6 shown</span>"), std::string::npos);
  EXPECT_NE(dom.find("gone.png"), std::string::npos) << "a missing image is shown as missing";
  EXPECT_EQ(dom.find("<script>alert"), std::string::npos);

  // Every row opened and sorted by max error, largest first (NaN counts as largest, errors last).
  const std::string all = chromium.dump_dom(file_url(index, "expand-all&sort=max_abs:desc"), "expanded");
  EXPECT_EQ(body_attr(all, "data-sorted"), "max_abs:desc");
  EXPECT_EQ(body_attr(all, "data-images-ready"), "all");
  const std::string total = body_attr(all, "data-images-total");
  EXPECT_EQ(body_attr(all, "data-images-decoded"), total);
  EXPECT_GE(std::atoi(total.c_str()), 5 + 3 * 4) << "every card with images shows them";
  std::vector<std::string> order;
  const std::regex row("<tbody class=\"cell [a-z]+\" id=\"(c[0-9]+)\"");
  for (std::sregex_iterator it(all.begin(), all.end(), row), end; it != end; ++it)
    order.push_back((*it)[1]);
  EXPECT_EQ(order, (std::vector<std::string>{"c4", "c1", "c2", "c0", "c5", "c3"}));
  EXPECT_EQ(count(all, "<tr class=\"detail\">"), report.results.size()) << "no detail row left hidden";

  // Filtering from the URL.
  const std::string failing = chromium.dump_dom(file_url(index, "status=failing"), "failing");
  EXPECT_NE(failing.find("<span id=\"shown\">4 of 6 shown</span>"), std::string::npos);

  // Over the image budget, images come from the run's files by relative path.
  const fs::path linked = keep / "html-linked";
  fs::remove_all(linked);
  auto small = write_html(report, linked.string(), HtmlOptions{.image_budget = 0});
  ASSERT_TRUE(small) << small.error().to_string();
  EXPECT_EQ(small->images_embedded, 0u);
  const std::string files = chromium.dump_dom(file_url(linked / "index.html", "expand-all"), "linked");
  EXPECT_EQ(count(files, "data:image/png"), 0u);
  EXPECT_EQ(body_attr(files, "data-images-ready"), "all");
  EXPECT_EQ(body_attr(files, "data-images-decoded"), total) << "the same images, from files";

  // The screenshot, kept for people and CI artefact upload.
  const fs::path shot = keep / "report.png";
  ASSERT_TRUE(chromium.screenshot(file_url(index), shot)) << chromium.last_command();
  const std::string png = slurp(shot);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_GT(png.size(), 10000u) << "a rendered page, not a blank one";
  std::cout << "[ report   ] screenshot: " << shot.string() << "\n[ report   ] page: " << index.string() << "\n";
}

TEST_F(HtmlInChromium, MatrixLinksShowRowsOfABigTable) {
  const fs::path dir = test::fresh_dir("html_many_chromium");
  const RunReport report = test::many_cell_report(dir / "out", 4);
  ASSERT_TRUE(write_html(report, (dir / "out").string()));
  const fs::path index = dir / "out" / "index.html";
  Chromium chromium;

  const std::string opened = chromium.dump_dom(file_url(index), "big");
  EXPECT_NE(opened.find("<span id=\"shown\">0 of 480 shown</span>"), std::string::npos) << chromium.last_command();
  EXPECT_NE(opened.find("<section id=\"matrix\">"), std::string::npos);
  EXPECT_EQ(body_attr(opened, "data-images-ready"), "all") << "the open failure card's images";

  // What a matrix count links to: that case/variant/column's shapes.
  const std::string cell = chromium.dump_dom(file_url(index, "filter=/case2/vertex/cg/gl/cross/&status="), "big-cell");
  EXPECT_NE(cell.find("<span id=\"shown\">4 of 480 shown</span>"), std::string::npos);
  EXPECT_NE(cell.find("<p id=\"collapsed\" hidden=\"\">"), std::string::npos);

  // An opened row gets its card from the store, and its linked images load from the run's files.
  const std::string row = chromium.dump_dom(file_url(index, "filter=/case3/pixel_lut/glsl/gl/glsl/torus/&expand-all"), "big-row");
  EXPECT_NE(row.find("<span id=\"shown\">1 of 480 shown</span>"), std::string::npos);
  EXPECT_EQ(count(row, "<tr class=\"detail\">"), 1u);
  EXPECT_NE(row.find("<code>case3/pixel_lut/glsl/gl/glsl/torus</code>"), std::string::npos);
  EXPECT_EQ(body_attr(row, "data-images-ready"), "all");
  EXPECT_EQ(body_attr(row, "data-images-total"), std::to_string(3 + 3 + 9)) << "the failure card's and this row's";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace shaderbed
