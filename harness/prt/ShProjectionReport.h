#pragma once
// What `shaderbed sh project` prints: the coefficients (index i = l(l+1)+m, l, m, values)
// and the largest differences, as text or as JSON.
#include <string>

#include "prt/ShProjection.h"

namespace shaderbed {

// The whole of stdout, final newline included.
std::string sh_projection_report(const ShProjection& projection, bool json);

}  // namespace shaderbed
