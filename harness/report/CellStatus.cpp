#include "report/Results.h"

namespace shaderbed {

const char* to_string(CellStatus s) {
  switch (s) {
    case CellStatus::pass: return "pass";
    case CellStatus::fail: return "fail";
    case CellStatus::error: return "error";
    case CellStatus::skipped: return "skipped";
  }
  return "?";
}

std::optional<CellStatus> parse_cell_status(std::string_view text) {
  for (CellStatus s : {CellStatus::pass, CellStatus::fail, CellStatus::error, CellStatus::skipped})
    if (text == to_string(s)) return s;
  return std::nullopt;
}

}  // namespace shaderbed
