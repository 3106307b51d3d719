#pragma once
// GL failures as shaderbed::Error values. glGetError is drained (it can hold several
// flags) and every code is named, so a failed call reads as a sentence, not a number.
#include <string>
#include <string_view>

#include "backends/gl/GlFunctions.h"
#include "core/Error.h"

namespace shaderbed::gl {

// stage "gl", backend "gl".
Error gl_error(std::string message);

// "GL_INVALID_OPERATION, GL_OUT_OF_MEMORY" for the pending flags; empty when none.
std::string drain_gl_errors(const GlFunctions& gl);

// An error naming what was being done when GL raised a flag; success when none.
Result<void> check_gl(const GlFunctions& gl, std::string_view what);

}  // namespace shaderbed::gl
