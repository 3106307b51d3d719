#include "report/ConsoleWrap.h"

#include <algorithm>

namespace shaderbed {
namespace {

// Columns, not bytes: UTF-8 continuation bytes (the × and → of explanations) take none.
bool continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

size_t columns(const std::string& text, size_t from, size_t to) {
  size_t n = 0;
  for (size_t i = from; i < to && i < text.size(); ++i) n += !continuation(text[i]);
  return n;
}

// Where to cut `line` (from `start`) so its first piece fits `room` columns: after the last
// "; " in the second half of the room, else at the last space, else after `room` columns.
size_t cut(const std::string& line, size_t start, size_t room) {
  size_t end = start, used = 0;
  for (; end < line.size() && used < room; ++end) used += !continuation(line[end]);
  while (end < line.size() && continuation(line[end])) ++end;
  if (end >= line.size()) return line.size();
  const std::string window = line.substr(start, end - start + 1);
  const size_t semicolon = window.rfind("; ");
  if (semicolon != std::string::npos && semicolon > window.size() / 2) return start + semicolon + 1;
  const size_t space = window.rfind(' ');
  if (space != std::string::npos && space > 0) return start + space;
  return end;
}

std::string fold_line(const std::string& line, size_t prefix, const std::string& indent) {
  if (prefix + columns(line, 0, line.size()) <= kConsoleFoldAbove) return line;
  std::string out;
  size_t start = 0;
  size_t room = kConsoleWidth > prefix + 20 ? kConsoleWidth - prefix : 20;
  while (start < line.size()) {
    const size_t end = cut(line, start, room);
    if (!out.empty()) out += "\n" + indent;
    out += line.substr(start, end - start);
    start = end;
    while (start < line.size() && line[start] == ' ') ++start;
    room = kConsoleWidth > indent.size() + 20 ? kConsoleWidth - indent.size() : 20;
  }
  return out;
}

}  // namespace

std::string fold_for_console(const std::string& text, size_t first_prefix, const std::string& indent) {
  std::string out;
  size_t start = 0;
  for (bool first = true; start <= text.size(); first = false) {
    const size_t end = std::min(text.find('\n', start), text.size());
    if (!first) out += '\n';
    out += fold_line(text.substr(start, end - start), first ? first_prefix : 0, indent);
    start = end + 1;
  }
  return out;
}

}  // namespace shaderbed
