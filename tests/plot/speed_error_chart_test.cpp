// Real charts drawn by the installed gnuplot: the files exist, the PNG has the requested
// size and actual drawing in it, and the SVG carries the title, every label, the front's
// line and nothing that would break inlining. Outputs stay under
// $TMPDIR/shaderbed-plot-tests/<test>/ to be looked at.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "NonFinite.h"
#include "plot/Gnuplot.h"
#include "plot/SpeedErrorChart.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using test::kNaN;

fs::path output_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / "shaderbed-plot-tests" / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// How gnuplot's svg terminal writes text: '&' and '<' escaped, everything else verbatim.
std::string svg_text(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : std::string(1, c);
  return out;
}

bool contains_text(const std::string& svg, const std::string& text) {
  return svg.find("<text>" + svg_text(text) + "</text>") != std::string::npos;
}

// The plot group (<g id="..._plot_N">...</g>) whose key entry reads `key`.
std::string plot_group(const std::string& svg, const std::string& key) {
  const std::size_t at = svg.find("<text>" + key + "</text>");
  if (at == std::string::npos) return {};
  const std::size_t begin = svg.rfind("_plot_", at);
  const std::size_t end = svg.find("_plot_", at);
  return svg.substr(begin, (end == std::string::npos ? svg.size() : end) - begin);
}

struct Marker {
  std::string shape;
  double x, y;
};
std::vector<Marker> markers(const std::string& svg_part) {
  std::vector<Marker> found;
  static const std::regex use(R"(<use xlink:href='#(gpPt\d+)' transform='translate\(([-0-9.]+),([-0-9.]+)\))");
  for (auto it = std::sregex_iterator(svg_part.begin(), svg_part.end(), use); it != std::sregex_iterator(); ++it)
    found.push_back({(*it)[1], std::stod((*it)[2]), std::stod((*it)[3])});
  return found;
}

// Vertex counts of the subpaths of every <path d='...'> in `svg_part`.
std::vector<int> subpath_vertex_counts(const std::string& svg_part) {
  std::vector<int> counts;
  static const std::regex path(R"(<path [^>]*d='([^']*)')");
  for (auto it = std::sregex_iterator(svg_part.begin(), svg_part.end(), path); it != std::sregex_iterator(); ++it) {
    const std::string d = (*it)[1];
    for (char c : d) {
      if (c == 'M') counts.push_back(1);
      if (c == 'L' && !counts.empty()) ++counts.back();
    }
  }
  return counts;
}

struct Png {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> pixels;
};
Png read_png(const std::string& path) {
  Png png;
  auto in = OIIO::ImageInput::open(path);
  if (!in) return png;
  const OIIO::ImageSpec& spec = in->spec();
  png.width = spec.width, png.height = spec.height, png.channels = spec.nchannels;
  png.pixels.resize(std::size_t(png.width) * png.height * png.channels);
  in->read_image(0, 0, 0, png.channels, OIIO::TypeDesc::UINT8, png.pixels.data());
  return png;
}
int pixels_near(const Png& png, int r, int g, int b) {
  int n = 0;
  for (std::size_t i = 0; i + 2 < png.pixels.size(); i += png.channels)
    n += std::abs(png.pixels[i] - r) < 20 && std::abs(png.pixels[i + 1] - g) < 20 && std::abs(png.pixels[i + 2] - b) < 20;
  return n;
}

// An Oren-Nayar LUT sweep: error falls as the LUT grows, time rises; two book/robust
// arithmetic variants; labels with the characters that break naive quoting.
std::vector<ChartPoint> lut_sweep() {
  return {
      {"lut_8", "pixel_lut", 0.40, 2.0e-2},  {"lut_32", "pixel_lut", 0.45, 4.0e-3},
      {"lut_128", "pixel_lut", 0.60, 9.0e-4}, {"lut_256", "pixel_lut", 0.95, 8.0e-4},
      {"book", "pixel", 0.80, 1.0e-4},        {"robust \"clamped\" it's", "pixel", 0.90, 1.2e-4},
      {"vertex_a&b<c>", "vertex", 0.30, 5.0e-2}, {"vertex_slow", "vertex", 0.70, 6.0e-2},
  };
}

TEST(SpeedErrorChart, WritesAPngAndAnInlinableSvgWithTitleLabelsAndTheFront) {
  const fs::path dir = output_dir();
  ChartSpec spec{.title = "oren_nayar: LUT size vs arithmetic",
                 .x_label = "GPU time per draw (ms)",
                 .y_label = "interior RMSE",
                 .width = 800,
                 .height = 500};
  const std::vector<ChartPoint> points = lut_sweep();
  auto files = write_speed_error_chart(points, spec, (dir / "speed_error").string());
  ASSERT_TRUE(files) << files.error().to_string();
  EXPECT_EQ(files->png, (dir / "speed_error.png").string());
  EXPECT_EQ(files->svg, (dir / "speed_error.svg").string());

  const Png png = read_png(files->png);
  EXPECT_EQ(png.width, 800);
  EXPECT_EQ(png.height, 500);
  EXPECT_GT(pixels_near(png, 0x1f, 0x77, 0xb4), 50) << "the first series' colour is missing from the PNG";
  EXPECT_GT(pixels_near(png, 0xff, 0x7f, 0x0e), 50) << "the second series' colour is missing from the PNG";

  const std::string svg = read_all(files->svg);
  EXPECT_TRUE(svg.starts_with("<svg")) << svg.substr(0, 80);
  EXPECT_NE(svg.find("viewBox=\"0 0 800 500\""), std::string::npos);
  EXPECT_TRUE(contains_text(svg, spec.title));
  EXPECT_NE(svg.find("<title>" + spec.title + "</title>"), std::string::npos) << "the tooltip of the inlined chart";
  EXPECT_TRUE(contains_text(svg, spec.x_label));
  EXPECT_TRUE(contains_text(svg, spec.y_label));
  for (const ChartPoint& p : points) EXPECT_TRUE(contains_text(svg, p.label)) << p.label;
  for (const char* series : {"pixel_lut", "pixel", "vertex"}) EXPECT_TRUE(contains_text(svg, series)) << series;

  // Inlining: no script, no external reference, nothing an HTML parser would choke on.
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("<?xml"), std::string::npos);
  EXPECT_EQ(svg.find("<!DOCTYPE"), std::string::npos);
  EXPECT_EQ(svg.find("@import"), std::string::npos);
  std::smatch external;
  EXPECT_FALSE(std::regex_search(svg, external, std::regex(R"(href=['"][^#])"))) << external.str();

  // The front here: vertex_a&b<c> (0.30), lut_8 (0.40), lut_32 (0.45), lut_128 (0.60),
  // book (0.80); lut_256, robust and vertex_slow are dominated. Its group holds one line
  // through five vertices and an open circle on each (plus the key's sample).
  const std::string front = plot_group(svg, "Pareto front");
  ASSERT_FALSE(front.empty());
  const std::vector<int> lines = subpath_vertex_counts(front);
  EXPECT_NE(std::ranges::find(lines, 5), lines.end()) << "no 5-vertex line in the front's group";
  std::vector<Marker> circles = markers(front);
  EXPECT_EQ(circles.size(), 6u);
  // Leftmost circle is the cheapest point, and each step right goes down (less error).
  circles.pop_back();  // the key sample comes last
  std::ranges::sort(circles, {}, &Marker::x);
  for (std::size_t k = 1; k < circles.size(); ++k) EXPECT_GT(circles[k].y, circles[k - 1].y) << "front step " << k;
}

// Horizontal segments (M x y L x2 y) in `svg_part`: where an error bar is drawn.
struct Segment {
  double x0, x1, y;
};
std::vector<Segment> horizontal_segments(const std::string& svg_part) {
  std::vector<Segment> found;
  static const std::regex seg(R"(M([-0-9.]+),([-0-9.]+) L([-0-9.]+),([-0-9.]+))");
  for (auto it = std::sregex_iterator(svg_part.begin(), svg_part.end(), seg); it != std::sregex_iterator(); ++it) {
    const double x0 = std::stod((*it)[1]), y0 = std::stod((*it)[2]), x1 = std::stod((*it)[3]), y1 = std::stod((*it)[4]);
    if (std::abs(y0 - y1) < 0.01 && std::abs(x1 - x0) > 0.5) found.push_back({std::min(x0, x1), std::max(x0, x1), y0});
  }
  return found;
}

TEST(SpeedErrorChart, DrawsEachMedianCostsConfidenceIntervalAsAnErrorBar) {
  const fs::path dir = output_dir();
  // Known intervals on a linear axis: 'a' +-0.1 around 1, 'b' from 1.5 to 3 around 2.
  std::vector<ChartPoint> points = {{"a", "timed", 1.0, 0.2}, {"b", "timed", 2.0, 0.1}};
  points[0].cost_low = 0.9, points[0].cost_high = 1.1;
  points[1].cost_low = 1.5, points[1].cost_high = 3.0;
  auto files = write_speed_error_chart(points, {.title = "bars", .x_scale = AxisScale::linear, .y_scale = AxisScale::linear},
                                       (dir / "bars").string());
  ASSERT_TRUE(files) << files.error().to_string();
  const std::string svg = read_all(files->svg);
  const std::string series = plot_group(svg, "timed");
  ASSERT_FALSE(series.empty());
  std::vector<Marker> dots = markers(series);
  ASSERT_EQ(dots.size(), 3u);
  dots.pop_back();   // the key's sample comes last
  std::ranges::sort(dots, {}, &Marker::x);
  const Marker a = dots[0], b = dots[1];
  const double px_per_ms = b.x - a.x;        // the medians are 1 ms apart
  auto bar_at = [&](const Marker& m) -> std::optional<Segment> {
    for (const Segment& s : horizontal_segments(series))
      if (std::abs(s.y - m.y) < 1.0 && s.x0 <= m.x && s.x1 >= m.x) return s;
    return std::nullopt;
  };
  const auto bar_a = bar_at(a), bar_b = bar_at(b);
  ASSERT_TRUE(bar_a) << "no error bar through a";
  ASSERT_TRUE(bar_b) << "no error bar through b";
  EXPECT_NEAR(bar_a->x0, a.x - 0.1 * px_per_ms, 1.5);
  EXPECT_NEAR(bar_a->x1, a.x + 0.1 * px_per_ms, 1.5);
  EXPECT_NEAR(bar_b->x0, b.x - 0.5 * px_per_ms, 1.5);
  EXPECT_NEAR(bar_b->x1, b.x + 1.0 * px_per_ms, 1.5);
  // a is faster beyond noise, b more accurate: both are on the front.
  EXPECT_EQ(markers(plot_group(svg, "Pareto front")).size(), 3u);   // two points and the key's sample
}

TEST(SpeedErrorChart, ChoosesALogAxisForCostsSpanningDecades) {
  const fs::path dir = output_dir();
  const std::vector<ChartPoint> points = {
      {"a", "s", 0.01, 3.0}, {"b", "s", 1.0, 2.0}, {"c", "s", 100.0, 1.0}};
  auto log_chart = write_speed_error_chart(points, {.title = "log"}, (dir / "log").string());
  auto linear_chart = write_speed_error_chart(points, {.title = "linear", .x_scale = AxisScale::linear}, (dir / "linear").string());
  ASSERT_TRUE(log_chart) << log_chart.error().to_string();
  ASSERT_TRUE(linear_chart) << linear_chart.error().to_string();

  // The series' markers (filled circles): on a log axis 0.01, 1 and 100 are evenly spaced.
  auto marker_xs = [](const std::string& svg) {
    std::vector<double> xs;
    for (const Marker& m : markers(plot_group(svg, "s"))) xs.push_back(m.x);
    xs.pop_back();  // the key sample
    std::ranges::sort(xs);
    return xs;
  };
  const std::string log_svg = read_all(log_chart->svg);
  const std::vector<double> log_xs = marker_xs(log_svg);
  ASSERT_EQ(log_xs.size(), 3u);
  EXPECT_NEAR(log_xs[1] - log_xs[0], log_xs[2] - log_xs[1], 1.0);
  for (const char* tick : {"0.01", "0.1", "1", "10", "100"}) EXPECT_TRUE(contains_text(log_svg, tick)) << tick;

  const std::vector<double> linear_xs = marker_xs(read_all(linear_chart->svg));
  ASSERT_EQ(linear_xs.size(), 3u);
  EXPECT_LT((linear_xs[1] - linear_xs[0]) * 50, linear_xs[2] - linear_xs[1]);
}

TEST(SpeedErrorChart, FlagsNonFiniteAndClampedPointsInsteadOfDroppingThem) {
  const fs::path dir = output_dir();
  const std::vector<ChartPoint> points = {{"fast", "book", 1.0, 1e-1},
                                          {"exact", "book", 3.0, 0.0},  // zero error on a log axis
                                          {"mid", "book", 2.0, 1e-3},
                                          {"broken", "book", 1.5, kNaN}};
  auto files = write_speed_error_chart(points, {.title = "hard", .y_scale = AxisScale::log}, (dir / "hard").string());
  ASSERT_TRUE(files) << files.error().to_string();
  const std::string svg = read_all(files->svg);
  EXPECT_TRUE(contains_text(svg, "broken (error=nan)"));
  EXPECT_TRUE(contains_text(svg, "exact (error=0)"));
  EXPECT_TRUE(contains_text(svg, "1 point with error <= 0 drawn at 0.0001 (log axis)"));
  EXPECT_TRUE(contains_text(svg, "1 point with NaN/Inf cost or error drawn at the edge (x), not on the front"));
  EXPECT_EQ(markers(plot_group(svg, "NaN/Inf (at the edge)")).size(), 2u);  // the point and the key sample
  EXPECT_EQ(markers(plot_group(svg, "Pareto front")).size(), 4u);          // fast, mid, exact + key
  EXPECT_EQ(read_png(files->png).width, ChartSpec{}.width);
}

TEST(SpeedErrorChart, ClearErrorWhenGnuplotIsNotOnPath) {
  const fs::path dir = output_dir();
  fs::create_directories(dir / "empty-bin");
  const char* saved = std::getenv("PATH");
  const std::string saved_path = saved != nullptr ? saved : "";
  ::setenv("PATH", (dir / "empty-bin").c_str(), 1);
  auto files = write_speed_error_chart(lut_sweep(), {.title = "t"}, (dir / "chart").string());
  ::setenv("PATH", saved_path.c_str(), 1);

  ASSERT_FALSE(files);
  EXPECT_EQ(files.error().stage, ErrorStage::plot);
  EXPECT_EQ(files.error().message, "gnuplot not found on PATH: install gnuplot-nox (scripts/install-deps)");
  EXPECT_FALSE(fs::exists(dir / "chart.png"));
  EXPECT_FALSE(fs::exists(dir / "chart.svg"));
}

TEST(SpeedErrorChart, ClearErrorForAGnuplotPathThatDoesNotExist) {
  const fs::path dir = output_dir();
  auto files = write_speed_error_chart(lut_sweep(), {.title = "t"}, (dir / "chart").string(), (dir / "no-gnuplot").string());
  ASSERT_FALSE(files);
  EXPECT_EQ(files.error().stage, ErrorStage::plot);
  EXPECT_NE(files.error().message.find("gnuplot not found at"), std::string::npos) << files.error().message;
  EXPECT_NE(files.error().message.find("gnuplot-nox"), std::string::npos) << files.error().message;
}

TEST(SpeedErrorChart, RefusesAnEmptyPointSet) {
  auto files = write_speed_error_chart({}, {.title = "nothing"}, (output_dir() / "chart").string());
  ASSERT_FALSE(files);
  EXPECT_EQ(files.error().stage, ErrorStage::plot);
}

}  // namespace
}  // namespace shaderbed
