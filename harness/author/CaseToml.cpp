#include "author/CaseToml.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace shaderbed {

namespace {

constexpr size_t kCommentColumn = 44;   // where the reasons of a table line up

}  // namespace

std::string toml_key(std::string_view key) {
  const bool bare = !key.empty() && std::ranges::all_of(key, [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-'; });
  return bare ? std::string(key) : toml_string(key);
}

std::string toml_value(const toml::node& value) {
  if (const toml::table* t = value.as_table()) {
    TomlEntries entries;
    for (const auto& [k, v] : *t) entries.emplace_back(std::string(k.str()), toml_value(v));
    return toml_inline_table(entries);
  }
  if (const toml::array* a = value.as_array()) {
    std::string out = "[";
    for (size_t i = 0; i < a->size(); ++i) out += (i ? ", " : "") + toml_value(*a->get(i));
    return out + "]";
  }
  // Double-quoted strings on one line (a literal or multi-line string of the original's
  // case is rewritten as one); floats in their shortest form, or to six significant
  // digits where that is shorter (relaxed precision: 0.1 + 0.2 is written 0.3).
  std::ostringstream os;
  os << toml::toml_formatter{value, toml::format_flags::allow_unicode_strings | toml::format_flags::relaxed_float_precision};
  return os.str();
}

std::string toml_string(std::string_view text) { return toml_value(toml::value<std::string>(std::string(text))); }

std::string toml_float(double number) { return toml_value(toml::value<double>(number)); }

std::string toml_inline_table(const TomlEntries& entries) {
  if (entries.empty()) return "{}";
  std::string out = "{ ";
  for (size_t i = 0; i < entries.size(); ++i) out += (i ? ", " : "") + toml_entry(entries[i].first, entries[i].second);
  return out + " }";
}

std::string toml_entry(std::string_view key, std::string_view value) {
  return toml_key(key) + " = " + std::string(value);
}

void CaseTable::set(const std::string& key, std::string value) {
  for (auto& entry : entries)
    if (entry.first == key) {
      entry.second = std::move(value);
      return;
    }
  entries.emplace_back(key, std::move(value));
}

const std::string* CaseTable::find(const std::string& key) const {
  for (const auto& entry : entries)
    if (entry.first == key) return &entry.second;
  return nullptr;
}

void CaseTomlWriter::line(const std::string& text) {
  text_ += text + "\n";
  ++lines_;
}

void CaseTomlWriter::header(std::string_view name) {
  line();
  line("[" + std::string(name) + "]");
}

void CaseTomlWriter::commented(const std::string& code, const std::string& comment) {
  std::string s = code;
  if (!comment.empty()) {
    s.resize(std::max(s.size() + 1, kCommentColumn), ' ');
    s += "# " + comment;
  }
  line(s);
}

void CaseTomlWriter::todo(const std::string& code, const std::string& what) {
  todos_.push_back("line " + std::to_string(lines_ + 1) + ": " + what);
  commented(code, "TODO: " + what);
}

void CaseTomlWriter::table(const CaseTable& table) {
  if (table.entries.empty()) return;
  header(table.header);
  for (const auto& [key, value] : table.entries) line(toml_entry(key, value));
}

}  // namespace shaderbed
