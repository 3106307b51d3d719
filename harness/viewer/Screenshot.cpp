#include "viewer/Screenshot.h"

#include <filesystem>

#include <fmt/format.h>

#include "compare/ErrorMap.h"
#include "compare/ImageFiles.h"
#include "imageio/ImageIoModule.h"

namespace shaderbed::viewer {
namespace fs = std::filesystem;

Result<std::vector<std::string>> write_screenshot(const std::string& stem, const Frame& frame,
                                                  const DisplayImage& shown, bool split) {
  if (!frame.render) return fail(ErrorStage::screenshot, "nothing has been drawn yet");
  std::vector<std::string> written;
  const auto add = [&](Result<void> ok, std::string file) -> Result<void> {
    if (!ok) return ok;
    written.push_back(std::move(file));
    return {};
  };
  const Image& render = *frame.render;
  if (auto ok = add(write_image_file(stem + ".png", shown.width, shown.height, 3, PixelType::uint8, shown.rgb.data()),
                    stem + ".png");
      !ok)
    return std::unexpected(ok.error());
  if (auto ok = add(write_exr(stem + ".exr", render.width, render.height, render.rgba), stem + ".exr"); !ok)
    return std::unexpected(ok.error());
  if (!split) return written;
  if (auto ok = add(write_png(stem + ".render.png", render), stem + ".render.png"); !ok)
    return std::unexpected(ok.error());
  if (frame.reference) {
    const Image reference = reference_as_image(*frame.reference);
    for (auto [ok, file] : {std::pair{write_png(stem + ".reference.png", reference), stem + ".reference.png"},
                            std::pair{write_exr(stem + ".reference.exr", reference.width, reference.height, reference.rgba),
                                      stem + ".reference.exr"}})
      if (auto added = add(ok, file); !added) return std::unexpected(added.error());
  }
  if (frame.error) {
    const Image& error = *frame.error;
    for (auto [ok, file] : {std::pair{write_error_map(stem + ".error.png", error_map(error, frame.interior_threshold)),
                                      stem + ".error.png"},
                            std::pair{write_exr(stem + ".error.exr", error.width, error.height, error.rgba),
                                      stem + ".error.exr"}})
      if (auto added = add(ok, file); !added) return std::unexpected(added.error());
  }
  return written;
}

std::string next_screenshot_stem(const std::string& out_dir, const ViewerState& s) {
  const fs::path dir = fs::path(out_dir) / s.menu.case_name / s.variant_name() / s.shape_name();
  const std::string cell = fmt::format("{}-{}-{}", to_string(s.language), s.backend, to_string(s.path));
  for (int n = 1;; ++n) {
    const fs::path stem = dir / fmt::format("{}.view-{}", cell, n);
    std::error_code ec;
    if (!fs::exists(stem.string() + ".png", ec)) return stem.string();
  }
}

std::string screenshot_stem(const std::string& file) {
  const fs::path p(file);
  if (p.extension() == ".png" || p.extension() == ".exr") return (p.parent_path() / p.stem()).string();
  return file;
}

}  // namespace shaderbed::viewer
