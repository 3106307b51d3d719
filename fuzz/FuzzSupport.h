#pragma once
// What the fuzz targets share: turning libFuzzer's bytes into the inputs the layers take.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

#include <unistd.h>

#include "compile/ShaderModule.h"

namespace shaderbed::fuzz {

inline std::string_view as_text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The loaders read a path: one file per process, rewritten per input. `folder` is a path
// under the process's own scratch folder, so a case file can sit in a `cases/` folder as
// the library's do (shader paths then resolve against its parent).
inline std::string write_scratch(std::string_view text, const std::string& folder, const std::string& name) {
  // Removed when the fuzzer exits normally (a crash leaves it, next to the crash's input).
  struct ScratchRoot {
    std::filesystem::path path;
    ~ScratchRoot() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const ScratchRoot root{std::filesystem::temp_directory_path() / ("shaderbed-fuzz-" + std::to_string(getpid()))};
  const std::filesystem::path dir = root.path / folder;
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / name;
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(text.data(), std::streamsize(text.size()));
  return file.string();
}

// Shader inputs may start with a header line naming the stage and entry point, as the
// seed corpus does ("//fuzz vertex basicLight_v"); without one, the first byte picks the
// stage and the entry is main, so any bytes still make an input.
struct ShaderInput {
  Stage stage = Stage::vertex;
  std::string entry = "main";
  std::string_view text;
};

inline ShaderInput shader_input(std::string_view data) {
  ShaderInput in;
  in.text = data;
  in.stage = (!data.empty() && (data[0] & 1)) ? Stage::fragment : Stage::vertex;
  constexpr std::string_view tag = "//fuzz ";
  if (!data.starts_with(tag)) return in;
  const size_t end = data.find('\n');
  std::string_view header = data.substr(tag.size(), end == std::string_view::npos ? std::string_view::npos : end - tag.size());
  in.text = end == std::string_view::npos ? std::string_view{} : data.substr(end + 1);
  const size_t space = header.find(' ');
  const std::string_view stage = header.substr(0, space);
  in.stage = stage == "fragment" ? Stage::fragment : Stage::vertex;
  if (space != std::string_view::npos && space + 1 < header.size() && header.size() - space < 64)
    in.entry = std::string(header.substr(space + 1));
  return in;
}

// Two stages in one input, split at a line "//fuzz fragment" (the seed corpus's form);
// without one, both stages get the whole input.
struct StagePair {
  std::string_view vertex, fragment;
};

inline StagePair stage_pair(std::string_view data) {
  constexpr std::string_view mark = "\n//fuzz fragment\n";
  const size_t at = data.find(mark);
  if (at == std::string_view::npos) return {data, data};
  return {data.substr(0, at + 1), data.substr(at + mark.size())};
}

}  // namespace shaderbed::fuzz
