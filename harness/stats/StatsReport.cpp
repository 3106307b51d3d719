#include "stats/StatsReport.h"
#include "core/AtomicFile.h"
#include "core/BoundedFile.h"

#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace shaderbed::stats {
namespace {

using json = nlohmann::ordered_json;

json counts_json(const ClassCounts& c) {
  json j = {{"total", c.total},         {"arithmetic", c.arithmetic}, {"extended", c.extended},
            {"texture", c.texture},     {"control", c.control},       {"memory", c.memory},
            {"conversion", c.conversion}, {"other", c.other}};
  j["extended_calls"] = json::object();
  for (const auto& [name, n] : c.extended_calls) j["extended_calls"][name] = n;
  return j;
}

ClassCounts counts_from(const json& j) {
  ClassCounts c;
  if (!j.is_object()) return c;
  c.total = j.value("total", 0);
  c.arithmetic = j.value("arithmetic", 0);
  c.extended = j.value("extended", 0);
  c.texture = j.value("texture", 0);
  c.control = j.value("control", 0);
  c.memory = j.value("memory", 0);
  c.conversion = j.value("conversion", 0);
  c.other = j.value("other", 0);
  if (j.contains("extended_calls") && j["extended_calls"].is_object())
    for (const auto& [name, n] : j["extended_calls"].items()) c.extended_calls[name] = n.get<int>();
  return c;
}

json nir_counts_json(const std::optional<NirCounts>& n) {
  if (!n) return nullptr;
  return {{"alu", n->alu}, {"tex", n->tex}, {"control", n->control}};
}

std::optional<NirCounts> nir_counts_from(const json& j) {
  if (!j.is_object()) return std::nullopt;
  return NirCounts{j.value("alu", 0), j.value("tex", 0), j.value("control", 0)};
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

}  // namespace

std::string to_json(const StatsReport& report) {
  json j;
  j["tools"] = json::object();
  for (const auto& [k, v] : report.tool) j["tools"][k] = v;
  j["entries"] = json::array();
  for (const StatsEntry& e : report.entries) {
    json x = {{"case", e.case_name}, {"variant", e.variant}, {"language", e.language}, {"stage", e.stage}};
    x["spirv"] = counts_json(e.spirv);
    x["spirv_opt"] = counts_json(e.spirv_opt);
    x["spirv_os"] = counts_json(e.spirv_os);
    x["glsl_lines"] = e.glsl_lines;
    if (e.nir) {
      x["nir"] = {{"vulkan", nir_counts_json(e.nir->vulkan)}, {"gl", nir_counts_json(e.nir->gl)}};
      if (!e.nir->note.empty()) x["nir"]["note"] = e.nir->note;
    } else {
      x["nir"] = nullptr;
    }
    x["book"] = e.book ? json(*e.book) : json(nullptr);
    if (!e.error.empty()) x["error"] = e.error;
    j["entries"].push_back(std::move(x));
  }
  return j.dump(2) + "\n";
}

Result<StatsReport> from_json(const std::string& text) {
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("entries") || !j["entries"].is_array())
    return fail(ErrorStage::stats, "not a `shaderbed stats --json` file (no \"entries\" array)");
  StatsReport r;
  // "tools", as every JSON shaderbed writes; "tool" in baselines written before.
  const char* tools = j.contains("tools") ? "tools" : "tool";
  if (j.contains(tools) && j[tools].is_object())
    for (const auto& [k, v] : j[tools].items())
      if (v.is_string()) r.tool[k] = v.get<std::string>();
  try {
    for (const json& x : j["entries"]) {
      StatsEntry e;
      e.case_name = x.at("case").get<std::string>();
      e.variant = x.at("variant").get<std::string>();
      e.language = x.at("language").get<std::string>();
      e.stage = x.at("stage").get<std::string>();
      e.spirv = counts_from(x.value("spirv", json()));
      e.spirv_opt = counts_from(x.value("spirv_opt", json()));
      e.spirv_os = counts_from(x.value("spirv_os", json()));
      e.glsl_lines = x.value("glsl_lines", 0);
      if (x.contains("nir") && x["nir"].is_object()) {
        NirStats n;
        n.vulkan = nir_counts_from(x["nir"].value("vulkan", json()));
        n.gl = nir_counts_from(x["nir"].value("gl", json()));
        n.note = x["nir"].value("note", "");
        e.nir = n;
      }
      if (x.contains("book") && x["book"].is_number_integer()) e.book = x["book"].get<int>();
      e.error = x.value("error", "");
      r.entries.push_back(std::move(e));
    }
  } catch (const json::exception& ex) {
    return fail(ErrorStage::stats, std::string("bad entry: ") + ex.what());
  }
  return r;
}

Result<StatsReport> read_stats_json(const std::string& path) {
  // A regular file of bounded size only: `--baseline /dev/zero` or a FIFO is one error.
  Result<std::string> text = read_bounded_file(path, "stats JSON", ErrorStage::stats, kMaxStatsBytes);
  if (!text) return std::unexpected(text.error());
  auto r = from_json(*text);
  if (!r) return std::unexpected(std::move(r.error()).in_file(path));
  return r;
}

Result<void> write_text_file(const std::string& path, const std::string& text) {
  if (auto ok = write_file_atomically(path, text, "the file"); !ok)
    return std::unexpected(Error(ok.error()).in_stage(ErrorStage::stats));
  return {};
}

std::string to_csv(const StatsReport& report) {
  std::string out = "case,variant,language,stage";
  for (const char* form : {"spirv", "spirv_opt", "spirv_os"})
    for (const char* cls : {"total", "arithmetic", "extended", "texture", "control", "memory", "conversion", "other"})
      out += fmt::format(",{}_{}", form, cls);
  out += ",extended_calls,glsl_lines,nir_vulkan_alu,nir_vulkan_tex,nir_vulkan_control,nir_gl_alu,nir_gl_tex,"
         "nir_gl_control,book,error\n";
  for (const StatsEntry& e : report.entries) {
    out += fmt::format("{},{},{},{}", csv_field(e.case_name), csv_field(e.variant), e.language, e.stage);
    for (const ClassCounts* c : {&e.spirv, &e.spirv_opt, &e.spirv_os})
      out += fmt::format(",{},{},{},{},{},{},{},{}", c->total, c->arithmetic, c->extended, c->texture, c->control,
                         c->memory, c->conversion, c->other);
    std::string calls;
    for (const auto& [name, n] : e.spirv_opt.extended_calls) calls += fmt::format("{}{}:{}", calls.empty() ? "" : " ", name, n);
    out += "," + csv_field(calls) + fmt::format(",{}", e.glsl_lines);
    auto nir = [&](const std::optional<NirCounts>& n) {
      return n ? fmt::format(",{},{},{}", n->alu, n->tex, n->control) : std::string(",,,");
    };
    out += nir(e.nir ? e.nir->vulkan : std::nullopt) + nir(e.nir ? e.nir->gl : std::nullopt);
    out += "," + (e.book ? std::to_string(*e.book) : std::string()) + "," + csv_field(e.error) + "\n";
  }
  return out;
}

namespace {

// Entries grouped by case/variant/stage in entry order, the languages present in a fixed order.
struct TableRows {
  std::vector<std::string> languages, rows;
  std::map<std::string, std::map<std::string, const StatsEntry*>> by_row;
};

// Calls row(name, cells) for each row in order, with a blank line in `out` between cases.
template <class Row>
void for_each_row(const TableRows& t, std::string& out, Row&& row) {
  std::string last_case;
  for (const std::string& r : t.rows) {
    const auto& cells = t.by_row.at(r);
    const std::string& case_name = cells.begin()->second->case_name;
    if (!last_case.empty() && case_name != last_case) out += "\n";
    last_case = case_name;
    row(r, cells);
  }
}

TableRows table_rows(const StatsReport& report) {
  TableRows t;
  for (const char* l : {"hlsl", "cg", "glsl"})
    for (const StatsEntry& e : report.entries)
      if (e.language == l) {
        t.languages.push_back(l);
        break;
      }
  for (const StatsEntry& e : report.entries) {
    std::string row = e.case_name + "/" + e.variant + "/" + e.stage;
    if (!t.by_row.contains(row)) t.rows.push_back(row);
    t.by_row[row][e.language] = &e;
  }
  return t;
}

std::string nir_alu(const StatsEntry& e, bool vulkan) {
  if (!e.nir) return "-";
  const std::optional<NirCounts>& n = vulkan ? e.nir->vulkan : e.nir->gl;
  return n ? std::to_string(n->alu) : std::string("-");
}

std::string book_text(const StatsEntry& e) {
  return e.book ? fmt::format("{} {}", *e.book, e.stage == "vertex" ? "vs_1_1" : "ps_2_0") : std::string();
}

// `text` folded at spaces so no line is wider than `width`, continuation lines indented.
std::string folded(const std::string& text, size_t width, const std::string& indent) {
  std::string out, line;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line = indent;
    }
    line += (line.empty() || line == indent ? "" : " ") + word;
    start = end + 1;
  }
  return out + line + "\n";
}

std::string extended_calls(const StatsEntry& e) {
  std::string calls;
  for (const auto& [name, n] : e.spirv_opt.extended_calls)
    calls += fmt::format("{}{}{}", calls.empty() ? "" : " ", name, n > 1 ? fmt::format("x{}", n) : "");
  return calls;
}

const char* const kBookLegend =
    "book: the book's fxc count in DX9 vs_1_1/ps_2_0 instruction slots, a different instruction set (for orientation, "
    "not comparable one to one).";

std::string compact_table(const TableRows& t) {
  // The row name is cut (its end kept: the stage and variant tell rows apart) rather than
  // letting a long case name push the table past kCompactTableWidth.
  constexpr size_t kCounts = 72;   // everything right of the name: see `head`
  const size_t limit = kCompactTableWidth - kCounts;
  size_t w = std::string("case/variant/stage").size();
  for (const std::string& r : t.rows) w = std::max(w, std::min(r.size(), limit));
  auto name = [&](const std::string& r) { return r.size() <= w ? r : "~" + r.substr(r.size() - (w - 1)); };
  std::string out = fmt::format("{:<{}} {:<4} {:>5}{:>4}{:>4}{:>4}{:>4} {:>5}{:>5} {:>5} {:>6} {:>6}  {}\n",
                                "case/variant/stage", w, "lang", "spirv", "ar", "ex", "tx", "cf", "-O", "-Os", "glsl",
                                "nir vk", "nir gl", "book");
  for_each_row(t, out, [&](const std::string& r, const auto& cells) {
    bool first = true, book_shown = false;   // the book's count once per row group, on a counted line
    for (const std::string& l : t.languages) {
      auto it = cells.find(l);
      if (it == cells.end()) continue;
      const StatsEntry& e = *it->second;
      const std::string label = first ? name(r) : "";
      if (!e.error.empty()) {
        out += fmt::format("{:<{}} {:<4} compile error\n", label, w, l);
      } else {
        const ClassCounts& c = e.spirv;
        out += fmt::format("{:<{}} {:<4} {:>5}{:>4}{:>4}{:>4}{:>4} {:>5}{:>5} {:>5} {:>6} {:>6}  {}", label, w, l, c.total,
                           c.arithmetic, c.extended, c.texture, c.control, e.spirv_opt.total, e.spirv_os.total,
                           e.glsl_lines, nir_alu(e, true), nir_alu(e, false), book_shown ? "" : book_text(e));
        book_shown = true;
        while (out.back() == ' ') out.pop_back();
        out += "\n";
      }
      first = false;
    }
  });
  out += "\nGLSL.std.450 calls after -O:\n";
  for (const std::string& r : t.rows)
    for (const std::string& l : t.languages) {
      auto it = t.by_row.at(r).find(l);
      if (it == t.by_row.at(r).end() || it->second->spirv_opt.extended_calls.empty()) continue;
      out += folded(fmt::format("{} {}: {}", r, l, extended_calls(*it->second)), kCompactTableWidth, "    ");
    }
  out += "\n" + folded("spirv = SPIR-V instructions in function bodies as compiled (Vulkan target), of which ar "
                       "arithmetic, ex GLSL.std.450 calls, tx texture, cf control flow; -O / -Os: totals after spirv-opt; "
                       "glsl: lines of SPIRV-Cross GLSL; nir vk / nir gl: NIR ALU instructions Mesa compiled on lavapipe / "
                       "the --gl-platform (- when not read: see the JSON's nir.note). --wide shows every class count.",
                       kCompactTableWidth, "");
  return out + folded(kBookLegend, kCompactTableWidth, "");
}

std::string wide_table(const TableRows& t) {
  size_t w = 10;
  for (const std::string& r : t.rows) w = std::max(w, r.size());
  const std::string block_head = "  tot  ar  ex  tx  cf mem  cv  ot   -O  ar  ex  -Os glsl nir vk nir gl";
  constexpr int kBlock = 70;
  auto block = [&](const StatsEntry* e) -> std::string {
    if (!e) return fmt::format("{:>{}}", "-", kBlock);
    if (!e->error.empty()) return fmt::format("{:>{}}", "compile error", kBlock);
    const ClassCounts& c = e->spirv;
    return fmt::format("{:>5}{:>4}{:>4}{:>4}{:>4}{:>4}{:>4}{:>4}{:>5}{:>4}{:>4}{:>5}{:>5}{:>7}{:>7}", c.total,
                       c.arithmetic, c.extended, c.texture, c.control, c.memory, c.conversion, c.other,
                       e->spirv_opt.total, e->spirv_opt.arithmetic, e->spirv_opt.extended, e->spirv_os.total,
                       e->glsl_lines, nir_alu(*e, true), nir_alu(*e, false));
  };
  std::string out;
  out += fmt::format("{:<{}}", "", w);
  for (const std::string& l : t.languages) out += fmt::format(" |{:^{}}", l, kBlock);
  out += " | book\n";
  out += fmt::format("{:<{}}", "case/variant/stage", w);
  for (size_t i = 0; i < t.languages.size(); ++i) out += " |" + block_head;
  out += " | DX9\n";
  for_each_row(t, out, [&](const std::string& r, const auto& cells) {
    out += fmt::format("{:<{}}", r, w);
    for (const std::string& l : t.languages) {
      auto it = cells.find(l);
      out += " |" + block(it == cells.end() ? nullptr : it->second);
    }
    out += " | " + book_text(*cells.begin()->second) + "\n";
  });
  // The GLSL.std.450 calls after -O, per shader, where the languages differ is easy to spot.
  out += "\nGLSL.std.450 calls after -O (per language):\n";
  for (const std::string& r : t.rows) {
    std::string line;
    for (const std::string& l : t.languages) {
      auto it = t.by_row.at(r).find(l);
      if (it == t.by_row.at(r).end() || it->second->spirv_opt.extended_calls.empty()) continue;
      line += fmt::format("  {}: {}", l, extended_calls(*it->second));
    }
    if (!line.empty()) out += fmt::format("{:<{}}{}\n", r, w, line);
  }
  out += "\ntot = SPIR-V instructions in function bodies as compiled (Vulkan target); ar arithmetic, ex GLSL.std.450 "
         "calls, tx texture, cf control flow, mem memory, cv conversion, ot other; -O / -Os: totals after spirv-opt; "
         "glsl: lines of SPIRV-Cross GLSL; nir vk / nir gl: NIR ALU instructions Mesa compiled on lavapipe / the "
         "--gl-platform (- when not read: see the JSON's nir.note).\n";
  return out + kBookLegend + "\n";
}

}  // namespace

std::string format_table(const StatsReport& report, TableForm form) {
  const TableRows t = table_rows(report);
  return form == TableForm::wide ? wide_table(t) : compact_table(t);
}

}  // namespace shaderbed::stats
