// `shaderbed devices`: the Vulkan devices of every installed driver, numbered as
// --vulkan-device takes them, the EGL devices as --gl-device takes them, and the GL
// renderer the chosen GL platform gives.
#include <fmt/format.h>

#include "backends/Backend.h"
#include "backends/gl/EglDevices.h"
#include "backends/gl/GlPlatform.h"
#include "backends/vulkan/VulkanDevice.h"
#include "cli/commands/Command.h"

namespace shaderbed {
namespace {

bool gl_platform_given = false;   // --gl-platform was on the command line

}  // namespace

void add_vulkan_device_option(CLI::App& app) {
  // Checked while parsing, so a device that does not exist is bad input before any work.
  const CLI::Validator exists(
      [](std::string& choice) -> std::string {
        auto device = vulkan::find_vulkan_device(choice);
        return device ? "" : device.error().message;
      },
      "INDEX|NAME");
  app.add_option_function<std::string>(
         "--vulkan-device", [](const std::string& choice) { choose_vulkan_device(choice); },
         "Run the Vulkan cells on this device: its index or a part of its name as 'shaderbed devices' lists them "
         "(any installed driver, e.g. a GPU's); default: lavapipe. The results record the device")
      ->check(exists);
}

void add_gl_platform_options(CLI::App& app) {
  std::vector<std::string> platforms(gl::kGlPlatforms.begin(), gl::kGlPlatforms.end());
  app.add_option_function<std::string>(
         "--gl-platform",
         [](const std::string& platform) {
           GlPlatformChoice choice = chosen_gl_platform();
           choice.platform = platform;
           choose_gl_platform(std::move(choice));
           gl_platform_given = true;
         },
         "How the GL cells reach OpenGL: osmesa (the default; Mesa up to 25.0) or egl (Mesa's surfaceless "
         "platform, or the EGL device --gl-device names). The results record it; see docs/gl-platforms.md")
      ->type_name("PLATFORM")
      ->check(CLI::IsMember(platforms));
  // Declared after --gl-platform: CLI11 runs the root's callbacks in declaration order, so
  // an explicit --gl-platform is known here wherever the two stand on the command line.
  const CLI::Validator exists(
      [](std::string& choice) -> std::string {
        if (gl_platform_given && chosen_gl_platform().platform != "egl")
          return "needs --gl-platform egl (OSMesa has no devices; --gl-device alone implies egl)";
        auto device = gl::find_egl_device(choice);
        return device ? "" : device.error().message;
      },
      "INDEX|NAME");
  app.add_option_function<std::string>(
         "--gl-device",
         [](const std::string& choice) { choose_gl_platform({.platform = "egl", .device = choice}); },
         "Run the GL cells on this EGL device: its index or a part of its name as 'shaderbed devices' lists them "
         "(e.g. a GPU's render node); implies --gl-platform egl. Default: Mesa's surfaceless platform on llvmpipe")
      ->check(exists);
}

Command add_devices_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "devices",
      "List the Vulkan devices of every installed driver (the index or a part of the name is what --vulkan-device "
      "takes; without it, lavapipe is used), the EGL devices (what --gl-device takes) and the OpenGL renderer of "
      "the chosen --gl-platform");
  return {cmd, [] {
            int status = 0;
            fmt::print("vulkan devices (--vulkan-device INDEX|NAME; default: lavapipe, the CPU device):\n");
            if (auto devices = vulkan::list_vulkan_devices(); !devices) {
              fmt::print("  none: {}\n", devices.error().to_string());
              status = kExitFail;
            } else if (devices->empty()) {
              fmt::print("  none\n");
              status = kExitFail;
            } else {
              for (const vulkan::VulkanDeviceInfo& d : *devices)
                fmt::print("  {}: {} [{}], Vulkan {}, {}\n", d.index, d.name, d.type, d.api_version, d.driver);
            }
            // Listing them is not using them: a machine without EGL still runs on OSMesa.
            fmt::print("egl devices (--gl-device INDEX|NAME; default: Mesa's surfaceless platform):\n");
            if (auto devices = gl::list_egl_devices(); !devices) {
              fmt::print("  none: {}\n", devices.error().to_string());
            } else if (devices->empty()) {
              fmt::print("  none\n");
            } else {
              for (const gl::EglDeviceInfo& d : *devices)
                fmt::print("  {}: {} [{}]\n", d.index, d.name, d.extensions);
            }
            fmt::print("opengl (--gl-platform {}):\n", chosen_gl_platform().platform);
            if (auto gl = make_gl_backend(); !gl) {
              fmt::print("  unavailable: {}\n", gl.error().to_string());
              status = kExitFail;
            } else {
              fmt::print("  {} on {}\n", (*gl)->driver_version(), (*gl)->platform());
            }
            return status;
          }};
}

}  // namespace shaderbed
