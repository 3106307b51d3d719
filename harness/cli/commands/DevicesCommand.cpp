// `shaderbed devices`: the Vulkan devices of every installed driver, numbered as
// --vulkan-device takes them, and the GL renderer OSMesa gives.
#include <fmt/format.h>

#include "backends/Backend.h"
#include "backends/vulkan/VulkanDevice.h"
#include "cli/commands/Command.h"

namespace shaderbed {

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

Command add_devices_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "devices",
      "List the Vulkan devices of every installed driver (the index or a part of the name is what --vulkan-device "
      "takes; without it, lavapipe is used) and the OpenGL renderer");
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
            fmt::print("opengl (OSMesa):\n");
            if (auto gl = make_gl_backend(); !gl) {
              fmt::print("  unavailable: {}\n", gl.error().to_string());
              status = kExitFail;
            } else {
              fmt::print("  {}\n", (*gl)->driver_version());
            }
            return status;
          }};
}

}  // namespace shaderbed
