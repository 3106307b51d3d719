#pragma once
// What `shaderbed sh eval` prints: the shape, the transfer, the light, how the exact
// integral was taken, and per band count the largest and the RMS error; as text or JSON.
#include <string>

#include "prt/ShLightingError.h"
#include "prt/ShTransferRun.h"

namespace shaderbed {

// The whole of stdout, final newline included.
std::string sh_lighting_error_report(const ShLightingErrorRequest& request, const ShLightingErrorSetup& setup,
                                     const ShTransferRun& run, const ShLightingError& error, bool json);

}  // namespace shaderbed
