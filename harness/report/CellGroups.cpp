#include "report/CellGroups.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace shaderbed {
namespace {

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

bool word_character(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// `from` only where it stands as a word: "sphere" in "/sphere/" or "sphere:", not in "hemisphere".
void replace_word(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (size_t at = text.find(from); at != std::string::npos;) {
    const size_t end = at + from.size();
    if ((at == 0 || !word_character(text[at - 1])) && (end == text.size() || !word_character(text[end]))) {
      text.replace(at, from.size(), to);
      at = text.find(from, at + to.size());
    } else {
      at = text.find(from, at + 1);
    }
  }
}

// Distinct values in first-seen order.
template <class Of>
std::vector<std::string> distinct(const std::vector<const CellResult*>& cells, Of&& of) {
  std::vector<std::string> out;
  for (const CellResult* r : cells)
    if (std::string v = of(*r); std::ranges::find(out, v) == out.end()) out.push_back(std::move(v));
  return out;
}

std::string backend_path(const CellResult& r) { return r.backend + "/" + r.path; }

}  // namespace

std::string without_cell_identity(std::string text, const CellResult& r) {
  replace_all(text, r.language + "-" + r.backend + "-" + r.path, "<cell>");
  replace_all(text, backend_path(r), "<backend/path>");
  replace_word(text, r.shape, "<shape>");
  return text;
}

std::string failure_key(const CellResult& r) {
  std::string message = without_cell_identity(r.message, r);
  // Numbers (1.30e-01, 411, -2.5) become '#': the same failure measures differently per cell.
  std::string text;
  for (size_t i = 0; i < message.size();) {
    const bool starts = std::isdigit(static_cast<unsigned char>(message[i])) ||
                        (message[i] == '.' && i + 1 < message.size() && std::isdigit(static_cast<unsigned char>(message[i + 1])));
    if (!starts || (i > 0 && word_character(message[i - 1]))) {   // digits inside a word (fp16, c5) stay
      text += message[i++];
      continue;
    }
    while (i < message.size() && (std::isalnum(static_cast<unsigned char>(message[i])) || message[i] == '.' ||
                                  ((message[i] == '-' || message[i] == '+') && (message[i - 1] == 'e' || message[i - 1] == 'E'))))
      ++i;
    text += '#';
  }
  std::string fits;
  for (const Explanation& e : r.explanations)
    if (e.fits) {
      fits = e.name;
      break;
    }
  const char* how = r.status == CellStatus::fail ? (r.known_failure ? "known" : "fail") : to_string(r.status);
  // A port that departs at another line is another bug.
  const std::string departs = r.divergence ? fmt::format("{}:{}:{}", r.divergence->kind, r.divergence->file, r.divergence->line) : "";
  return fmt::format("{}\x1f{}\x1f{}\x1f{}\x1f{}\x1f{}\x1f{}\x1f{}", r.variant, r.language, how, text, r.attribution, fits,
                     r.known_failure ? r.known_reason : "", departs);
}

std::string group_where(const std::vector<const CellResult*>& cells) {
  if (cells.empty()) return "";
  const auto variants = distinct(cells, [](const CellResult& r) { return r.variant; });
  const auto languages = distinct(cells, [](const CellResult& r) { return r.language; });
  return fmt::format("{} {} {}", cells.front()->case_name, fmt::join(variants, ", "), fmt::join(languages, ", "));
}

std::string group_cells_text(const std::vector<const CellResult*>& cells) {
  const auto variants = distinct(cells, [](const CellResult& r) { return r.variant; });
  const auto languages = distinct(cells, [](const CellResult& r) { return r.language; });
  const auto paths = distinct(cells, backend_path);
  const auto shapes = distinct(cells, [](const CellResult& r) { return r.shape; });
  const std::string count = fmt::format("{} cell{}", cells.size(), cells.size() == 1 ? "" : "s");
  // Cells are distinct, so as many as the product means every combination is there.
  if (cells.size() == variants.size() * languages.size() * paths.size() * shapes.size())
    return fmt::format("{}: {}{}{}", count, fmt::join(paths, ", "), paths.size() > 1 && shapes.size() > 1 ? " × " : " ",
                       fmt::join(shapes, ", "));
  // Otherwise by variant, language and path, each with its shapes; the variant and the
  // language only where the group spans more than one (group_where names them).
  std::vector<std::pair<std::string, std::vector<std::string>>> by_path;
  for (const CellResult* r : cells) {
    std::string who;
    if (variants.size() > 1) who += r->variant + " ";
    if (languages.size() > 1) who += r->language + " ";
    who += backend_path(*r);
    auto it = std::ranges::find(by_path, who, &std::pair<std::string, std::vector<std::string>>::first);
    if (it == by_path.end()) by_path.push_back({who, {r->shape}});
    else it->second.push_back(r->shape);
  }
  std::vector<std::string> parts;
  for (const auto& [who, its_shapes] : by_path) parts.push_back(fmt::format("{} {}", who, fmt::join(its_shapes, ", ")));
  return fmt::format("{}: {}", count, fmt::join(parts, "; "));
}

}  // namespace shaderbed
