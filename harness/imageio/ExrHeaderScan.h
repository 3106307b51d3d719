#pragma once
// OpenEXR 3.1 allocates each header attribute at the size the file declares before it
// checks that the file holds that many bytes: a 752-byte file declaring a 1.8 GB string
// attribute takes 1.8 GB and seconds to refuse (texture_loader_fuzzer found it). So an
// EXR's headers are walked first, and every attribute must fit inside the file.
#include <string>

#include "core/Error.h"

namespace shaderbed {

// Nothing for a file that is not OpenEXR (by its magic number); for an EXR, an error
// naming the first attribute that does not fit, or a header that does not end.
Result<void> check_exr_header_sizes(const std::string& path);

}  // namespace shaderbed
