#pragma once
// A draw's RenderState (backends/RenderState.h) as GL state: culling, depth, blending,
// polygon mode. Applied after GlRenderer's fixed state, before every draw.
#include "pipeline/RenderState.h"
#include "backends/gl/GlFunctions.h"

namespace shaderbed::gl {

void apply_render_state(const GlFunctions& gl, const RenderState& state);

}  // namespace shaderbed::gl
