#include "core/Error.h"

namespace shaderbed {

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
  if (!stage.empty()) {
    out += stage;
    if (!backend.empty()) out += '[' + backend + ']';
    out += ": ";
  } else if (!backend.empty()) {
    out += backend + ": ";
  }
  out += message;
  return out;
}

}  // namespace shaderbed
