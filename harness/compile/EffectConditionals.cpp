#include "compile/EffectConditionals.h"

#include <cctype>
#include <optional>
#include <set>

namespace shaderbed {
namespace {

using cg::Token;
using cg::TokenKind;

struct ConditionalMacro {
  bool function_like = false;
  std::string value;
};
using ConditionalMacros = std::map<std::string, ConditionalMacro>;

// "#  ifdef  NAME // c" -> {"ifdef", "NAME"}, backslash continuations joined.
std::pair<std::string, std::string> split_conditional_directive(const std::string& text) {
  std::string joined;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r')) {
      while (i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r')) ++i;
      joined += ' ';
      continue;
    }
    joined += text[i];
  }
  std::size_t at = joined.find('#');
  at = at == std::string::npos ? 0 : at + 1;
  while (at < joined.size() && std::isspace(static_cast<unsigned char>(joined[at]))) ++at;
  std::size_t end = at;
  while (end < joined.size() && (std::isalnum(static_cast<unsigned char>(joined[end])) || joined[end] == '_')) ++end;
  return {joined.substr(at, end - at), joined.substr(end)};
}

// An #if expression over integers (C's rules, as glslang's preprocessor has them).
class IfExpression {
 public:
  IfExpression(const std::string& text, const ConditionalMacros& macros) : macros_(macros) { expand(text, 0); }

  std::optional<long long> value() {
    if (failed_) return std::nullopt;
    auto v = ternary();
    if (!v || at_ != tokens_.size()) return std::nullopt;
    return v;
  }

 private:
  void expand(const std::string& text, int depth) {
    if (depth > 32) {
      failed_ = true;
      return;
    }
    const std::vector<Token> lexed = cg::lex(text);
    for (std::size_t i = 0; i < lexed.size() && !failed_; ++i) {
      const Token& t = lexed[i];
      if (t.kind == TokenKind::directive || t.kind == TokenKind::string) {
        failed_ = true;
        return;
      }
      if (!t.is_identifier()) {
        tokens_.push_back(t.text);
        continue;
      }
      if (t.is("defined")) {
        const bool parens = i + 1 < lexed.size() && lexed[i + 1].is("(");
        const std::size_t name = i + (parens ? 2 : 1);
        if (name >= lexed.size() || !lexed[name].is_identifier() || (parens && (name + 1 >= lexed.size() ||
                                                                               !lexed[name + 1].is(")")))) {
          failed_ = true;
          return;
        }
        tokens_.push_back(macros_.contains(lexed[name].text) ? "1" : "0");
        i = name + (parens ? 1 : 0);
        continue;
      }
      const auto macro = macros_.find(t.text);
      if (macro == macros_.end() || expanding_.contains(t.text)) {
        tokens_.push_back("0");   // an unknown name is 0 in #if
        continue;
      }
      if (macro->second.function_like) {
        failed_ = true;           // its arguments would need a real preprocessor
        return;
      }
      expanding_.insert(t.text);
      expand(macro->second.value, depth + 1);
      expanding_.erase(t.text);
    }
  }

  bool accept(const char* op) {
    if (at_ < tokens_.size() && tokens_[at_] == op) {
      ++at_;
      return true;
    }
    return false;
  }

  std::optional<long long> ternary() {
    auto c = logical_or();
    if (!c || !accept("?")) return c;
    auto a = ternary();
    if (!a || !accept(":")) return std::nullopt;
    auto b = ternary();
    if (!b) return std::nullopt;
    return *c ? *a : *b;
  }

  // One left-associative level: next() operands joined by the operators of `ops`.
  template <typename Next, typename Apply>
  std::optional<long long> level(std::initializer_list<const char*> ops, Next next, Apply apply) {
    auto left = (this->*next)();
    while (left) {
      const char* matched = nullptr;
      for (const char* op : ops)
        if (accept(op)) {
          matched = op;
          break;
        }
      if (!matched) return left;
      auto right = (this->*next)();
      if (!right) return std::nullopt;
      left = apply(std::string(matched), *left, *right);
    }
    return left;
  }

  std::optional<long long> logical_or() {
    return level({"||"}, &IfExpression::logical_and,
                 [](const std::string&, long long a, long long b) -> std::optional<long long> { return a || b; });
  }
  std::optional<long long> logical_and() {
    return level({"&&"}, &IfExpression::bit_or,
                 [](const std::string&, long long a, long long b) -> std::optional<long long> { return a && b; });
  }
  std::optional<long long> bit_or() {
    return level({"|"}, &IfExpression::bit_xor,
                 [](const std::string&, long long a, long long b) -> std::optional<long long> { return a | b; });
  }
  std::optional<long long> bit_xor() {
    return level({"^"}, &IfExpression::bit_and,
                 [](const std::string&, long long a, long long b) -> std::optional<long long> { return a ^ b; });
  }
  std::optional<long long> bit_and() {
    return level({"&"}, &IfExpression::equality,
                 [](const std::string&, long long a, long long b) -> std::optional<long long> { return a & b; });
  }
  std::optional<long long> equality() {
    return level({"==", "!="}, &IfExpression::relational,
                 [](const std::string& op, long long a, long long b) -> std::optional<long long> {
                   return op == "==" ? a == b : a != b;
                 });
  }
  std::optional<long long> relational() {
    return level({"<=", ">=", "<", ">"}, &IfExpression::shift,
                 [](const std::string& op, long long a, long long b) -> std::optional<long long> {
                   return op == "<=" ? a <= b : op == ">=" ? a >= b : op == "<" ? a < b : a > b;
                 });
  }
  std::optional<long long> shift() {
    return level({"<<", ">>"}, &IfExpression::additive,
                 [](const std::string& op, long long a, long long b) -> std::optional<long long> {
                   if (b < 0 || b > 62) return std::nullopt;
                   return op == "<<" ? a << b : a >> b;
                 });
  }
  std::optional<long long> additive() {
    return level({"+", "-"}, &IfExpression::multiplicative,
                 [](const std::string& op, long long a, long long b) -> std::optional<long long> {
                   return op == "+" ? a + b : a - b;
                 });
  }
  std::optional<long long> multiplicative() {
    return level({"*", "/", "%"}, &IfExpression::unary,
                 [](const std::string& op, long long a, long long b) -> std::optional<long long> {
                   if (op == "*") return a * b;
                   if (b == 0) return std::nullopt;
                   return op == "/" ? a / b : a % b;
                 });
  }

  std::optional<long long> unary() {
    if (accept("!")) return apply(unary(), [](long long v) { return static_cast<long long>(!v); });
    if (accept("-")) return apply(unary(), [](long long v) { return -v; });
    if (accept("+")) return unary();
    if (accept("~")) return apply(unary(), [](long long v) { return ~v; });
    return primary();
  }

  template <typename F>
  static std::optional<long long> apply(std::optional<long long> v, F f) {
    if (!v) return v;
    return f(*v);
  }

  std::optional<long long> primary() {
    if (accept("(")) {
      auto v = ternary();
      if (!v || !accept(")")) return std::nullopt;
      return v;
    }
    if (at_ >= tokens_.size()) return std::nullopt;
    std::string number = tokens_[at_++];
    while (!number.empty() && (number.back() == 'u' || number.back() == 'U' || number.back() == 'l' ||
                               number.back() == 'L'))
      number.pop_back();
    if (number.empty() || !std::isdigit(static_cast<unsigned char>(number.front()))) return std::nullopt;
    try {
      std::size_t used = 0;
      const long long v = std::stoll(number, &used, 0);
      if (used != number.size()) return std::nullopt;   // a float, or not a number
      return v;
    } catch (...) {
      return std::nullopt;
    }
  }

  const ConditionalMacros& macros_;
  std::vector<std::string> tokens_;
  std::set<std::string> expanding_;
  std::size_t at_ = 0;
  bool failed_ = false;
};

// One #if ... #endif chain being read.
struct IfChain {
  bool parent_active = true;
  bool taken = false;     // a branch of the chain was kept
  bool unknown = false;   // a condition could not be evaluated: every branch from there is kept
  bool active = true;
};

}  // namespace

ConditionalRegions conditional_regions(const std::vector<cg::Token>& tokens,
                                       const std::map<std::string, std::string>& predefined) {
  ConditionalRegions out;
  out.active.assign(tokens.size(), true);
  ConditionalMacros macros;
  for (const auto& [name, value] : predefined) macros[name] = {false, value};
  std::vector<IfChain> chains;
  const auto active = [&] { return chains.empty() || chains.back().active; };
  // The condition's value, or nothing (noted) when it cannot be evaluated.
  const auto evaluate = [&](const std::string& keyword, const std::string& rest, const Token& t) -> std::optional<bool> {
    std::string name = rest;
    std::erase_if(name, [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
    if (keyword == "ifdef") return macros.contains(name);
    if (keyword == "ifndef") return !macros.contains(name);
    if (auto v = IfExpression(rest, macros).value()) return *v != 0;
    out.notes.push_back({t.line, "#" + keyword + rest + ": the effect layer cannot evaluate this condition (a "
                                                         "function-like macro, or one it does not see); it reads "
                                                         "every branch, as glslang's preprocessor may not"});
    return std::nullopt;
  };
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    if (t.kind != TokenKind::directive) {
      out.active[i] = active();
      continue;
    }
    const auto [keyword, rest] = split_conditional_directive(t.text);
    if (keyword == "if" || keyword == "ifdef" || keyword == "ifndef") {
      IfChain c{.parent_active = active()};
      if (c.parent_active) {
        const std::optional<bool> cond = evaluate(keyword, rest, t);
        c.unknown = !cond;
        c.taken = cond.value_or(true);
        c.active = cond.value_or(true);
      } else {
        c.taken = true;   // nothing under an inactive parent is kept
        c.active = false;
      }
      chains.push_back(c);
    } else if (keyword == "elif" && !chains.empty()) {
      IfChain& c = chains.back();
      if (c.unknown || !c.parent_active) {
        c.active = c.parent_active;
      } else if (c.taken) {
        c.active = false;
      } else {
        const std::optional<bool> cond = evaluate("if", rest, t);
        c.unknown = !cond;
        c.taken = cond.value_or(true);
        c.active = cond.value_or(true);
      }
    } else if (keyword == "else" && !chains.empty()) {
      IfChain& c = chains.back();
      c.active = c.parent_active && (c.unknown || !c.taken);
      c.taken = true;
    } else if (keyword == "endif" && !chains.empty()) {
      chains.pop_back();
    } else if (keyword == "define" && active()) {
      // "NAME value", "NAME(args) value": a '(' right after the name makes it function-like.
      std::size_t at = 0;
      while (at < rest.size() && std::isspace(static_cast<unsigned char>(rest[at]))) ++at;
      std::size_t end = at;
      while (end < rest.size() && (std::isalnum(static_cast<unsigned char>(rest[end])) || rest[end] == '_')) ++end;
      if (end > at) macros[rest.substr(at, end - at)] = {end < rest.size() && rest[end] == '(', rest.substr(end)};
    } else if (keyword == "undef" && active()) {
      std::string name = rest;
      std::erase_if(name, [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
      macros.erase(name);
    }
  }
  return out;
}

}  // namespace shaderbed
