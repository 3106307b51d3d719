#include "plot/SpeedErrorChart.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "plot/Gnuplot.h"
#include "plot/ParetoFront.h"
#include "core/AtomicFile.h"
#include "core/ScratchDirectory.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

// Colour-blind-friendly Tableau colours without red, which flags NaN/Inf points; paired
// with filled marker shapes so series stay apart in greyscale too.
constexpr std::array<const char*, 9> kSeriesColours = {"#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                                                       "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};
constexpr std::array<int, 6> kSeriesPointTypes = {7, 5, 9, 11, 13, 15};  // filled circle, square, triangles, diamond, pentagon
constexpr const char* kNonFiniteColour = "#d62728";

struct Series {
  std::string name;
  std::vector<std::size_t> points;
};

std::vector<Series> group_by_series(const std::vector<ChartPoint>& points) {
  std::vector<Series> series;  // in order of first appearance, so the caller controls the key
  for (std::size_t i = 0; i < points.size(); ++i) {
    auto it = std::ranges::find(series, points[i].series, &Series::name);
    if (it == series.end()) it = series.insert(series.end(), Series{points[i].series, {}});
    it->points.push_back(i);
  }
  return series;
}

bool is_finite_point(const ChartPoint& p) { return std::isfinite(p.cost) && std::isfinite(p.error); }

bool has_interval(const ChartPoint& p) { return std::isfinite(p.cost_low) && std::isfinite(p.cost_high); }

std::string non_finite_label(const ChartPoint& p) {
  std::string what;
  if (!std::isfinite(p.cost)) what += fmt::format("cost={}", p.cost);
  if (!std::isfinite(p.error)) what += fmt::format("{}error={}", what.empty() ? "" : ", ", p.error);
  return fmt::format("{} ({})", p.label, what);
}

// A point drawn at a log axis' floor says its real value, so it cannot pass for one that is there.
std::string clamped_label(const ChartPoint& p, const ChartAxis& x, const ChartAxis& y) {
  std::string what;
  if (x.log && p.cost <= 0) what += fmt::format("cost={:g}", p.cost);
  if (y.log && p.error <= 0) what += fmt::format("{}error={:g}", what.empty() ? "" : ", ", p.error);
  return what.empty() ? p.label : fmt::format("{} ({})", p.label, what);
}

// gnuplot's svg terminal uses the name in the ids of the plot groups; a distinct name per
// chart keeps ids unique when several charts are inlined into one page.
std::string svg_name(const std::string& out_stem) {
  std::string name = "chart_";
  for (char c : fs::path(out_stem).filename().string()) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

std::string range(const ChartAxis& axis) { return fmt::format("[{:.17g}:{:.17g}]", axis.low, axis.high); }

struct ChartInputs {
  const std::vector<ChartPoint>& points;
  const ChartSpec& spec;
  ChartAxis x, y;
  ParetoFront front;
  std::vector<Series> series;
  std::vector<std::string> notes;
};

// The data file: the front, then one block per series (its finite points), then the NaN/Inf
// points, each block addressed by gnuplot's `index`. Returns the plot clauses.
std::vector<std::string> write_data(const ChartInputs& in, const std::string& data_file, std::ostream& data) {
  std::vector<std::string> clauses;
  int block = 0;
  const std::string file = gnuplot_string(data_file);
  // Columns: x, y, then the cost interval's ends (the point itself when it has none).
  auto emit_block = [&](const std::vector<std::size_t>& indices) {
    for (std::size_t i : indices) {
      const ChartPoint& p = in.points[i];
      const double x = in.x.position(p.cost);
      data << fmt::format("{:.17g} {:.17g} {:.17g} {:.17g}\n", x, in.y.position(p.error),
                          has_interval(p) ? in.x.position(p.cost_low) : x, has_interval(p) ? in.x.position(p.cost_high) : x);
    }
    data << "\n\n";
    return block++;
  };

  // The front first, so the series' markers are drawn over its line.
  if (!in.front.front.empty())
    clauses.push_back(fmt::format("{} index {} using 1:2 with linespoints dt 2 lw 1.5 pt 6 ps 2.6 lc rgb '#000000' title 'Pareto front'",
                                  file, emit_block(in.front.front)));
  for (std::size_t s = 0; s < in.series.size(); ++s) {
    std::vector<std::size_t> finite;
    for (std::size_t i : in.series[s].points)
      if (is_finite_point(in.points[i])) finite.push_back(i);
    if (finite.empty()) continue;
    const std::string title = in.series[s].name.empty() ? "points" : in.series[s].name;
    // A series with measured intervals draws each point with its bar, in the series' colour.
    const bool bars = std::ranges::any_of(finite, [&](std::size_t i) { return has_interval(in.points[i]); });
    clauses.push_back(fmt::format("{} index {} using {} pt {} ps 1.4 lc rgb '{}' title {}", file, emit_block(finite),
                                  bars ? "1:2:3:4 with xerrorbars lw 1.2" : "1:2 with points",
                                  kSeriesPointTypes[s % kSeriesPointTypes.size()], kSeriesColours[s % kSeriesColours.size()],
                                  gnuplot_string(title)));
  }
  if (!in.front.non_finite.empty())
    clauses.push_back(fmt::format("{} index {} using 1:2 with points pt 2 ps 1.8 lw 2 lc rgb '{}' title 'NaN/Inf (at the edge)'",
                                  file, emit_block(in.front.non_finite), kNonFiniteColour));
  return clauses;
}

std::string script(const ChartInputs& in, const std::vector<std::string>& clauses, const fs::path& dir, const std::string& name) {
  const ChartSpec& spec = in.spec;
  std::string s;
  auto line = [&](const std::string& text) { s += text + "\n"; };
  line("set encoding utf8");
  line(fmt::format("set title {}", gnuplot_string(spec.title)));
  line(fmt::format("set xlabel {}", gnuplot_string(spec.x_label)));
  line(fmt::format("set ylabel {}", gnuplot_string(spec.y_label)));
  line(fmt::format("set xrange {}", range(in.x)));
  line(fmt::format("set yrange {}", range(in.y)));
  for (auto [axis, letter] : {std::pair(&in.x, 'x'), std::pair(&in.y, 'y')}) {
    if (axis->log) line(fmt::format("set logscale {} 10", letter));
    line(fmt::format("set format {} '%g'", letter));
    line(fmt::format("set m{}tics", letter));
  }
  line("set grid xtics ytics mxtics mytics lc rgb '#d9d9d9' lw 1, lc rgb '#efefef' lw 1");
  line("set key outside right top vertical Left reverse samplen 2 spacing 1.3");
  line("set border lc rgb '#404040'");

  int label_id = 1;
  for (std::size_t s_index = 0; s_index < in.series.size(); ++s_index)
    for (std::size_t i : in.series[s_index].points) {
      const ChartPoint& p = in.points[i];
      const bool finite = is_finite_point(p);
      line(fmt::format("set label {} {} at first {:.17g},{:.17g} offset char 0.8,0.6 left font ',9' textcolor rgb '{}' front",
                       label_id++, gnuplot_string(finite ? clamped_label(p, in.x, in.y) : non_finite_label(p)), in.x.position(p.cost),
                       in.y.position(p.error), finite ? kSeriesColours[s_index % kSeriesColours.size()] : kNonFiniteColour));
    }
  // Notes sit under the x axis label, one line each, in a bottom margin made for them.
  line(fmt::format("set bmargin {}", 4 + in.notes.size()));
  for (std::size_t n = 0; n < in.notes.size(); ++n)
    line(fmt::format("set label {} {} at screen 0.01,0 offset char 0,{:.1f} left font ',9' textcolor rgb '#803030'", label_id++,
                     gnuplot_string(in.notes[n]), double(in.notes.size() - n) - 0.3));

  std::string plot = "plot ";
  for (std::size_t c = 0; c < clauses.size(); ++c) plot += (c ? ", \\\n     " : "") + clauses[c];

  // noenhanced on each terminal (setting a terminal resets it): labels are literal text,
  // '_' and '^' are not sub/superscript markup.
  line(fmt::format("set terminal pngcairo size {},{} noenhanced font 'sans,10' background rgb '#ffffff'", spec.width, spec.height));
  line(fmt::format("set output {}", gnuplot_string((dir / "chart.png").string())));
  line(plot);
  // No `mouse`: that option adds a script and links gnuplot's JavaScript, which an
  // inlined report cannot load. `dynamic` leaves sizing to the page via the viewBox.
  line(fmt::format("set terminal svg size {},{} dynamic noenhanced font 'sans-serif,12' background rgb '#ffffff' name {}",
                   spec.width, spec.height, gnuplot_string(name)));
  line(fmt::format("set output {}", gnuplot_string((dir / "chart.svg").string())));
  line("replot");
  line("unset output");
  return s;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Result<void> write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) return std::unexpected(Error{.message = "cannot write the file", .file = path.string(), .stage = ErrorStage::plot});
  return {};
}

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : std::string(1, c);
  return out;
}

// Ready to paste into HTML: the XML declaration, the one part of gnuplot's SVG that does
// not belong inside a page, goes; the <title> (a tooltip once inlined) becomes the
// chart's title instead of the terminal's name.
std::string inlinable_svg(std::string svg, const std::string& name, const std::string& title) {
  if (svg.starts_with("<?xml")) {
    const std::size_t end = svg.find("?>");
    if (end != std::string::npos) svg.erase(0, svg.find_first_not_of("\r\n", end + 2));
  }
  const std::string gnuplot_title = "<title>" + name + "</title>";
  if (const std::size_t at = svg.find(gnuplot_title); at != std::string::npos)
    svg.replace(at, gnuplot_title.size(), "<title>" + xml_escaped(title) + "</title>");
  return svg;
}

}  // namespace

Result<ChartFiles> write_speed_error_chart(const std::vector<ChartPoint>& points, const ChartSpec& spec,
                                           const std::string& out_stem, const std::string& gnuplot) {
  if (points.empty()) return fail(ErrorStage::plot, fmt::format("no points to chart for '{}'", spec.title));
  if (spec.width < 64 || spec.height < 64)
    return fail(ErrorStage::plot, fmt::format("chart size {}x{} is too small to draw", spec.width, spec.height));

  std::vector<double> costs, errors;
  std::vector<CostError> cost_error;
  for (const ChartPoint& p : points) {
    costs.push_back(p.cost), errors.push_back(p.error);
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();   // half an interval is none
    cost_error.push_back({p.cost, p.error, has_interval(p) ? p.cost_low : kNone, has_interval(p) ? p.cost_high : kNone});
  }
  // The cost axis spans the error bars too (after the points, so a NaN point's place is kept).
  for (const ChartPoint& p : points)
    if (has_interval(p) && is_finite_point(p)) costs.push_back(p.cost_low), costs.push_back(p.cost_high);
  ChartInputs in{points, spec, plan_axis(costs, spec.x_scale, "cost"), plan_axis(errors, spec.y_scale, "error"),
                 find_pareto_front(cost_error), group_by_series(points), {}};
  for (const ChartAxis* axis : {&in.x, &in.y})
    if (!axis->note.empty()) in.notes.push_back(axis->note);
  if (const std::size_t n = in.front.non_finite.size(); n > 0)
    in.notes.push_back(fmt::format("{} point{} with NaN/Inf cost or error drawn at the edge (x), not on the front", n,
                                   n == 1 ? "" : "s"));

  auto dir = ScratchDirectory::create("plot");
  if (!dir) return std::unexpected(dir.error());
  const fs::path data_path = dir->path() / "points.dat", script_path = dir->path() / "chart.gp";
  const std::string name = svg_name(out_stem);
  std::ostringstream data;
  const std::vector<std::string> clauses = write_data(in, data_path.string(), data);
  if (auto ok = write_text(data_path, data.str()); !ok) return std::unexpected(ok.error());
  if (auto ok = write_text(script_path, script(in, clauses, dir->path(), name)); !ok)
    return std::unexpected(ok.error());
  if (auto ran = run_gnuplot(gnuplot, script_path); !ran) return std::unexpected(ran.error());

  const fs::path png = dir->path() / "chart.png", svg = dir->path() / "chart.svg";
  for (const fs::path& p : {png, svg})
    if (std::error_code ec; !fs::exists(p, ec) || fs::file_size(p, ec) == 0)
      return fail(ErrorStage::plot, fmt::format("gnuplot exited cleanly but wrote no {}", p.filename().string()));

  ChartFiles files{out_stem + ".png", out_stem + ".svg"};
  // Checked, flushed writes (a full disk is an error, not a short chart), renamed into place.
  if (auto ok = write_file_atomically(files.png, read_all(png), "chart"); !ok) return std::unexpected(ok.error());
  if (auto ok = write_file_atomically(files.svg, inlinable_svg(read_all(svg), name, spec.title), "chart"); !ok)
    return std::unexpected(ok.error());
  return files;
}

}  // namespace shaderbed
