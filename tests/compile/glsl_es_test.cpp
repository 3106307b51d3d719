// GLSL ES as WebGL writes it (compile/GlslProfile.h, GlslDialect.h): which sources are
// ES, which declare reduced precision, and what glslang and Mesa are given.
#include <gtest/gtest.h>

#include "compile/GlslDialect.h"
#include "compile/GlslProfile.h"

namespace shaderbed {
namespace {

bool es(const std::string& text) { return is_glsl_es(glsl_version(text), text); }

TEST(GlslEs, VersionsAndUnversionedWebGl1) {
  EXPECT_TRUE(es("#version 100\nvoid main() {}\n"));
  EXPECT_TRUE(es("#version 300 es\nprecision highp float;\n"));
  EXPECT_TRUE(es("// WebGL 1\nprecision mediump float;\nvoid main() {}\n"));
  EXPECT_FALSE(es("void main() { gl_FragColor = vec4(1.0); }\n"));      // desktop 1.10
  EXPECT_FALSE(es("#version 330 core\nprecision highp float;\n"));      // desktop, precision ignored
  EXPECT_TRUE(declares_reduced_precision("precision mediump float;\n"));
  EXPECT_TRUE(declares_reduced_precision("uniform lowp vec4 c;\n"));
  EXPECT_FALSE(declares_reduced_precision("precision highp float; // not mediump\n"));
}

ProgramSource program(const std::string& vs, const std::string& fs) {
  return {.language = Language::glsl,
          .vertex = {.stage = Stage::vertex, .path = "a.vert", .text = vs},
          .fragment = {.stage = Stage::fragment, .path = "a.frag", .text = fs}};
}

TEST(GlslEs, Es300IsCompiledAs310OnItsLineAndMesaGetsItAsWritten) {
  const std::string vs = "// c\n#version 300 es\nin vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n";
  const std::string fs = "#version 300 es\nprecision mediump float;\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
  auto prepared = prepare_glsl_program(program(vs, fs));
  ASSERT_TRUE(prepared) << prepared.error().to_string();
  EXPECT_NE(prepared->program.vertex.text.find("// c\n#version 310 es\n"), std::string::npos)
      << prepared->program.vertex.text;
  EXPECT_EQ(prepared->native_vertex, vs);
  EXPECT_EQ(prepared->native_fragment, fs);
  EXPECT_TRUE(prepared->native_reduced_precision);
}

TEST(GlslEs, UnversionedWebGl1GetsVersion100ForMesaOnly) {
  const std::string vs = "precision highp float;\nattribute vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n";
  const std::string fs = "precision highp float;\nvoid main() { gl_FragColor = vec4(1.0); }\n";
  auto prepared = prepare_glsl_program(program(vs, fs));
  ASSERT_TRUE(prepared) << prepared.error().to_string();
  EXPECT_EQ(prepared->native_vertex, "#version 100\n#line 1\n" + vs);
  EXPECT_EQ(prepared->native_fragment, "#version 100\n#line 1\n" + fs);
  EXPECT_FALSE(prepared->native_reduced_precision);   // highp only
}

}  // namespace
}  // namespace shaderbed
