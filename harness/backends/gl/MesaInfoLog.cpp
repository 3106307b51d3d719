#include "backends/gl/MesaInfoLog.h"

#include <regex>
#include <string>

namespace shaderbed::gl {
namespace {

std::string trim(std::string s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

}  // namespace

MesaLogError first_mesa_error(std::string_view info_log) {
  const std::string log(info_log);
  // "0:12(3): error: ..." and "0:12(3): preprocessor error: ...".
  static const std::regex positioned(R"((\d+):(\d+)\((\d+)\): (?:preprocessor )?error: ([^\n]*))");
  static const std::regex unpositioned(R"((?:^|\n)\s*error: ([^\n]*))");

  MesaLogError result;
  int errors = 0;
  for (auto it = std::sregex_iterator(log.begin(), log.end(), positioned); it != std::sregex_iterator(); ++it) {
    if (errors++ == 0) {
      result.line = std::stoi((*it)[2].str());
      result.column = std::stoi((*it)[3].str());
      result.message = trim((*it)[4].str());
    }
  }
  if (errors == 0) {
    for (auto it = std::sregex_iterator(log.begin(), log.end(), unpositioned); it != std::sregex_iterator(); ++it)
      if (errors++ == 0) result.message = trim((*it)[1].str());
  }
  if (errors == 0) {
    // Not in a format we know: keep the first line that says something.
    size_t start = 0;
    while (start < log.size() && result.message.empty()) {
      const size_t end = log.find('\n', start);
      result.message = trim(log.substr(start, end == std::string::npos ? std::string::npos : end - start));
      start = end == std::string::npos ? log.size() : end + 1;
    }
    return result;
  }
  if (errors > 1) result.message += " (+" + std::to_string(errors - 1) + " more errors)";
  return result;
}

}  // namespace shaderbed::gl
