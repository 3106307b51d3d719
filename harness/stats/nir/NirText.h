#pragma once
// Counting Mesa's NIR as printed by nir_print_shader (Mesa 22.3): ALU, texture and
// control-flow instructions of one shader, and pulling those shaders out of the text the
// driver writes (a GALLIUM_TRACE XML file, or MESA_GLSL=dump's stderr).
#include <string>
#include <string_view>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

struct NirCounts {
  int alu = 0;        // ALU instructions (fmul, fadd, vec3, mov, flt, bcsel...), load_const excluded
  int tex = 0;        // texture instructions (tex, txb, txl, txd, txf, txs, tg4, lod, ...)
  int control = 0;    // ifs + loops + jumps
  int ifs = 0;
  int loops = 0;
  int jumps = 0;      // break, continue, return, halt, goto
  int intrinsics = 0; // loads/stores and other intrinsics (not part of the three classes)
  int load_consts = 0;
};

// One shader found in driver output.
struct NirShader {
  Stage stage = Stage::vertex;
  std::string text;   // the NIR as printed, XML entities decoded
};

// Counts one shader's NIR text. An error when the text holds no function body ("impl"),
// so a wrong capture never reads as zero instructions.
Result<NirCounts> count_nir(std::string_view nir_text);

// Every vertex and fragment shader NIR in a GALLIUM_TRACE XML file (GALLIUM_TRACE_NIR set
// high enough), in creation order. Other stages are skipped.
std::vector<NirShader> nir_from_gallium_trace(std::string_view trace_xml);

// Every vertex and fragment shader NIR printed on stderr (MESA_GLSL=dump on GL prints the
// NIR of linked programs as "NIR for ... shader"/"shader: MESA_SHADER_..." blocks).
std::vector<NirShader> nir_from_printed_text(std::string_view text);

}  // namespace shaderbed
