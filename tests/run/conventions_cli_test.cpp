// The CLI's conventions through the binary: --version names shaderbed's version and the
// whole toolchain, `devices` lists the Vulkan devices as --vulkan-device numbers them, a
// chosen device is the one recorded in the results, and a device that does not exist is
// bad input (exit 2) with one line saying what there is.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
namespace {

using shaderbed::test::shaderbed_cli;

namespace fs = std::filesystem;

TEST(Conventions, VersionNamesShaderbedAndTheToolchain) {
  const auto [status, out] = shaderbed_cli("--version");
  ASSERT_EQ(status, 0) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(^shaderbed \d+\.\d+\.\d+)"))) << out;
  for (const char* tool : {"glslang", "SPIRV-Tools", "SPIRV-Cross", "Vulkan driver", "Vulkan device", "GL driver",
                           "GL platform", "LLVM"})
    EXPECT_NE(out.find(tool), std::string::npos) << tool << " missing from:\n" << out;
  // The drivers really started: Mesa's and LLVM's versions are read from them.
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(Mesa \d+\.\d+)"))) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(LLVM +\d+\.\d+)"))) << out;
  EXPECT_NE(out.find("[cpu]"), std::string::npos) << "lavapipe, a CPU device, is the default:\n" << out;
}

TEST(Conventions, DevicesListsLavapipeWithAnIndex) {
  const auto [status, out] = shaderbed_cli("devices");
  ASSERT_EQ(status, 0) << out;
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(\n  0: llvmpipe[^\n]*\[cpu\])"))) << out;
  EXPECT_NE(out.find("OpenGL"), std::string::npos) << out;
}

TEST(Conventions, ChosenVulkanDeviceIsRecordedInTheResults) {
  const fs::path json = fs::temp_directory_path() / ("conventions_" + std::to_string(::getpid()) + ".json");
  for (const char* choice : {"0", "LLVMPIPE"}) {
    const auto [status, out] = shaderbed_cli(std::string("run --vulkan-device ") + choice +
                                             " --case lambert --variant pixel --lang glsl --backend vulkan "
                                             "--shape sphere --size 32 --repeat 0 --quiet --json " + json.string());
    ASSERT_EQ(status, 0) << out;
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_TRUE(j["tools"]["vulkan_device"].get<std::string>().starts_with("llvmpipe")) << j["tools"].dump();
    EXPECT_EQ(j["results"][0]["status"], "pass");
  }
  fs::remove(json);
}

TEST(Conventions, UnknownVulkanDeviceIsBadInput) {
  const auto [status, out] = shaderbed_cli("run --vulkan-device no-such-gpu --case lambert --size 32 --repeat 0");
  EXPECT_EQ(status, 2) << out;
  EXPECT_NE(out.find("no-such-gpu"), std::string::npos) << out;
  EXPECT_NE(out.find("llvmpipe"), std::string::npos) << "the error lists the devices there are:\n" << out;
}

}  // namespace
