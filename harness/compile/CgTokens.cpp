#include "compile/CgTokens.h"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace shaderbed::cg {
namespace {

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Longest first, so "<<=" wins over "<<" and "<".
constexpr std::string_view kPunctuators[] = {"<<=", ">>=", "::", "++", "--", "<<", ">>", "<=", ">=", "==", "!=",
                                             "&&",  "||",  "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "->"};

}  // namespace

std::vector<Token> lex(std::string_view s) {
  std::vector<Token> out;
  out.reserve(s.size() / 4 + 16);  // about one token per 4 bytes of shader text: no regrowth
  std::size_t i = 0;
  int line = 1;
  bool line_start = true;  // only whitespace (or comments) since the last line break
  const auto emit = [&](TokenKind kind, std::size_t begin, std::size_t end, int at_line) {
    Token& t = out.emplace_back();
    t.kind = kind;
    t.begin = begin;
    t.end = end;
    t.physical_line = at_line;
    t.text.assign(s.substr(begin, end - begin));
  };
  while (i < s.size()) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
      line_start = true;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
      while (i < s.size() && s[i] != '\n') ++i;
      continue;
    }
    if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
      i += 2;
      while (i < s.size() && !(s[i] == '*' && i + 1 < s.size() && s[i + 1] == '/')) {
        if (s[i] == '\n') ++line;
        ++i;
      }
      i = std::min(s.size(), i + 2);
      continue;
    }
    const std::size_t begin = i;
    const int begin_line = line;
    if (c == '#' && line_start) {
      // A whole preprocessor line, with backslash continuations; a // comment ends it.
      while (i < s.size() && s[i] != '\n') {
        if (s[i] == '\\' && i + 1 < s.size() &&
            (s[i + 1] == '\n' || (s[i + 1] == '\r' && i + 2 < s.size() && s[i + 2] == '\n'))) {
          i += s[i + 1] == '\r' ? 3 : 2;
          ++line;
          continue;
        }
        if (s[i] == '/' && i + 1 < s.size() && (s[i + 1] == '/' || s[i + 1] == '*')) break;
        ++i;
      }
      std::size_t end = i;
      while (end > begin && std::isspace(static_cast<unsigned char>(s[end - 1]))) --end;
      emit(TokenKind::directive, begin, end, begin_line);
      line_start = false;
      continue;
    }
    line_start = false;
    if (ident_start(c)) {
      while (i < s.size() && ident_char(s[i])) ++i;
      emit(TokenKind::identifier, begin, i, begin_line);
      continue;
    }
    if (digit(c) || (c == '.' && i + 1 < s.size() && digit(s[i + 1]))) {
      if (c == '0' && i + 1 < s.size() && (s[i + 1] == 'x' || s[i + 1] == 'X') && i + 2 < s.size() &&
          std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
        i += 2;
        while (i < s.size() && std::isxdigit(static_cast<unsigned char>(s[i]))) ++i;
      } else {
        while (i < s.size() && digit(s[i])) ++i;
        if (i < s.size() && s[i] == '.') ++i;
        while (i < s.size() && digit(s[i])) ++i;
        if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
          std::size_t j = i + 1;
          if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
          if (j < s.size() && digit(s[j])) {
            i = j;
            while (i < s.size() && digit(s[i])) ++i;
          }
        }
      }
      while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;  // suffixes: f h x u l
      emit(TokenKind::number, begin, i, begin_line);
      continue;
    }
    if (c == '"') {
      ++i;
      while (i < s.size() && s[i] != '"' && s[i] != '\n') i += (s[i] == '\\' && i + 1 < s.size()) ? 2 : 1;
      if (i < s.size() && s[i] == '"') ++i;
      emit(TokenKind::string, begin, i, begin_line);
      continue;
    }
    std::size_t len = 1;
    if (std::string_view("<>:+-=!&|*/%^").find(c) != std::string_view::npos)  // the first chars of kPunctuators
      for (std::string_view p : kPunctuators)
        if (s.substr(i, p.size()) == p) {
          len = p.size();
          break;
        }
    i += len;
    emit(TokenKind::punctuation, begin, i, begin_line);
  }
  return out;
}

void assign_positions(std::vector<Token>& tokens, const std::string& path) {
  std::string file = path;
  int offset = 0;  // logical line = physical line + offset
  for (Token& t : tokens) {
    t.file = file;
    t.line = t.physical_line + offset;
    if (t.kind != TokenKind::directive) continue;
    // "#line N" or "#line N "file"": the next line is line N.
    std::string_view d = t.text;
    d.remove_prefix(1);
    while (!d.empty() && (d.front() == ' ' || d.front() == '\t')) d.remove_prefix(1);
    if (!d.starts_with("line")) continue;
    d.remove_prefix(4);
    while (!d.empty() && (d.front() == ' ' || d.front() == '\t')) d.remove_prefix(1);
    int n = 0;
    auto [ptr, ec] = std::from_chars(d.data(), d.data() + d.size(), n);
    if (ec != std::errc()) continue;
    d.remove_prefix(static_cast<std::size_t>(ptr - d.data()));
    const int directive_lines = static_cast<int>(std::count(t.text.begin(), t.text.end(), '\n'));
    offset = n - (t.physical_line + directive_lines + 1);
    if (auto q = d.find('"'); q != std::string_view::npos) {
      auto q2 = d.find('"', q + 1);
      if (q2 != std::string_view::npos) file = std::string(d.substr(q + 1, q2 - q - 1));
    }
  }
}

std::string rebuild(std::string_view text, const std::vector<Token>& tokens) {
  std::string out;
  out.reserve(text.size() + 256);
  std::size_t at = 0;
  for (const Token& t : tokens) {
    out.append(text.substr(at, t.begin - at));
    out += t.prefix;
    if (t.removed) {
      const std::string_view original = text.substr(t.begin, t.end - t.begin);
      out.append(static_cast<std::size_t>(std::count(original.begin(), original.end(), '\n')), '\n');
    } else {
      out += t.text;
    }
    out += t.suffix;
    at = t.end;
  }
  out.append(text.substr(at));
  return out;
}

}  // namespace shaderbed::cg
