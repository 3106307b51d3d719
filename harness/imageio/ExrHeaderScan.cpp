#include "imageio/ExrHeaderScan.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <optional>

#include <fmt/format.h>

namespace shaderbed {
namespace {

Error header_error(const std::string& message, const std::string& path) {
  return Error{.message = message, .file = path, .stage = ErrorStage::image};
}

// A NUL-terminated name of at most 255 characters (the long-name limit), or nullopt.
std::optional<std::string> read_name(std::ifstream& in) {
  std::string name;
  for (char c; in.get(c);) {
    if (c == '\0') return name;
    if (name.size() == 255) return std::nullopt;
    name += c;
  }
  return std::nullopt;
}

}  // namespace

Result<void> check_exr_header_sizes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 8> start{};
  if (!in.read(reinterpret_cast<char*>(start.data()), start.size())) return {};
  if (start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 || start[3] != 0x01) return {};
  in.seekg(0, std::ios::end);
  const std::int64_t size = in.tellg();
  in.seekg(8);
  const bool multipart = (start[5] & 0x10) != 0;   // version field bit 12
  // Single-part: one header. Multi-part: headers until an empty one.
  for (;;) {
    for (;;) {
      const auto name = read_name(in);
      if (!name) return std::unexpected(header_error("EXR header does not end (a name without its NUL)", path));
      if (name->empty()) break;
      const auto type = read_name(in);
      std::array<unsigned char, 4> bytes{};
      if (!type || !in.read(reinterpret_cast<char*>(bytes.data()), bytes.size()))
        return std::unexpected(header_error(fmt::format("EXR header attribute '{}' is cut short", *name), path));
      const std::int32_t declared = std::int32_t(std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 |
                                                 std::uint32_t(bytes[2]) << 16 | std::uint32_t(bytes[3]) << 24);
      const std::int64_t left = size - std::int64_t(in.tellg());
      if (declared < 0 || declared > left)
        return std::unexpected(header_error(
            fmt::format("EXR header attribute '{}' ({}) declares {} bytes, more than the {}-byte file holds", *name,
                        *type, declared, size),
            path));
      in.seekg(declared, std::ios::cur);
    }
    if (!multipart) return {};
    if (in.peek() == 0) return {};   // the empty header after the last part
    if (in.peek() == std::ifstream::traits_type::eof())
      return std::unexpected(header_error("EXR multi-part headers do not end", path));
  }
}

}  // namespace shaderbed
