#include "report/TwinText.h"
#include "report/HtmlReport.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "core/AtomicFile.h"
#include "core/Fnv1a.h"
#include "report/CellExplanation.h"
#include "report/CellGroups.h"
#include "report/HtmlScaleBar.h"
#include "report/Markup.h"
#include "report/ReportAssets.gen.h"   // report_css, report_js: generated from report/assets/
#include "report/SummaryMatrix.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;
using markup::escape;
using markup::sci;

constexpr size_t kMaxImageFile = size_t(16) << 20;   // larger "PNGs" are not embedded

std::string attr(std::string_view s) { return escape(s, true); }

// A number for data-v (what the table sorts by): shortest round-trip text, or Infinity.
std::string sort_value(double v) {
  if (std::isnan(v) || (std::isinf(v) && v > 0)) return "Infinity";
  if (std::isinf(v)) return "-Infinity";
  return fmt::format("{}", v);
}

std::string db(double v) { return std::isfinite(v) ? fmt::format("{:.1f}", v) : sci(v); }

// "pass", "fail" (new), "known", "error", "skipped".
std::string kind(const CellResult& r) {
  if (r.status == CellStatus::fail) return r.known_failure ? "known" : "fail";
  return to_string(r.status);
}

std::string status_label(const std::string& k) {
  return k == "pass" ? "pass" : k == "fail" ? "FAIL" : k == "known" ? "known" : k == "skipped" ? "skipped" : "ERROR";
}

int status_rank(const std::string& k) { return k == "error" ? 3 : k == "fail" ? 2 : k == "known" ? 1 : 0; }

// Percent-encodes a relative path for href/src (keeps / and unreserved characters).
std::string url_path(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') out += char(c);
    else out += fmt::format("%{:02X}", c);
  }
  return out;
}

bool read_file(const fs::path& path, std::string& out, size_t limit) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec || size > limit) return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  out = s.str();
  return bool(in) || in.eof();
}

class Writer {
 public:
  Writer(const RunReport& report, const fs::path& dir, const HtmlOptions& options)
      : report_(report), dir_(dir), options_(options) {}

  Result<HtmlSummary> write() {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec || !fs::is_directory(dir_))
      return std::unexpected(Error{.message = "cannot create the HTML report folder: " + ec.message(),
                                   .file = dir_.string(), .stage = ErrorStage::report});
    index_groups();
    copy_sources();
    // The page without images (every image as a file link, a little longer than a store
    // key) bounds the markup; images get what is left of max_page_bytes.
    const size_t markup = page().size();
    choose_images(std::min(options_.image_budget, options_.max_page_bytes > markup ? options_.max_page_bytes - markup : 0));
    const std::string html = page();
    const fs::path index = dir_ / "index.html";
    if (auto ok = write_file_atomically(index.string(), html, "HTML report"); !ok) return std::unexpected(ok.error());
    summary_.index_path = index.string();
    summary_.html_bytes = html.size();
    return summary_;
  }

 private:
  // ---- artefacts ----

  // The file a recorded path names: as written, or under the run's folder.
  std::string resolve(const std::string& path) const {
    if (path.empty()) return "";
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) return path;
    if (fs::path(path).is_relative() && !report_.out_dir.empty()) {
      const fs::path under = fs::path(report_.out_dir) / path;
      if (fs::is_regular_file(under, ec)) return under.string();
    }
    return "";
  }

  std::string relative_url(const std::string& file) const {
    std::error_code ec;
    const fs::path rel = fs::relative(fs::absolute(file, ec), fs::absolute(dir_, ec), ec);
    if (ec || rel.empty()) return "file://" + url_path(fs::absolute(file, ec).generic_string());
    return url_path(rel.generic_string());
  }

  void index_groups() {
    for (size_t i = 0; i < report_.results.size(); ++i) {
      const CellResult& r = report_.results[i];
      groups_[group_key(r)].push_back(i);
    }
    int stored = 0;
    for (const char* k : {"fail", "error", "known", "skipped"}) {
      std::vector<const CellResult*> cells;
      for (const CellResult& r : report_.results)
        if (kind(r) == k) cells.push_back(&r);
      auto& cards = failure_cards_[k];
      for (auto& group : group_cells(cells, [](const CellResult& r) { return failure_key(r); }))
        cards.push_back({std::move(group), -1});
      for (FailureCard& c : cards)
        if (c.cells.size() > 1) c.store = stored++;
    }
  }
  static std::string group_key(const CellResult& r) { return r.case_name + "/" + r.variant + "/" + r.shape; }

  // Embeds one PNG if it exists, is a PNG and fits in the budget. Idempotent per path.
  void consider(const std::string& recorded) {
    if (recorded.empty() || considered_.contains(recorded)) return;
    considered_.insert(recorded);
    const std::string file = resolve(recorded);
    if (file.empty()) return;
    std::string bytes;
    if (!read_file(file, bytes, kMaxImageFile) || bytes.size() < 8 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return;
    const size_t encoded = (bytes.size() + 2) / 3 * 4 + 22;
    if (summary_.image_bytes + encoded > budget_) return;
    const std::string key = fmt::format("i{}", store_.size());
    store_.push_back({key, "data:image/png;base64," + markup::base64(bytes)});
    embedded_[recorded] = key;
    summary_.image_bytes += encoded;
  }

  void choose_images(size_t budget) {
    budget_ = budget;
    const auto& cells = report_.results;
    auto own = [&](const CellResult& r) {
      consider(r.artefacts.reference_png);
      consider(r.artefacts.render_png);
      consider(r.artefacts.error_png);
    };
    // 1. Failing and erroring cells: new failures, errors, known failures.
    for (const char* k : {"fail", "error", "known"})
      for (const CellResult& r : cells)
        if (kind(r) == k) own(r);
    // 2. One passing example per case/variant.
    std::set<std::string> example;
    for (const CellResult& r : cells)
      if (r.status == CellStatus::pass && example.insert(r.case_name + "/" + r.variant).second) own(r);
    // 3. The other renders of a failing cell's case/variant/shape (the attribution evidence).
    for (const CellResult& r : cells)
      if (kind(r) != "pass" && kind(r) != "skipped")
        for (size_t s : groups_.at(group_key(r))) consider(cells[s].artefacts.render_png);
    // 4. Whatever still fits: references, then renders, then error maps.
    for (const CellResult& r : cells) consider(r.artefacts.reference_png);
    for (const CellResult& r : cells) consider(r.artefacts.render_png);
    for (const CellResult& r : cells) consider(r.artefacts.error_png);
    // Count what the page shows but does not embed.
    std::set<std::string> seen;
    for (const CellResult& r : cells)
      for (const std::string* p : {&r.artefacts.reference_png, &r.artefacts.render_png, &r.artefacts.error_png}) {
        if (p->empty() || embedded_.contains(*p) || !seen.insert(*p).second) continue;
        (resolve(*p).empty() ? summary_.images_missing : summary_.images_linked)++;
      }
    summary_.images_embedded = store_.size();
  }

  // Copies each distinct source text into DIR/sources/, mirroring its place under the run's
  // folder (else sources/other/HASH/NAME), with .txt appended so browsers display it. A
  // copy that fails (a full disk) costs that link, never the page.
  void copy_sources() {
    for (const CellResult& r : report_.results) {
      const CellArtefacts& a = r.artefacts;
      for (const std::string* p : {&a.vertex_spirv, &a.fragment_spirv, &a.vertex_cross_glsl, &a.fragment_cross_glsl}) {
        if (p->empty() || sources_.contains(*p)) continue;
        const std::string file = resolve(*p);
        if (file.empty()) {
          sources_[*p] = "";
          continue;
        }
        std::error_code ec;
        fs::path rel;
        if (!report_.out_dir.empty()) {
          rel = fs::relative(fs::absolute(file, ec), fs::absolute(report_.out_dir, ec), ec);
          if (ec || rel.empty() || *rel.begin() == "..") rel.clear();
        }
        if (rel.empty())
          rel = fs::path("other") / hex64(fnv1a64(fs::absolute(file, ec).string())) / fs::path(file).filename();
        rel = fs::path("sources") / (rel.string() + ".txt");
        fs::create_directories((dir_ / rel).parent_path(), ec);
        fs::copy_file(file, dir_ / rel, fs::copy_options::overwrite_existing, ec);
        if (ec) {
          fs::remove(dir_ / rel, ec);   // copy_file leaves what it managed to write
          sources_[*p] = "";
          ++summary_.sources_not_copied;
          continue;
        }
        sources_[*p] = url_path(rel.generic_string());
        ++summary_.sources_copied;
      }
    }
  }

  // ---- markup ----

  // An image in a <figure>; `role` (reference, render, error) puts it in a zoomable viewport.
  std::string image(const std::string& recorded, const std::string& label, const std::string& caption,
                    const std::string& role = "") const {
    if (recorded.empty()) return "";
    std::string body;
    if (auto it = embedded_.find(recorded); it != embedded_.end()) {
      body = fmt::format("<img data-img=\"{}\" alt=\"{}\" title=\"{}\">", it->second, attr(label), attr(recorded));
    } else if (const std::string file = resolve(recorded); !file.empty()) {
      body = fmt::format("<img data-file=\"{}\" alt=\"{}\" title=\"{}\">", attr(relative_url(file)), attr(label),
                         attr(recorded));
    } else {
      body = fmt::format("<div class=\"missing\">missing<br><code>{}</code></div>", escape(recorded));
    }
    if (role.empty()) return fmt::format("<figure>{}<figcaption>{}</figcaption></figure>", body, caption);
    return fmt::format("<figure data-role=\"{}\"><div class=\"vp\">{}</div><figcaption>{}</figcaption></figure>", role, body,
                       caption);
  }

  std::string source_link(const std::string& recorded, const std::string& label) const {
    if (recorded.empty()) return "";
    const auto it = sources_.find(recorded);
    if (it == sources_.end() || it->second.empty())
      return fmt::format("<span class=\"missing\" title=\"{}\">{}: missing</span>", attr(recorded), escape(label));
    // No title with the recorded path: the link is the path, and 1400 cards repeat it ~10 times each.
    return fmt::format("<a href=\"{}\">{}</a>", attr(it->second), escape(label));
  }

  std::string file_link(const std::string& recorded, const std::string& label) const {
    if (recorded.empty()) return "";
    const std::string file = resolve(recorded);
    if (file.empty()) return fmt::format("<span class=\"missing\" title=\"{}\">{}: missing</span>", attr(recorded), escape(label));
    return fmt::format("<a href=\"{}\">{}</a>", attr(relative_url(file)), escape(label));
  }

  static std::string join_nonempty(const std::vector<std::string>& parts, const char* sep) {
    std::string out;
    for (const std::string& p : parts)
      if (!p.empty()) out += (out.empty() ? "" : sep) + p;
    return out;
  }

  // Where a failing shader departs: the line, and both sources side by side with the
  // shader's line and the original's nearest one highlighted.
  static std::string departs(const CellResult::Divergence& d) {
    if (d.kind == "error") return fmt::format("<p class=\"note\"><b>departs</b>: not localised: {}</p>", escape(d.error));
    std::string h = fmt::format("<div class=\"departs\"><p><b>departs</b>: {}</p>", escape(d.text));
    const auto listing = [](const CellResult::Divergence::Excerpt& e, const std::string& title) {
      if (e.lines.empty()) return std::string();
      std::string pre = fmt::format("<pre title=\"{}\"><b>{}</b>\n", escape(e.file), escape(title + ": " + e.file));
      for (size_t i = 0; i < e.lines.size(); ++i) {
        const int line = e.first + int(i);
        const std::string text = fmt::format("<span class=\"ln\">{}</span>{}", line, escape(e.lines[i]));
        pre += line == e.mark ? "<span class=\"hit\">" + text + "</span>" : text + "\n";
      }
      return pre + "</pre>";
    };
    const std::string sources = listing(d.port_source, "shader") + listing(d.original_source, "original");
    if (!sources.empty()) h += "<div class=\"src\">" + sources + "</div>";
    return h + "</div>";
  }

  // A cell's card: its images first (reference or original | render | error, with the
  // error map's scale and a flicker toggle, zoom synchronised across the three), then what
  // it measured, the cells that failed the same way (`group`, when more than this one),
  // why it failed (collapsed: the message once, the attribution, every convention fit),
  // the other renders of its shape and every number. `headline_shown`: the message's
  // first line is already on the card's summary line.
  // reference | render | error (with its scale bar) of one cell.
  std::string trio_images(const CellResult& r) const {
    const CellArtefacts& a = r.artefacts;
    const std::string reference_caption = r.reference.kind == "render"   ? "original (" + escape(r.reference.label) + ")"
                                          : r.reference.kind == "images" ? std::string("stored image")
                                                                         : std::string("reference");
    const std::string scale = html_error_scale_bar(r);
    return image(a.reference_png, "reference", reference_caption, "reference") + image(a.render_png, "render", "render", "render") +
           image(a.error_png, "error map", scale.empty() ? "error" : "error " + scale, "error");
  }

  std::string card(size_t index, const std::vector<const CellResult*>* group = nullptr, bool headline_shown = false) const {
    const CellResult& r = report_.results[index];
    const CellMetrics& m = r.metrics;
    const CellArtefacts& a = r.artefacts;
    const std::string k = kind(r);
    const bool measured = r.status == CellStatus::pass || r.status == CellStatus::fail;
    std::string h = "<div class=\"card\">";

    const std::string imgs = trio_images(r);
    if (!imgs.empty())
      h += "<div class=\"trio\"><div class=\"imgs\">" + imgs +
           "</div><div class=\"tools\"><button type=\"button\" class=\"flicker\" title=\"show the reference in the "
           "render's place, and back\">flicker render / reference</button> <button type=\"button\" class=\"unzoom\">reset "
           "zoom</button> <small>click an image to zoom in (shift-click out, or the wheel); all three follow</small></div></div>";
    if (measured)
      h += fmt::format("<p class=\"measured\">max error <b>{}</b>{} &middot; threshold {} &middot; {} bad pixels &middot; "
                       "rmse {} &middot; psnr {} dB</p>",
                       sci(m.max_abs),
                       r.interior_threshold > 0 && std::isfinite(m.max_abs)
                           ? fmt::format(" ({:.3g}&times; the threshold)", m.max_abs / r.interior_threshold)
                           : std::string(),
                       escape(tolerance_text(r.interior_threshold, r.interior_threshold_rel)), m.bad_pixels, sci(m.rmse),
                       db(m.psnr));
    if (group && group->size() > 1) {
      h += fmt::format("<div class=\"group\" data-count=\"{}\"><b>{}</b><ul class=\"cells\">", group->size(),
                       escape(group_cells_text(*group)));
      // Each cell's images wait in a <template> (not loaded) until its "show" puts them in the trio.
      std::string templates;
      for (const CellResult* c : *group) {
        const size_t at = size_t(c - report_.results.data());
        const std::string its = imgs.empty() ? "" : trio_images(*c);
        h += fmt::format("<li{}>{}<a class=\"jump\" href=\"#c{}\">{} {}/{} {}</a> {}</li>", c == &r ? " class=\"shown\"" : "",
                         its.empty() ? "" : fmt::format("<button type=\"button\" class=\"pick\" data-cell=\"{}\">show</button> ", at),
                         at, escape(c->language), escape(c->backend), escape(c->path), escape(c->shape),
                         c->status == CellStatus::fail ? "max " + sci(c->metrics.max_abs) : std::string());
        if (!its.empty()) templates += fmt::format("<template data-cell=\"{}\">{}</template>", at, its);
      }
      h += "</ul>" + templates + "</div>";
    }
    if (r.known_failure)
      h += fmt::format("<p class=\"known\"><b>known failure</b>{}</p>",
                       r.known_reason.empty() ? "" : ": " + escape(r.known_reason));
    if (!r.reference_note.empty()) h += fmt::format("<p class=\"note\"><b>reference</b>: {}</p>", escape(r.reference_note));
    for (const std::string& w : r.warnings) h += fmt::format("<p class=\"note\"><b>warning</b>: {}</p>", escape(w));
    const std::string against = judged_against(r);
    if (!against.empty()) h += fmt::format("<p class=\"note\"><b>judged against</b>: {}</p>", escape(against));
    if (r.reference.is_reference) h += "<p class=\"note\"><b>this render is the reference</b> of its case</p>";

    // Why: collapsed behind one line, unless there are no images to look at first (an error).
    std::string why;
    const bool one_line = r.message.find('\n') == std::string::npos && r.message.size() <= 160;
    if (!r.message.empty() && !(headline_shown && one_line)) why += fmt::format("<pre class=\"msg\">{}</pre>", escape(r.message));
    if (!r.attribution.empty() || !r.attribution_reason.empty())
      why += fmt::format("<p class=\"attr\"><b>attribution: {}</b>{}</p>", escape(r.attribution.empty() ? "-" : r.attribution),
                         r.attribution_reason.empty() ? "" : " &mdash; " + escape(r.attribution_reason));
    // Which convention explains a failure: each fit with its residual, the fitting ones first.
    if (!r.explanations.empty()) {
      why += "<table class=\"kv\"><tr><th>convention</th><th>fits</th><th>residual</th><th>rmse</th></tr>";
      for (const Explanation& e : r.explanations)
        why += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>", escape(e.summary),
                           e.fits ? "<b>yes</b>" : "no", sci(e.residual), sci(e.rmse));
      why += "</table>";
    }
    if (r.divergence) why += departs(*r.divergence);
    if (!why.empty()) {
      std::string line = best_explanation(r);
      if (line.empty() && !r.explanations.empty()) line = fmt::format("no convention explains it ({} tried)", r.explanations.size());
      if (line.empty()) line = withheld_explanation(r);
      if (!r.attribution.empty()) line += (line.empty() ? "" : "; ") + ("attribution: " + r.attribution);
      h += fmt::format("<details class=\"why\"{}><summary><b>{}</b>{}</summary>{}</details>", imgs.empty() ? " open" : "",
                       k == "pass" ? "message" : "why", line.empty() ? "" : ": " + escape(line), why);
    }

    // Every render of this case/variant/shape, for failing cells: which ones agree.
    if (k != "pass" && k != "skipped") {
      std::string strip;
      for (size_t s : groups_.at(group_key(r))) {
        const CellResult& o = report_.results[s];
        if (s == index || o.artefacts.render_png.empty()) continue;
        strip += image(o.artefacts.render_png, "render " + o.language + " " + o.backend + "/" + o.path,
                       fmt::format("{} {}/{} <span class=\"st {}\">{}</span>", escape(o.language), escape(o.backend),
                                   escape(o.path), kind(o), status_label(kind(o))));
      }
      if (!strip.empty())
        h += fmt::format("<div class=\"sib\"><div class=\"lbl\">all renders of {}/{}/{}</div><div class=\"imgs small\">{}</div></div>",
                         escape(r.case_name), escape(r.variant), escape(r.shape), strip);
    }

    h += "<table class=\"kv\">";
    auto row = [&](const std::string& key, const std::string& value) {
      h += fmt::format("<tr><th>{}</th><td>{}</td></tr>", key, value);
    };
    if (r.status == CellStatus::pass || r.status == CellStatus::fail) {
      row("interior", fmt::format("max {} &nbsp; threshold {} &nbsp; smallest passing {} &nbsp; rmse {} &nbsp; psnr {} dB",
                                  sci(m.max_abs), escape(tolerance_text(r.interior_threshold, r.interior_threshold_rel)),
                                  sci(m.min_passing_interior), sci(m.rmse), db(m.psnr)));
      row("silhouette", fmt::format("max {} &nbsp; threshold {} &nbsp; smallest passing {}", sci(m.silhouette_max_abs),
                                    escape(tolerance_text(r.silhouette_threshold, r.silhouette_threshold_rel)),
                                    sci(m.min_passing_silhouette)));
      if (!r.tolerance_reason.empty()) row("tolerance", escape(r.tolerance_reason));
      row("pixels", fmt::format("{} bad, {} NaN/Inf in the render, {} NaN/Inf mismatches, {} coverage mismatches",
                                m.bad_pixels, m.nonfinite, m.nonfinite_mismatch, m.coverage_mismatch));
      row("coverage", fmt::format("{} drawn, {} in the reference, {:.1f} expected; {} interior, {} silhouette",
                                  m.covered_pixels, m.reference_covered_pixels, m.expected_area, m.interior_pixels,
                                  m.silhouette_pixels));
      for (const auto& [name, v] : {std::pair{"render values", &m.render_values}, std::pair{"reference values", &m.reference_values}})
        row(name, fmt::format("{} NaN, {} +Inf, {} -Inf, {} negative, {} above one", v->nan, v->pos_inf, v->neg_inf,
                              v->negative, v->above_one));
    }
    if (!r.lut_derivation.empty() || r.lut_bound != 0)
      row("LUT bound", fmt::format("{} &mdash; {}", sci(r.lut_bound), escape(r.lut_derivation)));
    if (!r.texel_derivation.empty())
      row("texel bound", fmt::format("{} &mdash; {}", sci(r.texel_bound), escape(r.texel_derivation)));
    if (r.sh)
      row("SH", fmt::format("{}; against the exact integral {} (the approximation's own {}{}), precompute {:.0f} ms, "
                            "{:.0f} bytes per vertex",
                            escape(r.sh->summary), sci(r.sh->render_vs_exact), sci(r.sh->truncation),
                            r.sh->bound >= 0 ? ", bound " + sci(r.sh->bound) : std::string(), r.sh->precompute_ms,
                            r.sh->bytes_per_vertex));
    for (const std::string& line : twin_lines(r)) {
      const size_t colon = line.find(": ");
      row(escape(line.substr(0, colon)), escape(line.substr(colon + 2)));
    }
    if (!r.time_ms.empty()) {
      std::vector<std::string> t;
      for (const auto& [stage, ms] : r.time_ms)
        t.push_back(fmt::format("{} {:.2f}{}", escape(stage), ms, shared_stage(stage) ? "*" : ""));
      row("time (ms)", join_nonempty(t, ", ") + " &nbsp;<small>(* shared by cells)</small>" +
                           (r.program_cached ? " &nbsp;<small>pipeline reused from an earlier cell</small>" : ""));
    }
    if (r.gpu.runs > 0)
      row("draw (ms)",
          fmt::format("wall {:.3f} [{:.3f}, {:.3f}], {} {:.3f} [{:.3f}, {:.3f}] &nbsp;<small>median [{:.0f}% CI] of {} "
                      "runs after {} warm-up</small>",
                      r.gpu.wall.median, r.gpu.wall.low, r.gpu.wall.high, escape(r.gpu.clock), r.gpu.device.median,
                      r.gpu.device.low, r.gpu.device.high, 100 * r.gpu.wall.level, r.gpu.runs, r.gpu.warmup));
    if (r.vertex_instructions + r.fragment_instructions > 0)
      row("SPIR-V instructions", fmt::format("vertex {}, fragment {}", r.vertex_instructions, r.fragment_instructions));
    if (!r.vertex_spirv_hash.empty() || !r.fragment_spirv_hash.empty())
      row("SPIR-V hash", fmt::format("vertex <code>{}</code> fragment <code>{}</code>", escape(r.vertex_spirv_hash),
                                     escape(r.fragment_spirv_hash)));
    const std::string sources =
        join_nonempty({source_link(a.vertex_spirv, "vertex SPIR-V"), source_link(a.fragment_spirv, "fragment SPIR-V"),
                       source_link(a.vertex_cross_glsl, "vertex GLSL (SPIRV-Cross)"),
                       source_link(a.fragment_cross_glsl, "fragment GLSL (SPIRV-Cross)")},
                      " &middot; ");
    if (!sources.empty()) row("sources", sources);
    const std::string files = join_nonempty({file_link(a.render_exr, "render.exr"), file_link(a.error_exr, "error.exr"),
                                             file_link(a.render_png, "render.png"), file_link(a.error_png, "error.png"),
                                             file_link(a.reference_png, "reference.png")},
                                            " &middot; ");
    if (!files.empty()) row("files", files + " &nbsp;<small>(in the run's folder)</small>");
    row("id", "<code>" + escape(r.id()) + "</code>");
    h += "</table></div>";
    return h;
  }

  std::string table_row(size_t i) const {
    const CellResult& r = report_.results[i];
    const CellMetrics& m = r.metrics;
    const std::string k = kind(r);
    const bool measured = r.status == CellStatus::pass || r.status == CellStatus::fail;
    auto num = [&](double v, bool shown) {
      return shown ? fmt::format("<td class=\"n\" data-v=\"{}\">{}</td>", sort_value(v), sci(v)) : "<td class=\"n\" data-v=\"\">-</td>";
    };
    // data-id "/case/variant/lang/backend/path/shape/": the matrix links filter on its prefixes.
    std::string h =
        fmt::format("<tbody class=\"cell {}\" id=\"c{}\" data-i=\"{}\" data-id=\"{}\"{}><tr class=\"row\" tabindex=\"0\">", k,
                    i, i, attr("/" + r.id() + "/"), collapsed() ? " hidden" : "");
    h += fmt::format("<td class=\"n\" data-v=\"{}\">{}</td>", i, i + 1);
    for (const std::string* s : {&r.case_name, &r.variant, &r.language, &r.backend, &r.path, &r.shape})
      h += "<td>" + escape(*s) + "</td>";
    h += fmt::format("<td data-v=\"{}\"><span class=\"st {}\">{}</span></td>", status_rank(k), k, status_label(k));
    h += num(m.max_abs, measured);
    h += num(r.interior_threshold, measured);
    h += num(m.min_passing_interior, measured);
    h += num(m.silhouette_max_abs, measured);
    h += num(m.rmse, measured);
    h += measured ? fmt::format("<td class=\"n\" data-v=\"{}\">{}</td>", sort_value(m.psnr), db(m.psnr))
                  : "<td class=\"n\" data-v=\"\">-</td>";
    h += "<td>" + escape(r.attribution) + "</td>";
    h += fmt::format("<td class=\"n\" data-v=\"{}\">{:.1f}</td>", sort_value(own_ms(r)), own_ms(r));
    // The card comes from the page's card store when the row is opened (see page()).
    h += fmt::format("</tr><tr class=\"detail\" hidden><td colspan=\"{}\" data-card=\"{}\"></td></tr></tbody>\n",
                     kColumns, i);
    return h;
  }

  static constexpr int kColumns = 16;

  // Laying out a table's rows is most of what a browser spends on a big page (1400 rows:
  // seconds), so above this many cells the table starts with no row shown until a matrix
  // link, a filter or "show all" asks for rows.
  static constexpr size_t kCollapseAbove = 250;
  bool collapsed() const { return report_.results.size() > kCollapseAbove; }

  // A link that shows the table's cells under `prefix`, e.g. "/phong/pixel/" (see data-id).
  static std::string filter_link(const std::string& prefix, const std::string& text, const std::string& title) {
    return fmt::format("<a class=\"mxl\" href=\"#filter={}&amp;status=\" title=\"{}\">{}</a>", attr(url_path(prefix)),
                       attr(title), text);
  }

  // The summary matrix (report/SummaryMatrix), as the console prints it; every count links
  // to its cells in the table.
  std::string matrix_section() const {
    const SummaryMatrix m = build_summary_matrix(report_);
    if (m.rows.empty()) return "";
    std::string h = "<section id=\"matrix\"><h2>Summary</h2>\n<table class=\"matrix\"><thead>";
    // Header rows: language, backend, path, each spanning its run of equal columns.
    auto spans = [&](auto&& name, auto&& same) {
      std::string row;
      for (size_t c = 0; c < m.columns.size();) {
        size_t n = 1;
        while (c + n < m.columns.size() && same(m.columns[c], m.columns[c + n])) ++n;
        row += fmt::format("<th{}>{}</th>", n > 1 ? fmt::format(" colspan=\"{}\"", n) : "", escape(name(m.columns[c])));
        c += n;
      }
      return row;
    };
    auto same_language = [](const MatrixColumn& a, const MatrixColumn& b) { return a.language == b.language; };
    auto same_backend = [](const MatrixColumn& a, const MatrixColumn& b) {
      return a.language == b.language && a.backend == b.backend;
    };
    h += "<tr><th class=\"rh\" rowspan=\"3\">case</th><th class=\"rh\" rowspan=\"3\">variant</th>" +
         spans([](const MatrixColumn& c) { return c.language; }, same_language) +
         "<th rowspan=\"3\" title=\"the row's largest interior error\">worst<br>max err</th>"
         "<th rowspan=\"3\" title=\"the row's largest interior error as a share of its cell's threshold\">of tol</th></tr>\n";
    h += "<tr>" + spans([](const MatrixColumn& c) { return c.backend; }, same_backend) + "</tr>\n";
    h += "<tr>" + spans([](const MatrixColumn& c) { return c.path; }, [](auto&&, auto&&) { return false; }) +
         "</tr></thead>\n<tbody>";
    for (size_t r = 0; r < m.rows.size(); ++r) {
      const MatrixRow& row = m.rows[r];
      const std::string base = "/" + row.case_name + "/" + row.variant + "/";
      h += "<tr>";
      h += "<td class=\"rh\">" +
           (r == 0 || m.rows[r - 1].case_name != row.case_name
                ? filter_link("/" + row.case_name + "/", escape(row.case_name), "every cell of " + row.case_name)
                : std::string()) +
           "</td>";
      h += "<td class=\"rh\">" +
           filter_link(base, escape(row.variant), "every cell of " + row.case_name + "/" + row.variant) + "</td>";
      for (size_t c = 0; c < row.cells.size(); ++c) {
        const MatrixCell& cell = row.cells[c];
        if (cell.empty()) {
          h += "<td class=\"mx none\">-</td>";
          continue;
        }
        const MatrixColumn& col = m.columns[c];
        const char* k = cell.failed ? "fail" : cell.errors ? "error" : cell.known ? "known"
                        : cell.skipped == cell.total ? "skipped" : "pass";
        std::string title = fmt::format("{} {} {}: {} of {} passed", row.case_name, row.variant, col.label(), cell.passed,
                                        cell.total);
        for (const auto& [n, what] :
             {std::pair{cell.failed, "failed"}, std::pair{cell.known, "known failures"}, std::pair{cell.errors, "errors"},
              std::pair{cell.skipped, "skipped"}})
          if (n) title += fmt::format(", {} {}", n, what);
        const std::string cells = base + col.language + "/" + col.backend + "/" + col.path + "/";
        h += fmt::format("<td class=\"mx {}\">{}</td>", k, filter_link(cells, escape(cell.text()), title));
      }
      h += fmt::format("<td class=\"n\">{}</td><td class=\"n\">{}</td></tr>\n", row.measured ? sci(row.worst_max_abs) : "-",
                       row.measured ? escape(percent_of_threshold(row.worst_of_threshold)) : "-");
    }
    h += "</tbody></table>\n<p class=\"policy\">shapes passed of those run; <b>!</b> a new failure or error, <b>*</b> "
         "known failures only. Click a count to show its cells in the table below.</p></section>\n";
    return h;
  }

  std::string charts_section() const {
    if (options_.charts.empty()) return "";
    std::string h = "<section id=\"charts\"><h2>Speed against error</h2>\n";
    for (const HtmlChart& c : options_.charts)
      h += fmt::format("<figure class=\"chart\"><figcaption><b>{}</b> {}</figcaption>\n{}\n</figure>\n", escape(c.title),
                       escape(c.caption), c.svg);
    return h + "</section>\n";
  }

  // Cells that failed the same way (report/CellGroups.h failure_key) share one card: its
  // first cell's images and numbers, and the list of all of them.
  std::string failure_section(const char* k, const char* title, size_t open_limit) const {
    const auto& cards = failure_cards_.at(k);
    if (cards.empty()) return "";
    size_t cells = 0;
    for (const FailureCard& c : cards) cells += c.cells.size();
    std::string h = fmt::format("<section class=\"fails\" id=\"sec-{}\"><h2>{} ({}{})</h2>\n", k, title, cells,
                                cards.size() < cells ? fmt::format(", in {} card{}", cards.size(), cards.size() == 1 ? "" : "s") : "");
    for (size_t n = 0; n < cards.size(); ++n) {
      const FailureCard& c = cards[n];
      const CellResult& r = *c.cells.front();
      const size_t i = size_t(&r - report_.results.data());
      const bool open = n < open_limit;
      std::string headline = r.message.substr(0, r.message.find('\n'));
      if (headline.size() > 160) headline = headline.substr(0, 157) + "...";
      const std::string who = c.cells.size() == 1 ? r.case_name + " " + r.variant + " " + r.language : group_where(c.cells);
      const std::string where =
          c.cells.size() == 1 ? r.backend + "/" + r.path + " " + r.shape : fmt::format("{} cells", c.cells.size());
      h += fmt::format(
          "<details class=\"fc\" id=\"f{}\" data-count=\"{}\"{}><summary><span class=\"st {}\">{}</span> <b>{}</b> {} "
          "&nbsp;<span class=\"why\">{}{}</span> <a class=\"jump\" href=\"#c{}\">table&nbsp;row</a></summary>{}</details>\n",
          i, c.cells.size(),
          open                 ? std::string(" open")
          : c.cells.size() > 1 ? fmt::format(" data-group=\"{}\"", c.store)
                               : fmt::format(" data-card=\"{}\"", i),
          k, status_label(k), escape(who), escape(where), escape(headline),
          r.attribution.empty() ? "" : " &mdash; " + escape(r.attribution), i, open ? card(i, &c.cells, true) : "");
    }
    return h + "</section>\n";
  }

  std::string page() const {
    const ToolVersions& t = report_.tools;
    size_t known = 0;
    for (const CellResult& r : report_.results) known += kind(r) == "known";
    const size_t fails = report_.count(CellStatus::fail) - known;
    auto unknown = [](const std::string& s) { return s.empty() ? std::string("<i>unknown</i>") : escape(s); };

    std::string h;
    h.reserve(summary_.image_bytes + report_.results.size() * 4096 + 65536);
    h += "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data: file: 'self'; "
         "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n";
    h += fmt::format("<title>shaderbed: {} passed, {} failed, {} known, {} errors</title>\n", report_.count(CellStatus::pass), fails,
                     known, report_.count(CellStatus::error));
    // A blank line before the style and the script, as the page has always had.
    h += "<style>\n\n" + std::string(report_assets::report_css) + "</style>\n</head>\n";
    h += fmt::format("<body data-cells=\"{}\" data-images-ready=\"pending\">\n", report_.results.size());
    h += "<header><h1>shaderbed report</h1>\n<div class=\"totals\">";
    h += fmt::format("<span class=\"tot\"><b>{}</b> cells</span>", report_.results.size());
    h += fmt::format("<span class=\"tot st pass\"><b>{}</b> passed</span>", report_.count(CellStatus::pass));
    h += fmt::format("<span class=\"tot st fail\"><b>{}</b> failed</span>", fails);
    h += fmt::format("<span class=\"tot st known\"><b>{}</b> known failures</span>", known);
    h += fmt::format("<span class=\"tot st error\"><b>{}</b> errors</span>", report_.count(CellStatus::error));
    if (const size_t skipped = report_.count(CellStatus::skipped))
      h += fmt::format("<span class=\"tot st skipped\"><b>{}</b> skipped</span>", skipped);
    h += fmt::format("<span class=\"tot\">{:.1f} s</span>", report_.wall_ms / 1000.0);
    h += fmt::format("<span class=\"verdict {}\">{}</span>", report_.acceptable() ? "ok" : "bad",
                     report_.acceptable() ? "acceptable" : "NOT acceptable");
    h += "</div>\n<table class=\"kv tools\">";
    h += fmt::format("<tr><th>glslang</th><td>{}</td><th>SPIRV-Tools</th><td>{}</td><th>SPIRV-Cross</th><td>{}</td></tr>",
                     unknown(t.glslang), unknown(t.spirv_tools), unknown(t.spirv_cross));
    h += fmt::format("<tr><th>Mesa (Vulkan)</th><td>{}</td><th>Mesa (GL)</th><td>{}</td><th>LLVM</th><td>{}</td></tr>",
                     unknown(t.vulkan_driver), unknown(t.gl_driver), unknown(t.llvm));
    h += fmt::format("<tr><th>shard</th><td>{}</td><th>run folder</th><td colspan=\"3\"><code>{}</code></td></tr>",
                     report_.shard.empty() ? "whole run" : escape(report_.shard), escape(report_.out_dir));
    h += "</table>\n";
    h += fmt::format(
        "<p class=\"policy\">Images: {} embedded ({:.1f} MB), {} linked to the run's files, {} missing. Embedded first: "
        "failing cells, one passing example per case/variant, other renders of failing shapes, then the rest while the budget lasts. Error maps are in "
        "false colour from 0 to the cell's worst interior error (or its threshold), with the scale under each. Click a "
        "table header to sort, a row for details, an image to zoom (the three images of a card zoom together).{}{}</p>\n",
        summary_.images_embedded, summary_.image_bytes / 1048576.0, summary_.images_linked, summary_.images_missing,
        report_.keep_images == "failing" ? " The run kept the images of the cells that did not pass only "
                                           "(<code>--keep-images all</code> keeps every cell's)."
        : report_.keep_images == "none"  ? " The run kept no images (<code>--keep-images none</code>)."
                                         : "",
        summary_.sources_not_copied ? fmt::format(" {} shader source{} could not be copied into the report (no link).",
                                                  summary_.sources_not_copied, summary_.sources_not_copied == 1 ? "" : "s")
                                    : "");
    for (const std::string& note : options_.notes) h += fmt::format("<p class=\"note\">{}</p>\n", escape(note));
    std::string nav;
    for (const auto& [k, title] : {std::pair{"fail", "failures"}, std::pair{"error", "errors"}, std::pair{"known", "known failures"},
                                  std::pair{"skipped", "skipped"}}) {
      size_t n = 0;
      for (const CellResult& r : report_.results) n += kind(r) == k;
      if (n) nav += fmt::format("<a href=\"#sec-{}\">{} ({})</a>", k, title, n);
    }
    if (!options_.charts.empty()) nav = "<a href=\"#charts\">speed against error</a>" + nav;
    if (!report_.results.empty()) nav = "<a href=\"#matrix\">summary</a>" + nav;
    h += "<nav>" + nav + "<a href=\"#all\">all cells</a></nav>\n";
    h += "</header>\n<main>\n";
    h += matrix_section();
    h += charts_section();

    h += failure_section("fail", "Failures", 40);
    h += failure_section("error", "Errors", 20);
    h += failure_section("known", "Known failures", 0);
    h += failure_section("skipped", "Skipped: the path does not apply to the shader", 0);

    h += "<section id=\"all\"><h2>All cells</h2>\n<div class=\"filters\"><input id=\"filter\" type=\"search\" "
         "placeholder=\"filter: text in any column\" size=\"40\"> <select id=\"status\"><option value=\"\">all</option>"
         "<option value=\"failing\">not passing</option><option value=\"fail\">failed</option><option "
         "value=\"known\">known</option><option value=\"error\">errors</option><option value=\"skipped\">skipped</option><option value=\"pass\">passed</option>"
         "</select> <span id=\"shown\"></span> <button id=\"expand\" type=\"button\">expand shown</button> <button "
         "id=\"collapse\" type=\"button\">collapse all</button></div>\n";
    if (collapsed())
      h += fmt::format("<p id=\"collapsed\">{} cells: click a count in the summary, filter, or <button id=\"showall\" "
                       "type=\"button\">show all</button></p>\n",
                       report_.results.size());
    h += fmt::format("<table id=\"cells\"{}><thead><tr>", collapsed() ? " data-collapsed=\"1\"" : "");
    const char* const cols[kColumns][3] = {
        {"index", "num", "#"},          {"case", "str", "case"},       {"variant", "str", "variant"},
        {"language", "str", "lang"},    {"backend", "str", "backend"}, {"path", "str", "path"},
        {"shape", "str", "shape"},      {"status", "num", "status"},   {"max_abs", "num", "max err"},
        {"threshold", "num", "threshold"}, {"min_passing", "num", "min passing"}, {"silhouette", "num", "silh. err"},
        {"rmse", "num", "rmse"},        {"psnr", "num", "psnr"},       {"attribution", "str", "attribution"},
        {"ms", "num", "ms"}};
    for (const auto& c : cols) {
      const std::string key = c[0];
      const char* title = key == "max_abs"       ? "largest interior error"
                          : key == "threshold"   ? "the case's interior threshold (with the LUT bound for LUT variants)"
                          : key == "min_passing" ? "the smallest interior threshold that would have passed"
                          : key == "silhouette"  ? "largest silhouette-band error"
                          : key == "psnr"        ? "interior PSNR in dB, peak 1"
                          : key == "ms"          ? "this cell's own time: build, draw, readback, compare"
                                                 : "";
      h += fmt::format("<th data-key=\"{}\" data-type=\"{}\" tabindex=\"0\"{}>{}</th>", c[0], c[1],
                       *title ? fmt::format(" title=\"{}\"", title) : "", c[2]);
    }
    h += "</tr></thead>\n";
    for (size_t i = 0; i < report_.results.size(); ++i) h += table_row(i);
    h += "</table></section>\n</main>\n";

    // The image store: each distinct PNG once, set on <img data-img> when its card is shown.
    h += "<script type=\"application/json\" id=\"sb-images\">{";
    for (size_t i = 0; i < store_.size(); ++i)
      h += fmt::format("{}\"{}\":\"{}\"", i ? ",\n" : "", store_[i].first, store_[i].second);
    h += "}</script>\n";
    // Every cell's card, as HTML in a JSON array, put into the page when it is opened:
    // thousands of hidden cards would otherwise be parsed into the DOM on load.
    h += "<script type=\"application/json\" id=\"sb-cards\">[";
    for (size_t i = 0; i < report_.results.size(); ++i) h += (i ? ",\n" : "") + markup::script_json_string(card(i));
    h += "]</script>\n";
    // The cards of failures that several cells share, put into the page when opened.
    h += "<script type=\"application/json\" id=\"sb-groups\">[";
    bool first = true;
    for (const char* k : {"fail", "error", "known", "skipped"})
      for (const FailureCard& c : failure_cards_.at(k))
        if (c.store >= 0) {
          h += (first ? "" : ",\n") +
               markup::script_json_string(card(size_t(c.cells.front() - report_.results.data()), &c.cells, true));
          first = false;
        }
    h += "]</script>\n<script>\n\n" + std::string(report_assets::report_js) + "</script>\n</body></html>\n";
    return h;
  }

  const RunReport& report_;
  fs::path dir_;
  HtmlOptions options_;
  HtmlSummary summary_;
  size_t budget_ = 0;
  std::map<std::string, std::vector<size_t>> groups_;
  struct FailureCard {
    std::vector<const CellResult*> cells;   // failed the same way, in run order
    int store = -1;                         // its card's place in the page's group store (more than one cell)
  };
  std::map<std::string, std::vector<FailureCard>> failure_cards_;   // by kind()
  std::set<std::string> considered_;
  std::map<std::string, std::string> embedded_;   // recorded path -> store key
  std::vector<std::pair<std::string, std::string>> store_;   // key, data URI
  std::map<std::string, std::string> sources_;    // recorded path -> relative URL ("" = missing)
};

}  // namespace

Result<HtmlSummary> write_html(const RunReport& report, const std::string& dir, const HtmlOptions& options) {
  return Writer(report, dir, options).write();
}

Result<void> write_html(const RunReport& report, const std::string& dir) {
  auto summary = write_html(report, dir, HtmlOptions{});
  if (!summary) return std::unexpected(summary.error());
  return {};
}

}  // namespace shaderbed
