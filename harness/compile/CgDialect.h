#pragma once
// The Cg dialect layer. There is no Cg compiler on this machine (the NVIDIA Cg Toolkit
// is deprecated and not packaged); Cg is HLSL's sibling, so a Cg program is rewritten
// into the DX9-style HLSL that glslang's HLSL front end reads, keeping every line where
// it was so errors point into the author's files. The passes, in order:
//
//   1. prepare_cg_file (each file, as read, before preprocessing): Cg #pragma directives
//      are stripped with a reason (profile options, bindings, `once`, which the includer
//      honours), and Cg's `x` (fixed) literal suffix is dropped — glslang's preprocessor
//      would split 0.5x into "0.5 x".
//   2. glslang preprocesses (includes resolved relative to the including file; see
//      CgFrontEnd.h); the output carries `#line N "file"` markers.
//   3. translate_cg (the preprocessed text, so #if'd-out code is not judged): rejects
//      unsupported Cg constructs with one named error at file:line, maps Cg types and
//      semantics to HLSL, and rewrites the entry signature where glslang needs it.
//   4. after SPIR-V generation, assign_cg_varying_locations gives every varying the
//      location its Cg semantic names (TEXCOORDn -> n, COLOR0 -> 8, COLOR1 -> 9), so a
//      fragment program that reads only TEXCOORD1 links with a vertex program that
//      writes TEXCOORD0..2, as it does under Cg (glslang would number by order).
//
// Supported: half, half1..4, halfNxM, fixed, fixed1..4, fixedNxM (all fp32: Cg's
// reduced precision and fixed's [-2, 2) range are NOT emulated); uniform parameters of
// the entry function (they become $Global members with their Cg names; uniform sampler
// parameters are hoisted to globals so they get distinct bindings); `varying`; `lit`
// (a correct helper: glslang 12 miscompiles lit); tex1D/tex2D/tex3D/texCUBE with their
// lod/bias/grad forms, tex3Dproj; semantics POSITION/HPOS, COLOR/COL, COLOR0-1/COL0-1,
// TEXCOORD0-7/TEX0-7, NORMAL, TANGENT, BINORMAL, WPOS (the fragment coordinate, origin
// upper left as glslang's HLSL declares it), FACE (on an entry
// parameter: +1 front, -1 back, as Cg), DEPTH/DEPR, PSIZE/PSIZ (vertex output),
// TEXUNITn (sampler unit -> register(sN)), ATTR0-15 (vertex inputs, NVIDIA's aliasing:
// 0 POSITION, 2 NORMAL, 3/4 COLOR0/1, 8-15 TEXCOORD0-7 with 14 TANGENT, 15 BINORMAL).
//
// Unsupported (one error naming the construct, its file and line): rectangle textures
// (texRECT*, samplerRECT), tex1Dproj/tex2Dproj (Cg divides by the last of float2/float3
// and treats the longer form as a depth comparison; HLSL divides by .w), texCUBEproj,
// buffer textures (samplerBUF, texBUF*), typed lookups (f1tex2D, h4tex2D ...), Cg
// interfaces, `packed`, unsized array parameters, pack_*/unpack_*, noise (crashes
// glslang), semantics BCOL0/BCOL1, FOG/FOGP/FOGC/FOGCOORD, CLP0-5, PSIZE on a fragment
// input, WPOS/FACE in a vertex program, FACE inside a struct, ATTRn in a fragment
// program, and the depth-compare lookup form tex2D(sampler2D, float3) (caught on the
// AST). A varying without a semantic, or with one that is not a Cg varying (NORMAL as a
// vertex output), and varyings whose locations overlap are errors too: Cg would reject
// them, and glslang would link them by declaration order instead.
//
// Known differences that are not errors: WPOS has its origin upper left (as Cg's D3D
// profiles; Cg's OpenGL profiles put it lower left); COLOR outputs are not clamped to [0, 1] as
// arbvp1 did (errata E13); Cg runtime calls (cgSetParameter...) are the harness's
// uniform binding by name.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "compile/ShaderModule.h"
#include "core/Error.h"

namespace shaderbed {

// Something the dialect did on the author's behalf, with where and why.
struct CgNote {
  std::string file;
  int line = 0;
  std::string text;
};

// A semantic as written and what it became, where it was written (for errors found
// later, on the SPIR-V).
struct CgSemanticUse {
  std::string written;  // upper case, as in the source (e.g. "COL0")
  std::string mapped;   // upper case, as given to glslang (e.g. "COLOR0")
  std::string file;
  int line = 0;
};

struct CgPreparedFile {
  std::string text;  // same number of lines as the input
  bool pragma_once = false;
  std::vector<CgNote> notes;
};

struct CgTranslation {
  std::string text;     // HLSL for glslang; same lines (and #line markers) as the input
  std::string helpers;  // HLSL helper functions the text calls (for the preamble)
  std::vector<CgNote> notes;
  std::vector<CgSemanticUse> semantics;
  std::string entry_file;  // where the entry function's definition starts
  int entry_line = 0;
};

// Pass 1, on one file as read. Never fails on valid input; kept as Result for symmetry.
Result<CgPreparedFile> prepare_cg_file(std::string_view text, const std::string& path);

// Pass 3, on glslang's preprocessed output of the whole program. `path` names the text
// until its first #line marker.
Result<CgTranslation> translate_cg(std::string_view preprocessed, const std::string& path, Stage stage,
                                   const std::string& entry_point);

// Pass 4: rewrites the Location decorations of the stage's varyings (and fragment colour
// outputs) from their semantics, in place. Errors name the semantic and, when the
// translation saw it, its file and line.
Result<void> assign_cg_varying_locations(std::vector<uint32_t>& spirv, Stage stage, const CgTranslation& translation,
                                         const std::string& path);

// The location a Cg varying semantic links through (TEXCOORDn -> n, COLOR/COLOR0 -> 8,
// COLOR1 -> 9); -1 if the semantic is not a Cg varying.
int cg_varying_location(std::string_view semantic);

}  // namespace shaderbed
