#include "core/WritablePath.h"

#include <limits.h>
#include <unistd.h>

#include <filesystem>

namespace shaderbed {
namespace fs = std::filesystem;

Result<void> check_writable_folder(const std::string& path, const std::string& what) {
  auto bad = [&](const std::string& why) {
    return std::unexpected(Error{.message = what + ": cannot write into '" + path + "': " + why, .stage = ErrorStage::options});
  };
  std::error_code ec;
  if (!fs::exists(path, ec)) fs::create_directories(path, ec);
  if (ec) return bad(ec.message());
  if (!fs::is_directory(path, ec)) return bad("not a folder");
  if (::access(path.c_str(), W_OK) != 0) return bad("permission denied");
  return {};
}

Result<void> check_writable_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    return std::unexpected(Error{.message = what + ": '" + path + "' is a folder, not a file", .stage = ErrorStage::options});
  // Found now, not when the run is over and its report cannot be created.
  if (const size_t length = fs::path(path).filename().string().size(); length > NAME_MAX)
    return std::unexpected(Error{.message = what + ": the file name is " + std::to_string(length) +
                                            " bytes long; this system allows " + std::to_string(NAME_MAX),
                                 .file = path, .stage = ErrorStage::options});
  const fs::path parent = fs::path(path).parent_path();
  return check_writable_folder(parent.empty() ? "." : parent.string(), what);
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec), cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return ca == cb;
}

Result<void> check_not_an_input(const std::string& output, const std::string& what,
                                const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs)
    if (!input.empty() && same_file(output, input))
      return std::unexpected(Error{.message = what + ": '" + output + "' is " +
                                              (output == input ? "one of the inputs" : "the input '" + input + "'") +
                                              "; writing it would destroy it (choose another path)",
                                   .stage = ErrorStage::options});
  return {};
}

}  // namespace shaderbed
