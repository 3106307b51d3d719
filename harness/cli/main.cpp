// shaderbed: compile a lighting shader, render it on real drivers, diff it against a
// double-precision CPU reference.
#include <algorithm>

#include <fmt/format.h>

#include "cli/commands/Command.h"
#include "core/ClosestName.h"

namespace {

// CLI11 names arguments it did not expect; say which command refused them and the nearest
// option or command name, the way the case-file checks do.
bool explain_unexpected(const CLI::App& app) {
  const CLI::App* command = &app;
  for (const CLI::App* sub : app.get_subcommands()) command = sub;
  std::vector<std::string> names;
  for (const CLI::Option* o : command->get_options())
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  if (command == &app)
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  const std::vector<std::string_view> known(names.begin(), names.end());
  std::vector<std::string> extras = command->remaining();
  if (extras.empty()) extras = app.remaining();
  if (extras.empty()) return false;
  // An unknown option leaves its value behind too ("--sise 3": "3 --sise"): name the option.
  const auto option = std::find_if(extras.begin(), extras.end(), [](const std::string& e) { return e.starts_with("-"); });
  const std::string& first = option != extras.end() ? *option : extras.front();
  const std::string name = first.substr(0, first.find('='));
  const std::string where = command == &app ? "" : command->get_name() + ": ";
  fmt::print(stderr, "shaderbed: {}unexpected argument '{}'{}; see shaderbed {}--help\n", where, first,
             shaderbed::did_you_mean(name, known), command == &app ? "" : command->get_name() + " ");
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"shaderbed: a cross-API shader test bench. Compiles HLSL, Cg and GLSL lighting shaders to SPIR-V, "
               "renders them on Vulkan (lavapipe) and OpenGL (OSMesa) and compares every image with a "
               "double-precision CPU reference."};
  app.require_subcommand(0, 1);   // none only with --version
  const shaderbed::Command commands[] = {shaderbed::add_run_command(app), shaderbed::add_eval_command(app),
                                          shaderbed::add_merge_command(app),
                                          shaderbed::add_stats_command(app), shaderbed::add_sweep_command(app),
                                          shaderbed::add_hard_command(app),
                                          shaderbed::add_init_command(app),
                                          shaderbed::add_port_command(app), shaderbed::add_explain_command(app),
                                          shaderbed::add_cell_worker_command(app),
                                          shaderbed::add_compile_stages_command(app),
                                          shaderbed::add_bench_command(app), shaderbed::add_devices_command(app),
                                          shaderbed::add_view_command(app), shaderbed::add_view_compile_command(app),
                                          shaderbed::add_sh_command(app)};
  shaderbed::add_cache_options(app);
  shaderbed::add_vulkan_device_option(app);
  shaderbed::add_version_flag(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    if (!explain_unexpected(app)) app.exit(e);
    return shaderbed::kExitBadInput;
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return shaderbed::kExitBadInput;
  }
  for (const shaderbed::Command& c : commands)
    if (c.app->parsed()) return c.run();
  fmt::print(stderr, "shaderbed: a command is required (shaderbed --help lists them)\n");
  return shaderbed::kExitBadInput;
}
