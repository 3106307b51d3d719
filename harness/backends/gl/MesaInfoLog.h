#pragma once
// Mesa's GLSL compiler reports "0:12(3): error: `x' undeclared" (source string 0, line
// 12, column 3). The first error becomes the Error's line and column; the count of the
// others stays in the message so a cascade is visible without flooding one line.
#include <string>
#include <string_view>

namespace shaderbed::gl {

struct MesaLogError {
  int line = 0;        // 0 when the log names no position (e.g. linker errors)
  int column = 0;
  std::string message; // "`x' undeclared (+2 more errors)", or the first non-empty log line
};

MesaLogError first_mesa_error(std::string_view info_log);

}  // namespace shaderbed::gl
