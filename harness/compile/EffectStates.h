#pragma once
// What a DX9 effect's state assignments mean: sampler_state blocks (SamplerSettings) and
// a pass's render states and `compile` statements. Every state is applied, ignored with a
// note because it cannot change the image shaderbed draws (fixed-function vertex
// lighting when a vertex shader is bound, say), or refused with one error naming the
// state and its line: never silently dropped.
//
// Sampler states: Texture, MinFilter, MagFilter (POINT, LINEAR, ANISOTROPIC: drawn as
// LINEAR, noted), MipFilter (NONE, POINT, LINEAR), AddressU/V/W (WRAP, MIRROR, CLAMP,
// BORDER), BorderColor (0xAARRGGBB or float4), SRGBTexture; MaxAnisotropy is ignored;
// MipMapLodBias and MaxMipLevel only at 0.
// Pass states: VertexShader/PixelShader (`compile PROFILE F(args)`; SM4's
// SetVertexShader(CompileShader(PROFILE, F(args))) too), CullMode (NONE, CW, CCW),
// ZEnable, ZWriteEnable, ZFunc, AlphaBlendEnable, SrcBlend, DestBlend, BlendOp, FillMode
// (SOLID, WIREFRAME, POINT); values as D3D spells them, with or without the D3DCULL_ /
// D3DBLEND_ ... prefix, case-insensitive. Ignored with a note: Lighting, SpecularEnable,
// ColorVertex, NormalizeNormals, LocalViewer, the *MaterialSource states, Ambient,
// DitherEnable, MultiSampleAntialias; and at their default only: FogEnable,
// AlphaTestEnable, StencilEnable, ScissorTestEnable, SeparateAlphaBlendEnable,
// SRGBWriteEnable, ColorWriteEnable (all channels), ClipPlaneEnable.
#include <optional>
#include <string>
#include <vector>

#include "pipeline/RenderState.h"
#include "compile/EffectFile.h"

namespace shaderbed {

// `compile vs_2_0 VS(true, 2)`: the profile, the entry function and the arguments for
// its uniform parameters, as written.
struct EffectShaderCompile {
  std::string profile;
  std::string function;
  std::vector<std::string> arguments;
  int line = 0;
  int shader_model = 2;   // from the profile: vs_2_0 -> 2, ps_3_0 -> 3, vs_4_0 -> 4
};

struct EffectPassStates {
  RenderState render_state;
  std::optional<EffectShaderCompile> vertex;
  std::optional<EffectShaderCompile> pixel;
  std::vector<EffectNote> notes;
};

// One assignment of a sampler_state block, applied to `sampler`.
Result<void> apply_sampler_state(const EffectAssignment& state, EffectSampler& sampler, const std::string& path,
                                 std::vector<EffectNote>& notes);

// The pass's states, interpreted (see above).
Result<EffectPassStates> interpret_pass(const EffectPass& pass, const std::string& path);

}  // namespace shaderbed
