// `shaderbed help [COMMAND]`: the same text as `shaderbed [COMMAND] --help`, for those who
// type it the git way.
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "core/ClosestName.h"

namespace shaderbed {

Command add_help_command(CLI::App& app) {
  auto topic = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("help", "Show the help of a command (or the list of commands)");
  cmd->add_option("command", *topic, "The command whose help to show")->type_name("COMMAND");
  const CLI::App* root = &app;
  // Through the formatter, as --help does: App::help() would follow the parsed `help` itself.
  auto help_of = [root](const CLI::App* command, const std::string& usage_name) {
    return command->get_formatter()->make_help(command, usage_name, CLI::AppFormatMode::Normal);
  };
  return {cmd, [root, topic, help_of] {
            if (topic->empty()) {
              fmt::print("{}", help_of(root, root->get_name()));
              return 0;
            }
            std::vector<std::string> names;
            for (const CLI::App* sub : root->get_subcommands({}))
              if (!sub->get_group().empty()) names.push_back(sub->get_name());   // hidden ones stay hidden
            for (const std::string& name : names)
              if (name == *topic) {
                fmt::print("{}", help_of(root->get_subcommand(name), root->get_name() + " " + name));
                return 0;
              }
            const std::vector<std::string_view> known(names.begin(), names.end());
            fmt::print(stderr, "shaderbed: help: unknown command '{}'{}; see shaderbed help\n", *topic,
                       did_you_mean(*topic, known));
            return kExitBadInput;
          }};
}

}  // namespace shaderbed
