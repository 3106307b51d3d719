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

#include "ReportTestSupport.h"
#include "report/HtmlReport.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

// Debian's package; SHADERBED_CHROMIUM overrides (e.g. to check the missing-browser message).
std::string chromium_path() {
  const char* env = std::getenv("SHADERBED_CHROMIUM");
  return env && *env ? env : "/usr/bin/chromium";
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

size_t count(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
  return n;
}

// The attribute of <body> in a dumped DOM ("" when absent).
std::string body_attr(const std::string& dom, const std::string& name) {
  const size_t start = dom.find("<body");
  if (start == std::string::npos) return "";
  const std::string tag = dom.substr(start, dom.find('>', start) - start);
  std::smatch m;
  return std::regex_search(tag, m, std::regex(name + "=\"([^\"]*)\"")) ? m[1].str() : "";
}

// file:// URL of a local path (percent-encoding what a URL cannot hold raw).
std::string file_url(const fs::path& path, const std::string& fragment = "") {
  std::string out = "file://";
  for (unsigned char c : fs::absolute(path).string()) {
    if (std::isalnum(c) || std::string("/-_.~").find(char(c)) != std::string::npos) out += char(c);
    else {
      static const char* hex = "0123456789ABCDEF";
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return fragment.empty() ? out : out + "#" + fragment;
}

class Chromium {
 public:
  Chromium() : work_(test::fresh_dir("chromium")) {}
  ~Chromium() { fs::remove_all(work_); }

  // The flags that make headless Chromium quiet, offline and root-safe, with a fresh profile.
  std::string base(const std::string& name) const {
    const fs::path profile = work_ / ("profile-" + name);
    fs::create_directories(profile);
    return "timeout 120 " + quote(chromium_path()) +
           " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking"
           " --disable-component-update --disable-sync --disable-dev-shm-usage --hide-scrollbars"
           " --user-data-dir=" + quote(profile.string());
  }

  // The DOM after the page's script ran (virtual time lets timers and image decoding settle).
  std::string dump_dom(const std::string& url, const std::string& name) {
    const fs::path dom = work_ / (name + ".html"), log = work_ / (name + ".log");
    last_command_ = base(name) + " --virtual-time-budget=10000 --dump-dom " + quote(url);
    const int status = std::system((last_command_ + " > " + quote(dom.string()) + " 2> " + quote(log.string())).c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << last_command_ << "\n" << slurp(log);
    return slurp(dom);
  }

  bool screenshot(const std::string& url, const fs::path& png) {
    fs::remove(png);
    const fs::path log = work_ / "screenshot.log";
    last_command_ = base("shot") + " --virtual-time-budget=10000 --window-size=1280,900 --screenshot=" +
                    quote(png.string()) + " " + quote(url);
    const int status = std::system((last_command_ + " > " + quote(log.string()) + " 2>&1").c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << last_command_ << "\n" << slurp(log);
    return fs::exists(png);
  }

  const std::string& last_command() const { return last_command_; }

 private:
  fs::path work_;
  std::string last_command_;
};

// ---- without a browser ----

TEST(HtmlReport, WritesOneSelfContainedPageAndCopiesSources) {
  const fs::path dir = test::fresh_dir("html");
  const RunReport report = test::sample_report(dir / "out");
  auto summary = write_html(report, (dir / "html").string(), HtmlOptions{});
  ASSERT_TRUE(summary) << summary.error().to_string();
  const std::string html = slurp(dir / "html" / "index.html");
  EXPECT_EQ(summary->html_bytes, html.size());
  EXPECT_EQ(count(html, "<tbody class=\"cell "), report.results.size());
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
  EXPECT_NE(html.find("href=\"sources/lambert/pixel/glsl.frag.spvasm.txt\""), std::string::npos);
  EXPECT_NE(html.find("vertex GLSL (SPIRV-Cross): missing"), std::string::npos);
  // Text is escaped; the header has the toolchain and totals.
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt; &amp; &quot;quotes&quot; \\x01 control \xef\xbf\xbd byte"),
            std::string::npos);
  for (const char* needle : {"glslang 11:12.0.0", "SPIRV-Tools v2022.4", "spirv-cross 2022.12.01", "Mesa 22.3.6 llvmpipe",
                             "<b>6</b> cells", "<b>2</b> passed", "<b>2</b> failed", "<b>1</b> known failures",
                             "<b>1</b> errors", "known failure</b>: SPIRV-Cross 2022 drops precise",
                             "wall 0.750 [0.688, 1.125], timestamp queries 0.625 [0.500, 0.875]",
                             "vertex 10, fragment 34"})
    EXPECT_NE(html.find(needle), std::string::npos) << needle;
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
  const std::string failure = html.substr(card, html.find("</details>", card) - card);
  EXPECT_EQ(count(failure, "data-img=\""), 3u) << "reference, render and error of the failure are embedded";
  EXPECT_GE(count(failure, "data-file=\""), 2u) << "the other renders are linked";
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

}  // namespace
}  // namespace shaderbed
