#pragma once
// Screenshots: what the window shows as PNG (read back from the window, one image pixel
// per pixel) and the render, exact, as EXR; in split view the reference and the
// error image too, each as PNG and EXR. Written whole (OpenImageIO, through the image
// module), into folders created as needed.
#include <string>
#include <vector>

#include "core/Error.h"
#include "viewer/CellRenderer.h"
#include "viewer/SplitView.h"

namespace shaderbed::viewer {

// STEM.png (the window's content), STEM.exr (the render: RGBA exactly as drawn); in split
// view also STEM.render.png, STEM.reference.{png,exr} and STEM.error.{png,exr}. The files
// written, in that order.
Result<std::vector<std::string>> write_screenshot(const std::string& stem, const Frame& frame,
                                                  const DisplayImage& shown, bool split);

// Next to the case's outputs, as `run --out DIR` lays them out:
// DIR/<case>/<variant>/<shape>/<language>-<backend>-<path>.view-N, N the first number
// whose PNG does not exist yet.
std::string next_screenshot_stem(const std::string& out_dir, const ViewerState& state);

// FILE without a .png or .exr extension.
std::string screenshot_stem(const std::string& file);

}  // namespace shaderbed::viewer
