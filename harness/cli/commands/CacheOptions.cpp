// Root-level cache options (core/CacheSettings.h, docs/caches.md). They work before or
// after the subcommand (`shaderbed --no-driver-cache run ...`, `shaderbed run
// --no-driver-cache ...`): every subcommand falls through to the root for options it does
// not know.
//
// Each option applies itself from its own callback. CLI11 runs the root's option
// callbacks in declaration order, before any subcommand's and before the root's
// parse-complete callback, so as long as this is called before other root options are
// added (--vulkan-device loads the Vulkan driver while validating, --version starts the
// backends), the settings are in place before any driver loads or any shader compiles.
#include <string>

#include "cli/commands/Command.h"
#include "core/CacheSettings.h"

namespace shaderbed {
namespace {

template <class F>
void update_settings(F change) {
  CacheSettings settings = cache_settings();   // the environment's defaults until changed
  change(settings);
  set_cache_settings(std::move(settings));
}

}  // namespace

void add_cache_options(CLI::App& app) {
  const char* group = "Caches (also after the subcommand)";
  app.add_option_function<std::string>(
         "--cache-dir", [](const std::string& dir) { update_settings([&](CacheSettings& s) { s.root = dir; }); },
         "Cache root: Mesa's shader cache in DIR/mesa, compiled SPIR-V and SPIRV-Cross GLSL in DIR/compile "
         "(default: $SHADERBED_CACHE_DIR, else $XDG_CACHE_HOME/shaderbed, else ~/.cache/shaderbed). "
         "Caches never change a result; see docs/caches.md")
      ->type_name("DIR")
      ->group(group);
  app.add_flag_callback(
         "--no-driver-cache", [] { update_settings([](CacheSettings& s) { s.driver = false; }); },
         "Turn Mesa's disk shader cache off (MESA_SHADER_CACHE_DISABLE=true): drivers build every pipeline")
      ->group(group);
  app.add_flag_callback(
         "--no-compile-cache", [] { update_settings([](CacheSettings& s) { s.compile = false; }); },
         "Neither read nor write the disk compile cache: glslang, SPIRV-Tools and SPIRV-Cross run again")
      ->group(group);
  app.fallthrough();   // inherited by subcommands added from now on
  for (CLI::App* sub : app.get_subcommands(std::function<bool(CLI::App*)>{})) sub->fallthrough();
}

}  // namespace shaderbed
