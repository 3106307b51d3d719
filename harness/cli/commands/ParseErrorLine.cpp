#include "cli/commands/ParseErrorLine.h"

#include <algorithm>

#include <fmt/format.h>

#include "core/ClosestName.h"

namespace shaderbed {
namespace {

// The subcommand the command line reached (the root when none).
const CLI::App& command_of(const CLI::App& app) {
  const CLI::App* command = &app;
  for (const CLI::App* sub : app.get_subcommands()) command = sub;
  return *command;
}

std::string see_help(const CLI::App& app, const CLI::App& command) {
  return fmt::format("; see shaderbed {}--help", &command == &app ? "" : command.get_name() + " ");
}

// CLI11 names arguments it did not expect; say which command refused them and the nearest
// option or command name, the way the case-file checks do.
std::string unexpected_line(const CLI::App& app, const CLI::ParseError& error) {
  const CLI::App& command = command_of(app);
  std::vector<std::string> names;
  for (const CLI::Option* o : command.get_options())
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  if (&command == &app)
    for (const CLI::App* sub : app.get_subcommands({}))
      if (!sub->get_group().empty()) names.push_back(sub->get_name());   // hidden ones are not suggested
  const std::vector<std::string_view> known(names.begin(), names.end());
  std::vector<std::string> extras = command.remaining();
  if (extras.empty()) extras = app.remaining();
  if (extras.empty()) return error.what();
  // An unknown option leaves its value behind too ("--sise 3": "3 --sise"): name the option.
  const auto option = std::find_if(extras.begin(), extras.end(), [](const std::string& e) { return e.starts_with("-"); });
  const std::string& first = option != extras.end() ? *option : extras.front();
  const std::string name = first.substr(0, first.find('='));
  const std::string where = &command == &app ? "" : command.get_name() + ": ";
  const bool is_command = &command == &app && !first.starts_with("-");
  return fmt::format("{}unexpected {} '{}'{}{}", where, is_command ? "command" : "argument", first,
                     did_you_mean(name, known), see_help(app, command));
}

// "--twin: quad not in {double,float,half}" (CLI::IsMember): the nearest allowed value.
std::string refused_value_line(const CLI::App& app, const std::string& what) {
  const size_t in = what.rfind(" not in {");
  std::string suggestion;
  if (in != std::string::npos && what.ends_with("}")) {
    const size_t value_start = what.find(": ") == std::string::npos ? 0 : what.find(": ") + 2;
    const std::string value = what.substr(value_start, in - value_start);
    const std::string set = what.substr(in + 9, what.size() - in - 10);
    std::vector<std::string> allowed;
    for (size_t at = 0; at <= set.size();) {
      const size_t comma = std::min(set.find(',', at), set.size());
      allowed.push_back(set.substr(at, comma - at));
      at = comma + 1;
    }
    const std::vector<std::string_view> known(allowed.begin(), allowed.end());
    suggestion = did_you_mean(value, known);
  }
  return what + suggestion + see_help(app, command_of(app));
}

}  // namespace

std::string parse_error_line(const CLI::App& app, const CLI::ParseError& error) {
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) return unexpected_line(app, error);
  std::string what = error.what();
  while (!what.empty() && (what.back() == '\n' || what.back() == ' ')) what.pop_back();
  if (dynamic_cast<const CLI::ValidationError*>(&error)) return refused_value_line(app, what);
  std::replace(what.begin(), what.end(), '\n', ' ');
  return what + see_help(app, command_of(app));
}

}  // namespace shaderbed
