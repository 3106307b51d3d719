#include "report/ConsoleProblems.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "report/CellExplanation.h"
#include "report/CellGroups.h"
#include "report/ConsoleColour.h"
#include "report/ConsoleWrap.h"
#include "report/FirstLine.h"
#include "report/TwinText.h"

namespace shaderbed {
namespace {

std::string where(const CellResult& r) {
  return fmt::format("{} {} {} {}/{} {}", r.case_name, r.variant, r.language, r.backend, r.path, r.shape);
}

void print_images(const CellResult& r, std::FILE* out) {
  const CellArtefacts& a = r.artefacts;
  const std::string& render = a.render_png.empty() ? a.render_exr : a.render_png;
  const std::string& error = a.error_png.empty() ? a.error_exr : a.error_png;
  if (!render.empty()) fmt::print(out, "      render: {}\n", render);
  if (!error.empty()) fmt::print(out, "      error:  {}\n", error);
  if (!a.reference_png.empty()) fmt::print(out, "      ref:    {}\n", a.reference_png);
}

size_t known_failures(const RunReport& report) {
  size_t n = 0;
  for (const CellResult& r : report.results) n += r.status == CellStatus::fail && r.known_failure;
  return n;
}

// Passing cells too. A case's warning repeats on every backend, path and shape of its
// language, so each distinct one is printed once per case/variant/language with a count.
bool print_warnings(const RunReport& report, std::FILE* out, bool blank_line_first) {
  std::vector<std::pair<std::string, size_t>> lines;   // in first-seen order
  for (const CellResult& r : report.results)
    for (const std::string& w : r.warnings) {
      const std::string line = fmt::format("{} {} {}: {}", r.case_name, r.variant, r.language, w);
      auto it = std::find_if(lines.begin(), lines.end(), [&](const auto& l) { return l.first == line; });
      if (it == lines.end()) lines.emplace_back(line, 1);
      else ++it->second;
    }
  if (lines.empty()) return false;
  fmt::print(out, "{}warnings:\n", blank_line_first ? "\n" : "");
  for (const auto& [line, cells] : lines) fmt::print(out, "  {} ({} cell{})\n", line, cells, cells == 1 ? "" : "s");
  return true;
}

// One entry of a section: what the cells share (their message, then detail lines each
// starting with the 6-space indent), for one cell or a group of cells.
struct EntryText {
  std::string message;
  std::vector<std::string> details;
};

constexpr const char* kIndent = "      ";

// The entry for `cells` (one or a group): "  where: message", for a group the cells it
// covers on the next line, then the details of `shown` (the group's cell whose text is
// printed) and its images.
void print_entry(const std::vector<const CellResult*>& cells, const CellResult& shown, const EntryText& text, bool images,
                 std::FILE* out) {
  const std::string who = cells.size() == 1 ? where(*cells.front()) : group_where(cells);
  fmt::print(out, "  {}: {}\n", who, fold_for_console(text.message, who.size() + 4, kIndent));
  if (cells.size() > 1) fmt::print(out, "{}{}\n", kIndent, fold_for_console(group_cells_text(cells), 6, kIndent));
  for (const std::string& line : text.details) fmt::print(out, "{}{}\n", kIndent, fold_for_console(line, 6, kIndent));
  if (images) print_images(shown, out);
}

// The cells of a failure group that measure differently are shown by their worst (the
// largest interior error): the figures printed are then the group's bound.
const CellResult& worst_of(const std::vector<const CellResult*>& cells) {
  return **std::ranges::max_element(cells, {}, [](const CellResult* r) { return r->metrics.max_abs; });
}

EntryText failure_text(const CellResult& r) {
  EntryText t{r.message.empty() ? "failed" : first_line(r.message), {}};
  t.details.push_back(fmt::format("attribution: {}{}", r.attribution.empty() ? "none" : r.attribution,
                                  r.attribution_reason.empty() ? "" : " - " + r.attribution_reason));
  if (const std::string best = best_explanation(r); !best.empty())
    t.details.push_back("explained: " + best);
  else if (!r.explanations.empty())
    t.details.push_back("no convention explains it; closest: " + r.explanations.front().summary);
  else if (const std::string withheld = withheld_explanation(r); !withheld.empty())
    t.details.push_back("no convention offered: " + withheld);
  if (const auto& d = r.divergence) t.details.push_back("departs: " + (d->kind == "error" ? "not localised: " + d->error : d->text));
  if (const std::string against = judged_against(r); !against.empty()) t.details.push_back("judged against: " + against);
  if (!r.reference_note.empty()) t.details.push_back("reference: " + r.reference_note);
  for (std::string& line : twin_lines(r)) t.details.push_back(std::move(line));
  return t;
}

EntryText known_text(const CellResult& r) {
  EntryText t{r.message.empty() ? "failed" : first_line(r.message), {}};
  t.details.push_back("known: " + (r.known_reason.empty() ? std::string("(no reason given)") : r.known_reason));
  if (!r.attribution.empty()) t.details.push_back("attribution: " + r.attribution);
  return t;
}

}  // namespace

bool print_problems(const RunReport& report, std::FILE* out, bool blank_line_first, bool colour) {
  bool printed = false;
  // Cells whose entry reads the same but for their own identity are printed once, with
  // the cells it stands for (report/CellGroups.h); failures also when only their numbers
  // differ.
  auto section = [&](const char* title, Tint tint, auto&& wanted, auto&& text_of, bool images, bool by_failure = false) {
    std::vector<const CellResult*> cells;
    for (const CellResult& r : report.results)
      if (wanted(r)) cells.push_back(&r);
    if (cells.empty()) return;
    fmt::print(out, "{}{}:\n", printed || blank_line_first ? "\n" : "", tinted(title, tint, colour));
    printed = true;
    const auto key_of = [&](const CellResult& r) {
      const EntryText t = text_of(r);
      std::string key = t.message;
      for (const std::string& line : t.details) key += "\n" + line;
      return without_cell_identity(key, r);
    };
    // Failures group as the HTML report's cards do (failure_key: the numbers taken out).
    const auto groups = by_failure ? group_cells(cells, [](const CellResult& r) { return failure_key(r); })
                                   : group_cells(cells, key_of);
    for (const auto& group : groups) {
      const CellResult& shown = by_failure ? worst_of(group) : *group.front();
      EntryText text = text_of(shown);
      const std::string shown_key = key_of(shown);
      const bool differ = std::ranges::any_of(group, [&](const CellResult* r) { return key_of(*r) != shown_key; });
      if (differ) text.details.insert(text.details.begin(), "figures: the worst of them, " + where(shown));
      print_entry(group, shown, text, images, out);
    }
  };
  const auto message_only = [](const CellResult& r) { return EntryText{r.message, {}}; };
  const auto reason_only = [](const CellResult& r) { return EntryText{r.known_reason, {}}; };
  section("failures", Tint::fail, [](const CellResult& r) { return r.status == CellStatus::fail && !r.known_failure; },
          failure_text, true, true);
  section("errors", Tint::warn, [](const CellResult& r) { return r.status == CellStatus::error; }, message_only, false);
  section("known", Tint::warn, [](const CellResult& r) { return r.status == CellStatus::fail && r.known_failure; }, known_text,
          false);
  section("skipped (the path does not apply to the shader)", Tint::none,
          [](const CellResult& r) { return r.status == CellStatus::skipped; }, message_only, false);
  section("known failures that passed (remove them from the expectations)", Tint::warn,
          [](const CellResult& r) { return r.status == CellStatus::pass && r.known_failure; }, reason_only, false);
  print_warnings(report, out, printed || blank_line_first) && (printed = true);
  return printed;
}

void print_totals(const RunReport& report, std::FILE* out, bool colour) {
  const size_t known = known_failures(report);
  const size_t skipped = report.count(CellStatus::skipped);
  if (report.interruption)
    fmt::print(out, "INCOMPLETE: {}; the cells below are those it finished\n", report.interruption->reason);
  const std::string totals = fmt::format(
      "{}{} cells: {} passed, {} failed, {} known, {} errors{} in {:.1f} s",
      report.interruption ? "INCOMPLETE: " : report.acceptable() ? "" : "FAIL: ", report.results.size(),
      report.count(CellStatus::pass), report.count(CellStatus::fail) - known, known, report.count(CellStatus::error),
      skipped ? fmt::format(", {} skipped", skipped) : "", report.wall_ms / 1000.0);
  const Tint verdict = report.interruption ? Tint::warn : report.acceptable() ? Tint::pass : Tint::fail;
  fmt::print(out, "{}\n", tinted(totals, verdict, colour));
}

}  // namespace shaderbed
