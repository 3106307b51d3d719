#include "prt/ShProjectionReport.h"

#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "prt/RgbValues.h"
#include "sh/Basis.h"

namespace shaderbed {
namespace {

std::pair<int, int> band_and_order(size_t i) {
  const int l = int(std::sqrt(double(i)));
  return {l, int(i) - l * (l + 1)};
}

std::string projection_json(const ShProjection& p) {
  const ShProjectionRequest& a = p.request;
  const size_t n = size_t(sh::coefficient_count(a.bands));
  nlohmann::json j{{"light", a.light}, {"description", p.description}, {"bands", a.bands},
                   {"coefficient_count", n}, {"exact_method", p.exact_method}};
  if (p.has_jittered) {
    j["grid"] = a.grid;
    j["samples"] = size_t(a.grid) * size_t(a.grid);
    j["seed"] = a.seed;
  }
  if (a.light == "probe") j["probe"] = a.probe, j["mapping"] = a.mapping;
  nlohmann::json rows = nlohmann::json::array();
  for (size_t i = 0; i < n; ++i) {
    const auto [l, m] = band_and_order(i);
    nlohmann::json row{{"i", i}, {"l", l}, {"m", m}};
    if (p.has_jittered) row["jittered"] = p.scalar ? nlohmann::json(p.jittered_scalar[i]) : rgb_json(p.jittered_rgb[i]);
    row["exact"] = p.scalar ? nlohmann::json(p.exact_scalar[i]) : rgb_json(p.exact_rgb[i]);
    if (i < p.book.size()) row["book"] = p.book[i];
    rows.push_back(std::move(row));
  }
  j["coefficients"] = std::move(rows);
  auto largest = [](const ShProjection::Largest& x) { return nlohmann::json{{"value", x.value}, {"i", x.i}}; };
  if (p.has_jittered) j["max_jittered_vs_exact"] = largest(p.jittered_vs_exact);
  if (!p.book.empty()) {
    j["max_book_vs_exact"] = largest(p.book_vs_exact);
    if (p.has_jittered) j["max_book_vs_jittered"] = largest(p.book_vs_jittered);
  }
  return j.dump(2) + "\n";
}

std::string projection_text(const ShProjection& p) {
  const ShProjectionRequest& a = p.request;
  const size_t n = size_t(sh::coefficient_count(a.bands));
  std::string out = fmt::format("{}, {} bands ({} coefficients, SH frame z up)\n", p.description, a.bands, n);
  if (p.has_jittered)
    out += fmt::format("jittered: the book's {} x {} stratified grid = {} samples, seed {}\n", a.grid, a.grid,
                       size_t(a.grid) * size_t(a.grid), a.seed);
  out += fmt::format("{}\n", p.exact_method);
  if (p.scalar) {
    out += fmt::format("\n{:>4} {:>3} {:>3}  {:>12} {:>12} {:>12}\n", "i", "l", "m", p.has_jittered ? "jittered" : "",
                       "exact", p.book.empty() ? "" : "book");
    for (size_t i = 0; i < n; ++i) {
      const auto [l, m] = band_and_order(i);
      out += fmt::format("{:>4} {:>3} {:>3}  {:>12} {:>12.6f} {:>12}\n", i, l, m,
                         p.has_jittered ? fmt::format("{:.6f}", p.jittered_scalar[i]) : "", p.exact_scalar[i],
                         i < p.book.size() ? fmt::format("{:.6f}", p.book[i]) : "");
    }
  } else {
    auto triple = [](const glm::dvec3& v) { return fmt::format("{:>11.6f} {:>11.6f} {:>11.6f}", v.r, v.g, v.b); };
    out += fmt::format("\n{:>4} {:>3} {:>3}  {}{:>35}\n", "i", "l", "m",
                       p.has_jittered ? fmt::format("{:>35}  ", "jittered (r g b)") : "", "exact (r g b)");
    for (size_t i = 0; i < n; ++i) {
      const auto [l, m] = band_and_order(i);
      out += fmt::format("{:>4} {:>3} {:>3}  {}{}\n", i, l, m, p.has_jittered ? triple(p.jittered_rgb[i]) + "  " : "",
                         triple(p.exact_rgb[i]));
    }
  }
  out += "\n";
  if (p.has_jittered)
    out += fmt::format("max |jittered - exact| = {:.3e} (i = {})\n", p.jittered_vs_exact.value, p.jittered_vs_exact.i);
  if (!p.book.empty()) {
    out += fmt::format("max |book - exact|     = {:.3e} (i = {})\n", p.book_vs_exact.value, p.book_vs_exact.i);
    if (p.has_jittered)
      out += fmt::format("max |book - jittered|  = {:.3e} (i = {})\n", p.book_vs_jittered.value, p.book_vs_jittered.i);
  }
  return out;
}

}  // namespace

std::string sh_projection_report(const ShProjection& projection, bool json) {
  return json ? projection_json(projection) : projection_text(projection);
}

}  // namespace shaderbed
