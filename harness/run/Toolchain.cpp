#include "run/Toolchain.h"

#include <regex>

#include <fmt/format.h>

#include "compile/ToolVersions.h"

namespace shaderbed {
namespace {

std::string llvm_version(const std::string& driver) {
  static const std::regex llvm(R"(LLVM ([0-9.]+))");
  std::smatch m;
  return std::regex_search(driver, m, llvm) ? m[1].str() : "";
}

}  // namespace

ToolVersions toolchain(const std::vector<BackendSlot>& backends) {
  const CompilerVersions versions = compiler_versions();
  ToolVersions tools{versions.glslang, versions.spirv_tools, versions.spirv_cross, "", "", "", "", ""};
  for (const BackendSlot& b : backends) {
    const std::string v = b.backend ? (*b.backend)->driver_version() : "unavailable: " + b.backend.error().message;
    (b.name == "vulkan" ? tools.vulkan_driver : tools.gl_driver) = v;
    if (b.name == "vulkan" && b.backend) tools.vulkan_device = (*b.backend)->device_name();
    if (b.name == "gl" && b.backend) tools.gl_platform = (*b.backend)->platform();
    if (tools.llvm.empty()) tools.llvm = llvm_version(v);
  }
  return tools;
}

std::string version_text(const ToolVersions& t) {
  const auto or_none = [](const std::string& s) { return s.empty() ? std::string("-") : s; };
  return fmt::format(
      "shaderbed {}\n"
      "  glslang        {}\n"
      "  SPIRV-Tools    {}\n"
      "  SPIRV-Cross    {}\n"
      "  Vulkan driver  {}\n"
      "  Vulkan device  {}\n"
      "  GL driver      {}\n"
      "  GL platform    {}\n"
      "  LLVM           {}\n",
      SHADERBED_VERSION, or_none(t.glslang), or_none(t.spirv_tools), or_none(t.spirv_cross), or_none(t.vulkan_driver),
      or_none(t.vulkan_device), or_none(t.gl_driver), or_none(t.gl_platform), or_none(t.llvm));
}

}  // namespace shaderbed
