#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "ReportTestSupport.h"
#include "report/JunitReport.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

// A small, strict XML reader for the subset a JUnit file uses: declaration, comments,
// elements, attributes, text and the five entities plus character references. Throws on
// anything not well formed.
struct Node {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::vector<std::unique_ptr<Node>> children;
  std::string text;
  std::vector<const Node*> all(const std::string& n) const {
    std::vector<const Node*> out;
    for (const auto& c : children)
      if (c->name == n) out.push_back(c.get());
    return out;
  }
  const Node* first(const std::string& n) const {
    auto v = all(n);
    return v.empty() ? nullptr : v[0];
  }
};

class XmlReader {
 public:
  explicit XmlReader(std::string s) : s_(std::move(s)) {}
  std::unique_ptr<Node> document() {
    if (s_.compare(0, 5, "<?xml") == 0) i_ = s_.find("?>") + 2;
    skip_misc();
    auto root = element();
    skip_misc();
    if (i_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what + " at byte " + std::to_string(i_)); }
  void skip_ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  void skip_misc() {
    for (skip_ws(); s_.compare(i_, 4, "<!--") == 0; skip_ws()) i_ = s_.find("-->", i_) + 3;
  }
  std::string name() {
    const size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' || s_[i_] == '_' ||
                              s_[i_] == ':' || s_[i_] == '.'))
      ++i_;
    if (i_ == start) fail("expected a name");
    return s_.substr(start, i_ - start);
  }
  std::string decode(const std::string& raw) {
    std::string out;
    for (size_t k = 0; k < raw.size(); ++k) {
      const char c = raw[k];
      if (c == '<') fail("'<' in text or attribute");
      if (c != '&') {
        out += c;
        continue;
      }
      const size_t end = raw.find(';', k);
      if (end == std::string::npos) fail("unterminated entity");
      const std::string e = raw.substr(k + 1, end - k - 1);
      static const std::map<std::string, std::string> named = {
          {"amp", "&"}, {"lt", "<"}, {"gt", ">"}, {"quot", "\""}, {"apos", "'"}};
      if (auto it = named.find(e); it != named.end()) out += it->second;
      else if (e.size() > 1 && e[0] == '#') {
        const unsigned long cp = e[1] == 'x' ? std::stoul(e.substr(2), nullptr, 16) : std::stoul(e.substr(1));
        if (cp >= 0x80) fail("non-ASCII character reference (not needed here)");
        out += char(cp);
      } else fail("unknown entity &" + e + ";");
      k = end;
    }
    return out;
  }
  std::unique_ptr<Node> element() {
    if (s_[i_] != '<') fail("expected '<'");
    ++i_;
    auto node = std::make_unique<Node>();
    node->name = name();
    for (;;) {
      skip_ws();
      if (s_.compare(i_, 2, "/>") == 0) {
        i_ += 2;
        return node;
      }
      if (s_[i_] == '>') {
        ++i_;
        break;
      }
      const std::string key = name();
      skip_ws();
      if (s_[i_] != '=') fail("expected '='");
      ++i_;
      skip_ws();
      const char quote = s_[i_];
      if (quote != '"' && quote != '\'') fail("expected a quote");
      const size_t end = s_.find(quote, i_ + 1);
      if (end == std::string::npos) fail("unterminated attribute");
      if (node->attrs.contains(key)) fail("duplicate attribute " + key);
      node->attrs[key] = decode(s_.substr(i_ + 1, end - i_ - 1));
      i_ = end + 1;
    }
    for (;;) {
      const size_t lt = s_.find('<', i_);
      if (lt == std::string::npos) fail("unterminated element " + node->name);
      node->text += decode(s_.substr(i_, lt - i_));
      i_ = lt;
      if (s_.compare(i_, 4, "<!--") == 0) {
        i_ = s_.find("-->", i_) + 3;
        continue;
      }
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        if (name() != node->name) fail("mismatched end tag for " + node->name);
        skip_ws();
        if (s_[i_] != '>') fail("expected '>'");
        ++i_;
        return node;
      }
      node->children.push_back(element());
    }
  }
  std::string s_;
  size_t i_ = 0;
};

bool valid_xml_chars(const std::string& s) {
  for (size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = s[i];
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t') return false;
    if (c == 0xff || c == 0xfe) return false;
  }
  return true;
}

TEST(JunitReport, OneTestcasePerCellWithCountsAndMessages) {
  const fs::path dir = test::fresh_dir("junit");
  const RunReport report = test::sample_report(dir / "out", 8);
  const fs::path file = dir / "nested" / "r.xml";
  ASSERT_TRUE(write_junit(report, file.string()));
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  EXPECT_TRUE(valid_xml_chars(xml));
  EXPECT_EQ(xml.find("<script>"), std::string::npos);

  std::unique_ptr<Node> root;
  try {
    root = XmlReader(xml).document();
  } catch (const std::exception& e) {
    FAIL() << e.what() << "\n" << xml;
  }
  ASSERT_EQ(root->name, "testsuites");
  EXPECT_EQ(root->attrs["tests"], "6");
  EXPECT_EQ(root->attrs["failures"], "2");
  EXPECT_EQ(root->attrs["errors"], "1");
  EXPECT_FALSE(root->attrs.contains("skipped")) << "junit-10 allows skipped on <testsuite> only";
  EXPECT_EQ(root->attrs["time"], "1.234");   // wall_ms 1234.5 (binary 1234.49999...)

  const auto suites = root->all("testsuite");
  ASSERT_EQ(suites.size(), 2u);   // lambert and the case with markup in its name
  EXPECT_EQ(suites[0]->attrs.at("name"), "lambert");
  EXPECT_EQ(suites[0]->attrs.at("tests"), "5");
  EXPECT_EQ(suites[0]->attrs.at("failures"), "2");
  EXPECT_EQ(suites[0]->attrs.at("errors"), "1");
  EXPECT_EQ(suites[0]->attrs.at("skipped"), "1");
  EXPECT_EQ(suites[1]->attrs.at("name"), "phong<&>\"'");
  EXPECT_EQ(suites[1]->attrs.at("tests"), "1");
  std::map<std::string, std::string> props;
  for (const Node* p : suites[0]->first("properties")->all("property")) props[p->attrs.at("name")] = p->attrs.at("value");
  EXPECT_EQ(props["llvm"], "15.0.6");
  EXPECT_EQ(props["mesa_gl"], "Mesa 22.3.6 llvmpipe");

  std::vector<const Node*> cases;
  for (const Node* s : suites)
    for (const Node* c : s->all("testcase")) cases.push_back(c);
  ASSERT_EQ(cases.size(), report.results.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    const CellResult& r = report.results[i];
    EXPECT_EQ(cases[i]->attrs.at("classname"), r.case_name + "." + r.variant + "." + r.language);
    EXPECT_EQ(cases[i]->attrs.at("name"), r.backend + "/" + r.path + "/" + r.shape);
    // Context for what did not pass only: a passing case's would be most of the file.
    EXPECT_EQ(cases[i]->first("system-out") != nullptr, r.status != CellStatus::pass || !r.warnings.empty()) << i;
  }
  // The pass: no system-out, its own stages as the time (1.5 + 0.75 + 0.25 + 0.5 ms).
  EXPECT_TRUE(cases[0]->all("failure").empty());
  EXPECT_EQ(cases[0]->attrs.at("time"), "0.003");
  // The failure: timings and images in system-out.
  ASSERT_NE(cases[1]->first("system-out"), nullptr);
  EXPECT_NE(cases[1]->first("system-out")->text.find(" ms"), std::string::npos);
  EXPECT_NE(cases[1]->first("system-out")->text.find("render: " + report.results[1].artefacts.render_png),
            std::string::npos);
  // ... and as attachments, which GitLab's and Jenkins' test views show.
  EXPECT_NE(cases[1]->first("system-out")->text.find("[[ATTACHMENT|" + report.results[1].artefacts.render_png + "]]"),
            std::string::npos);
  // The failure: metric and attribution in the message.
  const Node* failure = cases[1]->first("failure");
  ASSERT_NE(failure, nullptr);
  const std::string& message = failure->attrs.at("message");
  EXPECT_NE(message.find("interior max error 1.30e-01 > 2.00e-03"), std::string::npos) << message;
  EXPECT_NE(message.find("max_abs 1.30e-01"), std::string::npos) << message;
  EXPECT_NE(message.find("attribution: driver (only gl/native differs"), std::string::npos) << message;
  EXPECT_EQ(failure->attrs.at("type"), "driver");
  EXPECT_NE(failure->text.find("411 bad pixels"), std::string::npos);
  // The known failure is skipped with its reason, not failed.
  EXPECT_TRUE(cases[2]->all("failure").empty());
  ASSERT_NE(cases[2]->first("skipped"), nullptr);
  EXPECT_EQ(cases[2]->first("skipped")->attrs.at("message"),
            "known: SPIRV-Cross 2022 drops precise on the GL path (issue #12)");
  // The error: first line as the message, all of it in the body.
  const Node* error = cases[3]->first("error");
  ASSERT_NE(error, nullptr);
  EXPECT_EQ(error->attrs.at("message"), "shaders/lambert.cg:12:5: compile: 'float4' : undeclared identifier");
  EXPECT_NE(error->text.find("second line"), std::string::npos);
  // NaN metrics print as text, not as garbage.
  EXPECT_NE(cases[4]->first("failure")->attrs.at("message").find("max_abs nan"), std::string::npos);
  EXPECT_TRUE(cases[5]->all("failure").empty());

  // xmllint, when installed, agrees that the file is well formed.
  if (fs::exists("/usr/bin/xmllint")) {
    EXPECT_EQ(std::system(("/usr/bin/xmllint --noout '" + file.string() + "'").c_str()), 0);
  }
  fs::remove_all(dir);
}

TEST(JunitReport, EscapesMarkupAndCleansBytes) {
  RunReport report;
  CellResult r;
  r.case_name = "a&b";
  r.variant = "v<1>";
  r.language = "glsl";
  r.backend = "gl";
  r.path = "native";
  r.shape = "cube\"'";
  r.status = CellStatus::fail;
  r.message = "bad <tag> & \"q\" 'a'\x01\x1f\xc3\x28 \xe2\x82\xac end\nline two";
  r.attribution = "front end";
  report.results.push_back(r);
  const std::string xml = to_junit(report);
  EXPECT_TRUE(valid_xml_chars(xml)) << xml;
  std::unique_ptr<Node> root;
  try {
    root = XmlReader(xml).document();
  } catch (const std::exception& e) {
    FAIL() << e.what() << "\n" << xml;
  }
  const Node* tc = root->first("testsuite")->first("testcase");
  EXPECT_EQ(tc->attrs.at("classname"), "a&b.v<1>.glsl");
  EXPECT_EQ(tc->attrs.at("name"), "gl/native/cube\"'");
  const std::string message = tc->first("failure")->attrs.at("message");
  EXPECT_EQ(message.rfind("bad <tag> & \"q\" 'a'\\x01\\x1f\xef\xbf\xbd( \xe2\x82\xac end; ", 0), 0u) << message;
  EXPECT_NE(tc->first("failure")->text.find("line two"), std::string::npos);
}

TEST(JunitReport, EmptyRunIsValid) {
  const std::string xml = to_junit(RunReport{});
  auto root = XmlReader(xml).document();
  EXPECT_EQ(root->attrs["tests"], "0");
  EXPECT_TRUE(root->all("testsuite").empty());
}

TEST(JunitReport, UnwritablePathIsAnError) {
  auto r = write_junit(RunReport{}, "/proc/shaderbed/r.xml");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().file, "/proc/shaderbed/r.xml");
}

}  // namespace
}  // namespace shaderbed
