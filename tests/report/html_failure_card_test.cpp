// A real failure's card in a real browser: `shaderbed run` on a mutant whose HLSL pixel
// shader reads the eye position as its light (tests/mutants/cases/lambert_light_register:
// 12 cells, hlsl x 3 paths x 4 shapes, fail alike), then headless Chromium on its
// index.html with a small script of the test's own after the page's, which works the card
// (clicks, wheel) and writes what it finds into <body data-t-*>. Checked: one card lists
// the 12 cells; its first content is reference | render | error; the why is collapsed with
// the message once; the screenshot's scale bar and error image show the colours the page's
// own data says (no stored picture); flicker swaps the render for the reference; zoom on
// one image transforms all three alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "HeadlessChromium.h"
#include "ReportTestSupport.h"
#include "ShellCommand.h"
#include "SourceTree.h"
#include "imageio/ImageIoModule.h"
#include "report/HtmlReport.h"
#include "report/Markup.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::body_attr;
using test::Chromium;
using test::chromium_path;
using test::file_url;
using test::slurp;

const char* const kWindow = "1280,900";

// An attribute value of a dumped DOM as text.
std::string unescape(std::string s) {
  for (const auto& [entity, text] : {std::pair{"&lt;", "<"}, std::pair{"&gt;", ">"}, std::pair{"&quot;", "\""},
                                     std::pair{"&#39;", "'"}, std::pair{"&nbsp;", "\xc2\xa0"}, std::pair{"&amp;", "&"}})
    for (size_t at = s.find(entity); at != std::string::npos; at = s.find(entity, at + 1)) s.replace(at, std::string(entity).size(), text);
  return s;
}

// One run of the mutant per test process (ctest runs each test in its own).
class HtmlFailureCard : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::fresh_dir("failure_card");
    const fs::path mutant = test::kSource / "tests" / "mutants" / "cases" / "lambert_light_register.toml";
    const auto [status, out] = test::shaderbed_cli("run --case " + test::quote(mutant.string()) +
                                                   " --variant pixel --size 48 --repeat 0 --quiet --json " +
                                                   test::quote((dir_ / "results.json").string()) + " --html " +
                                                   test::quote((dir_ / "html").string()));
    run_status_ = status;
    run_output_ = out;
    if (fs::exists(dir_ / "results.json")) results_ = nlohmann::json::parse(slurp(dir_ / "results.json"));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  void SetUp() override {
    ASSERT_TRUE(fs::exists(chromium_path())) << chromium_path() << " is missing: run scripts/install-deps";
    ASSERT_EQ(run_status_, 1) << "the mutant's cells fail\n" << run_output_;
    ASSERT_TRUE(fs::exists(dir_ / "html" / "index.html")) << run_output_;
    for (size_t i = 0; i < results_["results"].size(); ++i)
      if (results_["results"][i]["status"] == "fail") failing_.push_back(i);
    ASSERT_EQ(failing_.size(), 12u) << "hlsl on vulkan/spirv, gl/spirv, gl/cross, on 4 shapes\n" << run_output_;
  }

  // index.html with `js` run after the page's script, once the page (and its images) loaded.
  static std::string page_with(const std::string& name, const std::string& js) {
    std::string html = slurp(dir_ / "html" / "index.html");
    const std::string script =
        "<script>\nwindow.addEventListener('load', function () { setTimeout(function () {\n"
        "var body = document.body; function rec(k, v) { body.setAttribute('data-t-' + k, String(v)); }\n"
        "var card = document.querySelector('#sec-fail details.fc'), trio = card.querySelector('.trio');\n"
        "function img(role) { return trio.querySelector('figure[data-role=\"' + role + '\"] img'); }\n" +
        js + "\nrec('done', 1);\n}, 0); });\n</script>\n";
    html.insert(html.rfind("</body>"), script);
    const fs::path page = dir_ / "html" / (name + ".html");   // beside index.html: the same relative links
    std::ofstream(page, std::ios::binary) << html;
    return file_url(page);
  }

  static const nlohmann::json& cell(size_t i) { return results_["results"][i]; }

  static inline fs::path dir_;
  static inline int run_status_ = -1;
  static inline std::string run_output_;
  static inline nlohmann::json results_;
  std::vector<size_t> failing_;
};

TEST_F(HtmlFailureCard, CellsFailingTheSameWayAreOneCardWithTheImagesFirst) {
  Chromium chromium;
  const std::string dom = chromium.dump_dom(page_with("structure", R"(
    rec('cards', document.querySelectorAll('#sec-fail details.fc').length);
    rec('count', card.dataset.count);
    rec('listed', Array.prototype.map.call(card.querySelectorAll('.group li a'), function (a) { return a.getAttribute('href'); }).join(' '));
    var content = card.querySelector('.card');
    rec('card-follows-summary', card.children[0].tagName === 'SUMMARY' && card.children[1] === content);
    rec('first', content.firstElementChild.className);
    rec('roles', Array.prototype.map.call(content.firstElementChild.querySelectorAll('figure'), function (f) { return f.dataset.role; }).join(' '));
    rec('decoded', ['reference', 'render', 'error'].filter(function (r) { return img(r) && img(r).naturalWidth > 0; }).length);
    var why = card.querySelector('details.why');
    rec('why-after-images', !!why && !!(trio.compareDocumentPosition(why) & Node.DOCUMENT_POSITION_FOLLOWING));
    rec('why-open', !!why && why.open);
    rec('explanations-in-why', card.querySelectorAll('table.kv th').length > 0 &&
        Array.prototype.every.call(card.querySelectorAll('td'), function (td) { return !/fits only to/.test(td.textContent) || why.contains(td); }));
    var headline = card.querySelector('summary .why').textContent.split(' \u2014 ')[0];
    rec('headline', headline);
    rec('headline-times', card.textContent.split(headline).length - 1);
  )"), "structure", kWindow);
  ASSERT_EQ(body_attr(dom, "data-t-done"), "1") << chromium.last_command();

  // (c) One card for the 12 cells, listing each of them (by its table row).
  EXPECT_EQ(body_attr(dom, "data-t-cards"), "1");
  EXPECT_EQ(body_attr(dom, "data-t-count"), "12");
  std::string expected;
  for (size_t i : failing_) expected += (expected.empty() ? "#c" : " #c") + std::to_string(i);
  EXPECT_EQ(body_attr(dom, "data-t-listed"), expected);
  // (a) Its content starts with the images: reference | render | error, all decoded.
  EXPECT_EQ(body_attr(dom, "data-t-card-follows-summary"), "true");
  EXPECT_EQ(body_attr(dom, "data-t-first"), "trio");
  EXPECT_EQ(body_attr(dom, "data-t-roles"), "reference render error");
  EXPECT_EQ(body_attr(dom, "data-t-decoded"), "3");
  // Why it failed comes after, collapsed, with every convention fit inside it.
  EXPECT_EQ(body_attr(dom, "data-t-why-after-images"), "true");
  EXPECT_EQ(body_attr(dom, "data-t-why-open"), "false");
  EXPECT_EQ(body_attr(dom, "data-t-explanations-in-why"), "true");
  // The message once: the summary's line is the message's, and the card does not repeat it.
  const std::string message = cell(failing_.front())["message"].get<std::string>();
  const std::string headline = unescape(body_attr(dom, "data-t-headline"));
  EXPECT_FALSE(headline.empty());
  EXPECT_EQ(message.substr(0, std::min(headline.size(), message.find('\n'))), headline.substr(0, headline.find("...")));
  EXPECT_EQ(body_attr(dom, "data-t-headline-times"), "1");
}

// Channel-wise distance between a screenshot pixel and a colour.
int pixel_distance(const ImagePixels& shot, int x, int y, const std::array<int, 3>& rgb) {
  int worst = 0;
  for (int c = 0; c < 3; ++c) {
    const float v = shot.values[(size_t(y) * shot.width + x) * shot.channels + c];
    worst = std::max(worst, std::abs(int(std::lround(v * 255)) - rgb[c]));
  }
  return worst;
}

std::vector<std::array<int, 3>> parse_stops(const std::string& text) {
  std::vector<std::array<int, 3>> out;
  std::istringstream in(text);
  for (std::string hex; in >> hex;)
    out.push_back({std::stoi(hex.substr(1, 2), nullptr, 16), std::stoi(hex.substr(3, 2), nullptr, 16),
                   std::stoi(hex.substr(5, 2), nullptr, 16)});
  return out;
}

// The gradient's colour at t in [0, 1] between evenly spaced stops, as CSS interpolates it.
std::array<int, 3> along(const std::vector<std::array<int, 3>>& stops, double t) {
  const double at = t * double(stops.size() - 1);
  const size_t i = std::min(size_t(at), stops.size() - 2);
  const double f = at - double(i);
  std::array<int, 3> c{};
  for (int k = 0; k < 3; ++k) c[k] = int(std::lround(stops[i][k] + (stops[i + 1][k] - stops[i][k]) * f));
  return c;
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  for (double v; in >> v;) out.push_back(v);
  return out;
}

TEST_F(HtmlFailureCard, ScaleBarAndErrorMapShowTheColoursThePageSays) {
  // The card's images pinned to the window's top left, so the screenshot has them where
  // the dumped layout (the same page, window and script) measured them.
  const std::string page = page_with("scale", R"(
    trio.style.cssText = 'position:fixed;left:0;top:0;z-index:1000;background:#fff;padding:10px;margin:0';
    var s = trio.querySelector('.scale'), bar = s.querySelector('.bar').getBoundingClientRect();
    var e = img('error'), r = e.getBoundingClientRect();
    rec('bar', [bar.left, bar.top, bar.width, bar.height].join(' '));
    rec('error', [r.left, r.top, r.width, r.height, e.naturalWidth, e.naturalHeight].join(' '));
    rec('hi', s.querySelector('.hi').textContent);
  )");
  Chromium chromium;
  const std::string dom = chromium.dump_dom(page, "scale", kWindow);
  ASSERT_EQ(body_attr(dom, "data-t-done"), "1") << chromium.last_command();
  const fs::path shot = test::artefact_dir() / "failure-card.png";
  ASSERT_TRUE(chromium.screenshot(page, shot)) << chromium.last_command();
  const auto pixels = read_image_file(shot.string());
  ASSERT_TRUE(pixels) << pixels.error().to_string();

  // The scale's numbers are the run's: its top, the cell's threshold.
  const nlohmann::json& first = cell(failing_.front());
  const nlohmann::json& scale = first["artefacts"]["error_scale"];
  const std::string attrs = dom.substr(dom.find("<div class=\"scale\""), 400);
  EXPECT_NE(attrs.find("data-top=\"" + markup::sci(scale["top"].get<double>()) + "\""), std::string::npos) << attrs;
  EXPECT_NE(attrs.find("data-threshold=\"" + markup::sci(first["tolerance"]["interior"].get<double>()) + "\""),
            std::string::npos)
      << attrs;
  EXPECT_EQ(body_attr(dom, "data-t-hi"), markup::sci(scale["top"].get<double>()));
  EXPECT_EQ(scale["top"].get<double>(), scale["peak"].get<double>()) << "a failure's worst error tops its scale";

  // The bar on screen: the page's stops, left (0) to right (top), as its data-stops lists them.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(attrs, m, std::regex("data-stops=\"([^\"]*)\"")));
  const auto stops = parse_stops(m[1].str());
  ASSERT_EQ(stops.size(), 5u);
  const std::vector<double> bar = numbers(body_attr(dom, "data-t-bar"));
  ASSERT_EQ(bar.size(), 4u);
  const int y = int(bar[1] + bar[3] / 2);
  for (double t : {0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0}) {
    const int x = int(std::clamp(bar[0] + t * bar[2], bar[0] + 1, bar[0] + bar[2] - 2));
    EXPECT_LE(pixel_distance(*pixels, x, y, along(stops, (x + 0.5 - bar[0]) / bar[2])), 4) << "bar at t=" << t << " x=" << x;
  }
  EXPECT_LE(pixel_distance(*pixels, int(bar[0]) + 1, y, stops.front()), 6) << "the bar's left end is 0's colour";
  EXPECT_LE(pixel_distance(*pixels, int(bar[0] + bar[2]) - 2, y, stops.back()), 6) << "the right end, the top's";

  // The error image's worst pixel, where the run recorded it, is the top colour: on screen
  // and in the PNG file.
  const std::vector<double> error = numbers(body_attr(dom, "data-t-error"));
  ASSERT_EQ(error.size(), 6u);
  const int px = scale["peak_x"].get<int>(), py = scale["peak_y"].get<int>();
  const int sx = int(error[0] + (px + 0.5) * error[2] / error[4]), sy = int(error[1] + (py + 0.5) * error[3] / error[5]);
  EXPECT_LE(pixel_distance(*pixels, sx, sy, stops.back()), 2) << "screen pixel " << sx << "," << sy;
  const std::string png = first["artefacts"]["error_png"].get<std::string>();
  const auto file = read_image_file(fs::path(png).is_absolute() ? png : (dir_ / "html" / png).string());
  ASSERT_TRUE(file) << file.error().to_string();
  EXPECT_EQ(pixel_distance(*file, px, py, stops.back()), 0);
  std::cout << "[ report   ] failure card screenshot: " << shot.string() << "\n";
}

TEST_F(HtmlFailureCard, FlickerSwapsTheRenderAndZoomMovesAllThreeImages) {
  Chromium chromium;
  const std::string dom = chromium.dump_dom(page_with("interact", R"(
    var ref = img('reference'), ren = img('render'), err = img('error'), own = ren.getAttribute('src');
    function transforms() { return [ref.style.transform, ren.style.transform, err.style.transform].join('|'); }
    rec('distinct', own !== ref.getAttribute('src'));
    trio.querySelector('button.flicker').click();
    rec('flicker1', (ren.getAttribute('src') === ref.getAttribute('src')) + ' ' + trio.dataset.showing);
    trio.querySelector('button.flicker').click();
    rec('flicker2', (ren.getAttribute('src') === own) + ' ' + trio.dataset.showing);
    var r = ren.getBoundingClientRect();
    ren.dispatchEvent(new MouseEvent('click', {bubbles: true, clientX: r.left + r.width / 4, clientY: r.top + r.height / 4}));
    rec('click', transforms());
    var e = err.getBoundingClientRect();
    err.dispatchEvent(new WheelEvent('wheel', {bubbles: true, cancelable: true, deltaY: -100,
                                               clientX: e.left + e.width * 0.75, clientY: e.top + e.height / 2}));
    rec('wheel', transforms());
    trio.querySelector('button.unzoom').click();
    rec('reset', transforms());
    // Another cell of the card: its images and scale take the trio's place, at the same zoom.
    ren.dispatchEvent(new MouseEvent('click', {bubbles: true, clientX: r.left + 10, clientY: r.top + 10}));
    var picks = card.querySelectorAll('.group li button.pick');
    rec('picks', picks.length);
    picks[1].click();
    rec('picked', card.querySelector('.group li.shown button.pick').dataset.cell + ' ' +
                  trio.querySelector('.scale').dataset.top + ' ' + (img('render').getAttribute('src') !== own));
    rec('picked-zoom', [img('reference').style.transform, img('render').style.transform, img('error').style.transform].join('|'));
  )"), "interact", kWindow);
  ASSERT_EQ(body_attr(dom, "data-t-done"), "1") << chromium.last_command();
  // (d) Flicker shows the reference in the render's place, and back.
  EXPECT_EQ(body_attr(dom, "data-t-distinct"), "true") << "a failing render differs from its reference";
  EXPECT_EQ(body_attr(dom, "data-t-flicker1"), "true reference");
  EXPECT_EQ(body_attr(dom, "data-t-flicker2"), "true render");
  // (e) Zoom on one image gives all three the same transform.
  auto same_three = [](const std::string& joined) {
    const size_t a = joined.find('|'), b = joined.find('|', a + 1);
    const std::string first = joined.substr(0, a);
    return !first.empty() && joined.substr(a + 1, b - a - 1) == first && joined.substr(b + 1) == first;
  };
  const std::string click = body_attr(dom, "data-t-click"), wheel = body_attr(dom, "data-t-wheel");
  EXPECT_TRUE(same_three(click)) << click;
  EXPECT_NE(click.find("scale(2)"), std::string::npos) << click;
  EXPECT_TRUE(same_three(wheel)) << wheel;
  EXPECT_NE(wheel.find("scale(2.5)"), std::string::npos) << wheel;
  EXPECT_NE(wheel, click);
  EXPECT_EQ(body_attr(dom, "data-t-reset"), "||");
  // A shared card shows any of its cells: the second one's images, with its own scale.
  EXPECT_EQ(body_attr(dom, "data-t-picks"), "12");
  const nlohmann::json& second = cell(failing_[1]);
  EXPECT_EQ(body_attr(dom, "data-t-picked"),
            std::to_string(failing_[1]) + " " + markup::sci(second["artefacts"]["error_scale"]["top"].get<double>()) + " true");
  const std::string picked_zoom = body_attr(dom, "data-t-picked-zoom");
  EXPECT_TRUE(same_three(picked_zoom)) << picked_zoom;
  EXPECT_NE(picked_zoom.find("scale(2)"), std::string::npos) << picked_zoom;
}

}  // namespace
}  // namespace shaderbed

namespace shaderbed {
namespace {

// A card several cells share is kept out of the markup when it starts closed (known
// failures do) and put into the page from its store when opened.
TEST(HtmlSharedCard, ClosedCardIsFilledFromItsStoreWhenOpened) {
  ASSERT_TRUE(fs::exists(chromium_path())) << chromium_path() << " is missing: run scripts/install-deps";
  const fs::path dir = test::fresh_dir("shared_card");
  RunReport report = test::sample_report(dir / "out");
  const CellResult known = report.results[2];   // hlsl gl/cross sphere, a known failure
  ASSERT_TRUE(known.known_failure);
  for (const char* shape : {"cube", "cone"}) {
    CellResult other = known;
    other.shape = shape;
    other.message = "interior max error 4.00e-02 > 2.00e-03";   // other numbers, the same failure
    report.results.push_back(other);
  }
  ASSERT_TRUE(write_html(report, (dir / "html").string()));
  const std::string html = slurp(dir / "html" / "index.html");
  const size_t section = html.find("id=\"sec-known\"");
  ASSERT_NE(section, std::string::npos);
  EXPECT_NE(html.find("Known failures (3, in 1 card)", section), std::string::npos);
  EXPECT_NE(html.find("data-count=\"3\" data-group=\"0\"", section), std::string::npos) << "closed, from the store";

  std::string page = html;
  page.insert(page.rfind("</body>"),
              "<script>window.addEventListener('load', function () {"
              "var d = document.querySelector('#sec-known details.fc'); d.open = true;"
              "setTimeout(function () { var b = document.body;"
              "b.setAttribute('data-t-first', d.querySelector('.card').firstElementChild.className);"
              "b.setAttribute('data-t-listed', d.querySelectorAll('.group li').length); }, 50); });</script>\n");
  std::ofstream(dir / "html" / "opened.html", std::ios::binary) << page;
  Chromium chromium;
  const std::string dom = chromium.dump_dom(file_url(dir / "html" / "opened.html"), "shared");
  EXPECT_EQ(body_attr(dom, "data-t-first"), "trio") << chromium.last_command();
  EXPECT_EQ(body_attr(dom, "data-t-listed"), "3");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace shaderbed
