#pragma once
// The one writer of case-file text, shared by `shaderbed init` (author/CaseDraft.h) and
// `shaderbed port` (author/PortCase.h), so the two write keys, strings, numbers and tables
// alike. Values go through toml++ (double-quoted strings with TOML's escapes, floats with
// a decimal point, see toml_value); arrays and inline tables stay on one line, as case
// files are written by hand: `[0.7, 0.5, 0.3]`, `{ value = "world", layout = "row_vector" }`.
// The text is built a line at a time, so a comment lines up after its code and a TODO
// knows its line number.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

namespace shaderbed {

// Bare when the key is letters, digits, '_' and '-'; else a quoted string
// ("gl_LightSource[0].position").
std::string toml_key(std::string_view key);

// One value on one line; a parsed table's entries in toml++'s (key) order.
std::string toml_value(const toml::node& value);
std::string toml_string(std::string_view text);
std::string toml_float(double number);

// Keys with their values already written, in the order written.
using TomlEntries = std::vector<std::pair<std::string, std::string>>;

// "{ a = 1, b = 2 }"; "{}" when empty.
std::string toml_inline_table(const TomlEntries& entries);

// "key = value", the value already written.
std::string toml_entry(std::string_view key, std::string_view value);

// One [table] of a case: entries in the order first set; a key set again keeps its place
// and takes the new value.
struct CaseTable {
  std::string header;   // "bindings.glsl", without the brackets
  TomlEntries entries;
  void set(const std::string& key, std::string value);
  const std::string* find(const std::string& key) const;
};

// A case file's text, a line at a time.
class CaseTomlWriter {
 public:
  void line(const std::string& text = "");
  // A blank line, then "[name]".
  void header(std::string_view name);
  // `code`, then "# comment" from column 44 (one space after a longer code), so the
  // reasons of a table line up; just `code` when the comment is empty.
  void commented(const std::string& code, const std::string& comment);
  // A commented line saying "TODO: what", also listed in todos() as "line N: what".
  void todo(const std::string& code, const std::string& what);
  // header() and "key = value" for each entry; nothing for a table without entries.
  void table(const CaseTable& table);

  const std::string& text() const { return text_; }
  int next_line() const { return lines_ + 1; }   // the number the next line written gets
  const std::vector<std::string>& todos() const { return todos_; }

 private:
  std::string text_;
  int lines_ = 0;
  std::vector<std::string> todos_;
};

}  // namespace shaderbed
