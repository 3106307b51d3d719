#pragma once
// A lexer for Cg/HLSL source good enough to rewrite it safely: comments, string
// literals and preprocessor lines are never mistaken for code, identifiers are matched
// whole, and the text is rebuilt with every line break where it was.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace shaderbed::cg {

enum class TokenKind { identifier, number, string, punctuation, directive };

struct Token {
  TokenKind kind = TokenKind::punctuation;
  std::size_t begin = 0;  // byte range in the lexed text
  std::size_t end = 0;
  int physical_line = 1;  // 1-based line of `begin` in the lexed text
  std::string text;       // current spelling (rewrites change this)
  std::string prefix;     // inserted before the token (no line breaks)
  std::string suffix;     // inserted after the token (no line breaks)
  bool removed = false;   // dropped from the output; its line breaks are kept
  // Where the token is in the author's files, following #line markers.
  std::string file;
  int line = 0;

  bool is(std::string_view s) const { return text == s; }
  bool is_identifier() const { return kind == TokenKind::identifier; }
};

// Splits `text` into tokens; comments and whitespace are the gaps between them.
std::vector<Token> lex(std::string_view text);

// Fills Token::file/line, following `#line N "file"` and `#line N` directives; text
// before the first marker belongs to `path`.
void assign_positions(std::vector<Token>& tokens, const std::string& path);

// The text with the tokens' current spellings, gaps copied verbatim, removed tokens
// replaced by their line breaks.
std::string rebuild(std::string_view text, const std::vector<Token>& tokens);

}  // namespace shaderbed::cg
