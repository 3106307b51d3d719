#pragma once
// FNV-1a, 64 bits: the one non-cryptographic hash for names and fingerprints (cache entry
// names, SPIR-V hashes in the results, keys in the HTML page). Never trusted alone where a
// collision would matter: cache entries carry their whole key.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace shaderbed {

constexpr uint64_t kFnv1aOffset = 0xcbf29ce484222325ull;

inline uint64_t fnv1a64(std::string_view bytes, uint64_t hash = kFnv1aOffset) {
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 0x100000001b3ull;
  }
  return hash;
}

// The words' bytes in memory order (little-endian here, as the results have always had).
inline uint64_t fnv1a64(const std::vector<uint32_t>& words) {
  return fnv1a64(std::string_view(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t)));
}

// 16 lower-case hex digits.
inline std::string hex64(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

}  // namespace shaderbed
