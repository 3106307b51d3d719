#include "cli/commands/ColourChoice.h"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace shaderbed {
namespace {

std::string& colour_choice() {
  static std::string value = "auto";
  return value;
}

bool set_and_not_empty(const char* name) {
  const char* v = std::getenv(name);
  return v && *v;
}

}  // namespace

void add_colour_option(CLI::App& app) {
  app.add_option("--color,--colour", colour_choice(),
                 "Colour the verdicts: auto (on a terminal, unless NO_COLOR is set or TERM=dumb), always or never")
      ->type_name("WHEN")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "always", "never"}));
}

bool colour_on(std::FILE* stream) {
  if (colour_choice() == "always") return true;
  if (colour_choice() == "never" || set_and_not_empty("NO_COLOR")) return false;
  const char* term = std::getenv("TERM");
  if (term && std::string(term) == "dumb") return false;
  return isatty(fileno(stream));
}

}  // namespace shaderbed
