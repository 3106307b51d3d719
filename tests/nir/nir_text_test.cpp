// The NIR counter on hand-trimmed samples of what Mesa 22.3.6 prints on this machine
// (lavapipe GALLIUM_TRACE XML, OSMesa MESA_GLSL=dump stderr); counts worked out by hand.
#include <gtest/gtest.h>

#include "stats/nir/NirText.h"

namespace shaderbed {
namespace {

// A fragment shader as nir_print prints it: 3 load_const, 4 intrinsics, 2 derefs,
// ALU: fmul, fadd, vec3, flt, fsqrt, bcsel = 6; one tex; one if, one loop with a break.
const char* kFragment = R"(shader: MESA_SHADER_FRAGMENT
source_sha1: {0x00000000, 0x00000000, 0x00000000, 0x00000000, 0x00000000}
inputs: 2
decl_var shader_in INTERP_MODE_NONE vec3 In.Normal (VARYING_SLOT_VAR1.xyz, 1, 0)
decl_function main (0 params)

impl main {
	block block_0:
	/* preds: */
	vec1 32 ssa_0 = deref_var &In.Normal (shader_in vec3) 
	vec3 32 ssa_1 = intrinsic load_deref (ssa_0) (access=0)
	vec1 32 ssa_2 = load_const (0x3f800000 = 1.000000)
	vec1 32 ssa_3 = load_const (0x00000000 = 0.000000)
	vec1 32 ssa_4 = load_const (0x40000000 = 2.000000)
	vec1 32 ssa_5 = fmul ssa_1.x, ssa_1.x
	vec1 32 ssa_6 = fadd ssa_5, ssa_2
	vec3 32 ssa_7 = vec3 ssa_5, ssa_6, ssa_3
	vec4 32 ssa_8 = (float32)tex ssa_7 (coord), 0 (texture), 0 (sampler)
	vec1 1 ssa_9 = flt ssa_3, ssa_6
	/* succs: block_1 block_2 */
	if ssa_9 {
		block block_1:
		/* preds: block_0 */
		vec1 32 ssa_10 = fsqrt ssa_6
		/* succs: block_3 */
	} else {
		block block_2:
		/* preds: block_0 */
		/* succs: block_3 */
	}
	block block_3:
	/* preds: block_1 block_2 */
	vec1 32 ssa_11 = phi block_1: ssa_10, block_2: ssa_3
	loop {
		block block_4:
		/* preds: block_3 block_4 */
		break
		/* succs: block_5 */
	}
	block block_5:
	vec1 32 ssa_12 = bcsel ssa_9, ssa_11, ssa_4
	vec4 32 ssa_13 = intrinsic load_ubo (ssa_3, ssa_3) (access=0, align_mul=4, align_offset=0, range_base=0, range=-1)
	vec1 32 ssa_14 = deref_var &@entryPointOutput (shader_out vec4) 
	intrinsic store_deref (ssa_14, ssa_8) (wrmask=xyzw /*15*/, access=0)
	/* succs: block_6 */
	block block_6:
}
)";

TEST(NirText, CountsAluTextureAndControlFlowByHand) {
  auto c = count_nir(kFragment);
  ASSERT_TRUE(c) << c.error().to_string();
  EXPECT_EQ(c->alu, 6);
  EXPECT_EQ(c->tex, 1);
  EXPECT_EQ(c->ifs, 1);
  EXPECT_EQ(c->loops, 1);
  EXPECT_EQ(c->jumps, 1);
  EXPECT_EQ(c->control, 3);
  EXPECT_EQ(c->load_consts, 3);
  EXPECT_EQ(c->intrinsics, 3);   // load_deref, load_ubo, store_deref
}

TEST(NirText, TextWithoutAFunctionBodyIsAnErrorNotZero) {
  EXPECT_FALSE(count_nir(""));
  EXPECT_FALSE(count_nir("(declare (uniform ) mat4 modelViewProjection)\n"));
}

TEST(NirText, UntypedTextureOpcodesAndExactAluMarkersCount) {
  auto c = count_nir("impl main {\n\tvec4 32 ssa_2 = txl ssa_1 (coord), ssa_0 (lod)\n"
                     "\tvec1 32 ssa_3 = fmul! ssa_2.x, ssa_2.y\n\tvec1 32 ssa_4 = txs ssa_0 (lod)\n}\n");
  ASSERT_TRUE(c);
  EXPECT_EQ(c->tex, 2);
  EXPECT_EQ(c->alu, 1);
}

// lavapipe's GALLIUM_TRACE=file GALLIUM_TRACE_NIR=1000000 output, trimmed: the NIR is the
// CDATA of the create_*_state call's 'ir' member.
TEST(NirText, ShadersComeOutOfAGalliumTraceInOrder) {
  const std::string xml =
      "<trace version='0.1'>\n\t<call no='40' class='pipe_context' method='create_vs_state'>\n"
      "\t\t<arg name='state'><struct name='pipe_shader_state'><member name='type'><uint>2</uint></member>"
      "<member name='ir'><string><![CDATA[shader: MESA_SHADER_VERTEX\nimpl main {\n\tblock block_0:\n"
      "\tvec1 32 ssa_1 = fmul ssa_0, ssa_0\n}\n]]></string></member></struct></arg>\n\t</call>\n"
      "\t<call no='41' class='pipe_context' method='create_fs_state'>\n"
      "\t\t<arg name='state'><struct name='pipe_shader_state'><member name='ir'><string><![CDATA["
      "shader: MESA_SHADER_FRAGMENT\nimpl main {\n\tvec1 32 ssa_1 = fadd ssa_0, ssa_0\n"
      "\tvec1 32 ssa_2 = fmul ssa_1, ssa_1\n}\n]]></string></member></struct></arg>\n\t</call>\n</trace>\n";
  const auto shaders = nir_from_gallium_trace(xml);
  ASSERT_EQ(shaders.size(), 2u);
  EXPECT_EQ(shaders[0].stage, Stage::vertex);
  EXPECT_EQ(shaders[1].stage, Stage::fragment);
  EXPECT_EQ(count_nir(shaders[0].text)->alu, 1);
  EXPECT_EQ(count_nir(shaders[1].text)->alu, 2);
}

// OSMesa's MESA_GLSL=dump stderr, trimmed: GLSL IR, then the NIR of each linked stage,
// then the GLSL IR and NIR of a shader st makes itself; the GLSL IR between shaders must
// not leak into the counts.
TEST(NirText, ShadersComeOutOfMesaGlslDumpWithoutTheGlslIr) {
  const std::string err =
      "(\n(declare (uniform ) mat4 modelViewProjection)\n)\n"
      "shader: MESA_SHADER_FRAGMENT\nsource_sha1: {0x1, 0x2, 0x3, 0x4, 0x5}\nname: GLSL3\n"
      "impl main {\n\tblock block_0:\n\tvec1 32 ssa_3 = fmul ssa_1, ssa_2\n\tblock block_1:\n}\n\n"
      "( function main\n  (signature void\n    (\n      (assign  (xyzw) (var_ref gl_FragColor) "
      "(var_ref gl_CurrentAttribFrag2MESA) ) \n    ))\n)\n"
      "shader: MESA_SHADER_FRAGMENT\nname: GLSL0\nimpl main {\n"
      "\tvec4 32 ssa_8 = intrinsic load_ubo (ssa_5, ssa_9) (access=0)\n}\n";
  const auto shaders = nir_from_printed_text(err);
  ASSERT_EQ(shaders.size(), 2u);
  auto first = count_nir(shaders[0].text);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->alu, 1);
  EXPECT_EQ(first->control, 0);
  EXPECT_EQ(count_nir(shaders[1].text)->alu, 0);
}

}  // namespace
}  // namespace shaderbed
