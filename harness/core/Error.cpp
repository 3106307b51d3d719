#include "core/Error.h"

namespace shaderbed {

const char* to_string(ErrorStage s) {
  switch (s) {
    case ErrorStage::none: return "";
    case ErrorStage::against: return "--against";
    case ErrorStage::backend: return "backend";
    case ErrorStage::bench: return "bench";
    case ErrorStage::bind: return "bind";
    case ErrorStage::case_file: return "case";
    case ErrorStage::compile: return "compile";
    case ErrorStage::counterfactual: return "counterfactual";
    case ErrorStage::cross_compile: return "cross-compile";
    case ErrorStage::display: return "display";
    case ErrorStage::draw: return "draw";
    case ErrorStage::expectations: return "expectations";
    case ErrorStage::gl: return "gl";
    case ErrorStage::image: return "image";
    case ErrorStage::init: return "init";
    case ErrorStage::isolation: return "isolation";
    case ErrorStage::lut: return "lut";
    case ErrorStage::merge: return "merge";
    case ErrorStage::nir: return "nir";
    case ErrorStage::optimize: return "optimize";
    case ErrorStage::options: return "options";
    case ErrorStage::plot: return "plot";
    case ErrorStage::port: return "port";
    case ErrorStage::reference: return "reference";
    case ErrorStage::reflect: return "reflect";
    case ErrorStage::report: return "report";
    case ErrorStage::screenshot: return "screenshot";
    case ErrorStage::sh: return "sh";
    case ErrorStage::stats: return "stats";
    case ErrorStage::stored_images: return "stored images";
    case ErrorStage::sweep: return "sweep";
    case ErrorStage::texture: return "texture";
    case ErrorStage::validate: return "validate";
    case ErrorStage::viewer: return "viewer";
    case ErrorStage::twin: return "twin";
    case ErrorStage::vulkan: return "vulkan";
    case ErrorStage::worker: return "worker";
  }
  return "?";
}

std::optional<ErrorStage> parse_error_stage(std::string_view text) {
  for (int s = int(ErrorStage::none); s <= int(ErrorStage::worker); ++s)
    if (text == to_string(ErrorStage(s))) return ErrorStage(s);
  return std::nullopt;
}

std::string Error::to_string() const {
  std::string out;
  if (!file.empty()) {
    out += file;
    if (line > 0) {
      out += ':' + std::to_string(line);
      if (column > 0) out += ':' + std::to_string(column);
    }
    out += ": ";
  }
  if (stage != ErrorStage::none) {
    out += shaderbed::to_string(stage);
    if (!backend.empty()) out += '[' + backend + ']';
    out += ": ";
  } else if (!backend.empty()) {
    out += backend + ": ";
  }
  out += message;
  return out;
}

}  // namespace shaderbed
