#pragma once
// SHA-256 (OpenSSL's libcrypto): the hash for what must not be forged or collide on
// purpose, such as compile-cache entries (compile/CompileCache.h). Fnv1a.h stays the
// hash for names and fingerprints where only accidents matter.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace shaderbed {

using Sha256Digest = std::array<uint8_t, 32>;

Sha256Digest sha256(std::string_view bytes);

// 64 lower-case hex digits.
std::string sha256_hex(std::string_view bytes);

}  // namespace shaderbed
