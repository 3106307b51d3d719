#pragma once
// Feeds a program's uniforms from the resolver: each block packed by its reflected
// layout into its own uniform buffer, each loose (default-block) uniform with
// glProgramUniform*. A value the resolver cannot supply is an error naming the uniform.
#include <vector>

#include "backends/UniformPacking.h"
#include "backends/gl/GlObject.h"
#include "backends/gl/GlProgramInterface.h"

namespace shaderbed::gl {

// The buffers stay bound to their binding points; keep them alive until the draw is done.
Result<std::vector<GlBuffer>> upload_uniform_blocks(const GlFunctions& gl, const std::vector<UniformBlock>& blocks,
                                                    const UniformResolver& resolver);

Result<void> set_loose_uniforms(const GlFunctions& gl, GLuint program, const std::vector<LooseUniform>& uniforms,
                                const UniformResolver& resolver);

}  // namespace shaderbed::gl
