#include "ConformanceShaders.h"

#include <cmath>

#include <fmt/format.h>

namespace shaderbed::conformance {
namespace {

bool hlsl_family(Language language) { return language != Language::glsl; }

// A float literal both front ends read back to the same float (9 significant digits).
std::string float_literal(double x) {
  if (x == 0) return std::signbit(x) ? "(-0.0)" : "0.0";
  std::string s = fmt::format("{:.9g}", std::abs(x));
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return x < 0 ? "(-" + s + ")" : s;
}

std::string literal(const Arg& a, Language language) {
  if (a.v.size() == 1) return float_literal(a.v[0]);
  const bool hlsl = hlsl_family(language);
  std::string type;
  std::vector<double> order;  // the constructor's argument order
  if (a.rows == 1) {
    type = (hlsl ? "float" : "vec") + std::to_string(a.cols);
    order = a.v;
  } else if (hlsl) {
    type = "float" + std::to_string(a.rows) + "x" + std::to_string(a.cols);  // rows, row by row
    order = a.v;
  } else {
    type = "mat" + std::to_string(a.cols) + "x" + std::to_string(a.rows);  // columns, column by column
    for (int c = 0; c < a.cols; ++c)
      for (int r = 0; r < a.rows; ++r) order.push_back(a.v[size_t(r * a.cols + c)]);
  }
  std::string s = type + "(";
  for (size_t i = 0; i < order.size(); ++i) s += (i ? ", " : "") + float_literal(order[i]);
  return s + ")";
}

std::string expression(const Check& c, Language language, bool runtime) {
  std::string text = hlsl_family(language) ? c.hlsl_cg : c.glsl;
  for (size_t k = c.args.size(); k-- > 0;) {  // $10 before $1
    std::string value = literal(c.args[k], language);
    if (runtime && !c.literal_only) value = "(" + value + " * One)";
    const std::string token = "$" + std::to_string(k);
    for (size_t at = text.find(token); at != std::string::npos; at = text.find(token, at + value.size()))
      text.replace(at, token.size(), value);
  }
  return "sb_pad" + std::to_string(c.expected.size()) + "(" + text + ")";
}

std::string pad_helpers(Language language) {
  const bool hlsl = hlsl_family(language);
  const std::string v4 = hlsl ? "float4" : "vec4";
  std::string s;
  for (int n = 1; n <= 4; ++n) {
    const std::string type = n == 1 ? "float" : (hlsl ? "float" : "vec") + std::to_string(n);
    std::string body = n == 1 ? "x, 0.0, 0.0, 0.0" : n == 2 ? "x, 0.0, 0.0" : n == 3 ? "x, 0.0" : "x";
    s += fmt::format("{} sb_pad{}({} x) {{ return {}({}); }}\n", v4, n, type, v4, body);
  }
  return s;
}

const char* const kHlslVertex =
    "// Conformance test shader: passes NDC positions through (tests/conformance).\n"
    "float4 main(float3 position : POSITION) : POSITION { return float4(position, 1.0); }\n";

const char* const kGlslVertex =
    "#version 450\n"
    "// Conformance test shader: passes NDC positions through (tests/conformance).\n"
    "layout(location = 0) in vec3 position;\n"
    "void main() { gl_Position = vec4(position, 1.0); }\n";

}  // namespace

int image_width(const std::vector<Check>& checks) { return int(2 * checks.size()); }

bool runs_in(const Check& c, Language language) {
  const unsigned bit = language == Language::hlsl ? kHlsl : language == Language::cg ? kCg : kGlsl;
  return (c.languages & bit) && !(hlsl_family(language) ? c.hlsl_cg : c.glsl).empty();
}

ProgramSource conformance_program(const std::vector<Check>& checks, Language language) {
  const bool hlsl = hlsl_family(language);
  const std::string v4 = hlsl ? "float4" : "vec4";
  std::string fs;
  if (!hlsl) fs += "#version 450\n";
  fs += std::string("// Conformance test shader: evaluates every ") + to_string(language) +
        " intrinsic check at pixel x (tests/conformance/IntrinsicChecks.cpp).\n";
  if (language == Language::hlsl)
    fs += "float One;\nsampler2D Tex;\n";
  else if (language == Language::cg)
    fs += "uniform float One;\nuniform sampler2D Tex;\n";
  else
    fs += "layout(std140, binding = 0) uniform Probe { float One; };\nlayout(binding = 1) uniform sampler2D Tex;\n"
          "layout(location = 0) out vec4 colour;\n";
  fs += pad_helpers(language);
  if (language == Language::hlsl)
    fs += "float4 main(float4 pos : SV_Position) : SV_Target\n{\n";
  else if (language == Language::cg)
    fs += "float4 main(float4 pos : WPOS) : COLOR\n{\n";
  else
    fs += "vec4 probe(vec4 pos)\n{\n";
  fs += hlsl ? "    int i = (int)pos.x;\n" : "    int i = int(pos.x);\n";
  // Flat ifs that assign, not a chain of early returns: Mesa lowers each return into one
  // more level of nesting, and llvmpipe (lavapipe and OSMesa alike) silently ran only the
  // first ~106 of them (every later pixel kept the fall-through value).
  std::string branches;
  for (size_t k = 0; k < checks.size(); ++k) {
    const Check& c = checks[k];
    if (!runs_in(c, language)) continue;
    const int folded = int(2 * k), runtime = folded + 1;
    if (c.uniform_flow) {
      fs += fmt::format("    {} u{} = {};\n", v4, k, expression(c, language, false));
      branches += fmt::format("    if (i == {} || i == {}) r = u{};\n", folded, runtime, k);
    } else {
      branches += fmt::format("    if (i == {}) r = {};\n", folded, expression(c, language, false));
      branches += fmt::format("    if (i == {}) r = {};\n", runtime, expression(c, language, true));
    }
  }
  fs += "    " + v4 + " r = " + v4 + "(0.0, 0.0, 0.0, 0.0);\n" + branches + "    return r;\n}\n";
  if (!hlsl) fs += "void main() { colour = probe(gl_FragCoord); }\n";

  ProgramSource p;
  p.language = language;
  const std::string ext = language == Language::hlsl ? ".hlsl" : language == Language::cg ? ".cg" : "";
  p.vertex = ShaderSource{.stage = Stage::vertex, .path = hlsl ? "conformance_vs" + ext : "conformance.vert",
                          .text = hlsl ? kHlslVertex : kGlslVertex};
  p.fragment = ShaderSource{.stage = Stage::fragment, .path = hlsl ? "conformance_ps" + ext : "conformance.frag",
                            .text = fs};
  return p;
}

}  // namespace shaderbed::conformance
