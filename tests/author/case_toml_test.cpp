// The one writer of case-file text (author/CaseToml.h), as init and port write it: keys
// bare when they can be, strings double-quoted with TOML's escapes, floats with a decimal
// point, inline tables in the order given, comments aligned, TODOs with their line.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include "author/CaseToml.h"

namespace shaderbed {
namespace {

TEST(CaseToml, KeysAreBareWhenTheyCanBe) {
  EXPECT_EQ(toml_key("g_mWorld"), "g_mWorld");
  EXPECT_EQ(toml_key("base-colour"), "base-colour");
  EXPECT_EQ(toml_key("gl_LightSource[0].position"), R"("gl_LightSource[0].position")");
  EXPECT_EQ(toml_key(""), R"("")");
}

TEST(CaseToml, ValuesOnOneLine) {
  EXPECT_EQ(toml_string(R"(a "quoted" C:\path)"), R"("a \"quoted\" C:\\path")");
  EXPECT_EQ(toml_string("two\nlines"), R"("two\nlines")");
  EXPECT_EQ(toml_float(12.0), "12.0");
  EXPECT_EQ(toml_float(0.7), "0.7");
  EXPECT_EQ(toml_float(0.0), "0.0");
  EXPECT_EQ(toml_value(toml::array{"+x.png", 1.0, 2}), R"(["+x.png", 1.0, 2])");
  // A parsed table in toml++'s key order; one built here in the order given.
  EXPECT_EQ(toml_value(toml::table{{"path", "spirv"}, {"backend", "vulkan"}}), R"({ backend = "vulkan", path = "spirv" })");
  EXPECT_EQ(toml_inline_table({{"value", toml_string("world")}, {"layout", toml_string("row_vector")}}),
            R"({ value = "world", layout = "row_vector" })");
  EXPECT_EQ(toml_inline_table({}), "{}");
}

TEST(CaseToml, WhatIsWrittenParsesBack) {
  const std::string text = toml_entry("s", toml_string("tab\there \"q\" \\ \x01")) + "\n" +
                           toml_entry("t", toml_inline_table({{"a b", toml_value(toml::array{0.1, "x"})}})) + "\n";
  toml::table parsed;
  ASSERT_NO_THROW(parsed = toml::parse(text)) << text;
  EXPECT_EQ(parsed["s"].value_or(std::string()), "tab\there \"q\" \\ \x01");
  EXPECT_EQ(parsed["t"]["a b"][0].value_or(0.0), 0.1);
  EXPECT_EQ(parsed["t"]["a b"][1].value_or(std::string()), "x");
}

TEST(CaseToml, TablesKeepTheirFirstOrderAndTheLastValue) {
  CaseTable t{"bindings.glsl", {}};
  t.set("b", "1");
  t.set("a", "2");
  t.set("b", "3");
  ASSERT_NE(t.find("b"), nullptr);
  EXPECT_EQ(*t.find("b"), "3");
  EXPECT_EQ(t.find("c"), nullptr);
  CaseTomlWriter w;
  w.line("x = 1");
  w.table(t);
  w.table(CaseTable{"empty", {}});
  EXPECT_EQ(w.text(), "x = 1\n\n[bindings.glsl]\nb = 3\na = 2\n");
}

TEST(CaseToml, CommentsLineUpAndTodosKnowTheirLine) {
  CaseTomlWriter w;
  w.header("params");
  w.commented("a = 1", "why");
  w.commented(std::string(50, 'k'), "long");
  w.commented("b = 2", "");
  w.todo("# c = 0.0", "bind 'c'");
  EXPECT_EQ(w.text(), "\n[params]\n" + ("a = 1" + std::string(39, ' ') + "# why\n") + std::string(50, 'k') + " # long\n" +
                          "b = 2\n" + "# c = 0.0" + std::string(35, ' ') + "# TODO: bind 'c'\n");
  EXPECT_EQ(w.todos(), std::vector<std::string>{"line 6: bind 'c'"});
}

}  // namespace
}  // namespace shaderbed
