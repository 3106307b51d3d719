// `shaderbed port` through the binary: a library case and real-world cases ported to each
// target render as the original on every backend and path, the case and the shaders land
// next to the case (or in --out-dir), a second port does not overwrite without --force,
// and bad input (a bad --to, a shader instead of a case, an ambiguous original) is exit 2.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::read_text;

namespace fs = std::filesystem;
using shaderbed::test::TempDir;

const fs::path kRoot = SHADERBED_SOURCE_DIR;

std::pair<int, std::string> port(const std::string& args) {
  return shaderbed::test::run_shell(std::string(SHADERBED_BINARY) + " port " + args + " --size 48 --shape sphere -q");
}

bool every_cell_passed(const std::string& out) {
  return out.find(" 0 failed, 0 known, 0 errors") != std::string::npos && out.find("FAIL") == std::string::npos;
}

TEST(PortCli, LibraryHlslCaseToGlsl450AndGlsl330RendersAsTheOriginal) {
  TempDir tmp("port_cli");
  const std::string phong = (kRoot / "shaders/cases/phong.toml").string();
  for (const char* target : {"glsl", "glsl-gl"}) {
    const fs::path out_dir = tmp.path() / target;
    const auto [status, out] = port(phong + " --from hlsl --to " + target + " --out-dir " + out_dir.string());
    ASSERT_EQ(status, 0) << out;
    EXPECT_TRUE(every_cell_passed(out)) << out;
    EXPECT_NE(out.find("SPIRV-Cross changed or could not keep"), std::string::npos) << out;
    EXPECT_NE(out.find("'InVertex.Position' -> 'Position'"), std::string::npos) << out;
    ASSERT_TRUE(fs::exists(out_dir / "phong.port.toml")) << out;
    const std::string ported_case = read_text(out_dir / "phong.port.toml");
    EXPECT_NE(ported_case.find("reference = { backend = \"vulkan\", language = \"hlsl\", path = \"spirv\" }"),
              std::string::npos) << ported_case;
    EXPECT_NE(ported_case.find("[bindings.glsl]"), std::string::npos) << ported_case;
    EXPECT_NE(ported_case.find("[attributes.glsl]\nPosition = \"position\""), std::string::npos) << ported_case;
    EXPECT_EQ(ported_case.find("[tolerance]"), std::string::npos) << ported_case;
    const std::string vert = read_text(out_dir / "setup_vs.port.vert");
    EXPECT_NE(vert.find(std::string("#version ") + (std::string(target) == "glsl" ? "450" : "330")), std::string::npos) << vert;
    EXPECT_NE(vert.find("Transform"), std::string::npos) << vert;
  }
}

TEST(PortCli, LibraryGlslCaseToHlslRendersAsTheOriginal) {
  TempDir tmp("port_cli");
  const auto [status, out] = port((kRoot / "shaders/cases/phong.toml").string() + " --from glsl --to hlsl --out-dir " +
                                  (tmp / "hlsl"));
  ASSERT_EQ(status, 0) << out;
  EXPECT_TRUE(every_cell_passed(out)) << out;
  const std::string ported_case = read_text(tmp.path() / "hlsl/phong.port.toml");
  // GLSL's M * v reads the same bytes as an HLSL matrix of the other register convention.
  EXPECT_NE(ported_case.find("modelViewProjection = { value = \"transform\", layout = \"row_vector\" }"),
            std::string::npos) << ported_case;
  EXPECT_TRUE(fs::exists(tmp.path() / "hlsl/setup.port.vs.hlsl"));
}

TEST(PortCli, RealWorldGlsl330ToHlslAndSm5TexturedToGlslRenderAsTheOriginals) {
  TempDir tmp("port_cli");
  {
    const auto [status, out] = port((kRoot / "tests/realworld/cases/glsl330_blinn_phong.toml").string() +
                                    " --to hlsl --out-dir " + (tmp / "glsl330"));
    ASSERT_EQ(status, 0) << out;
    EXPECT_TRUE(every_cell_passed(out)) << out;
    EXPECT_NE(out.find("gets semantic POSITION"), std::string::npos) << out;
    const std::string vs = read_text(tmp.path() / "glsl330/blinn_phong.port.vs.hlsl");
    EXPECT_NE(vs.find("aPos : POSITION"), std::string::npos) << vs;
    EXPECT_NE(vs.find("model"), std::string::npos) << vs;
  }
  {
    const auto [status, out] = port((kRoot / "tests/realworld/cases/hlsl5_textured_diffuse.toml").string() +
                                    " --to glsl-gl --out-dir " + (tmp / "hlsl5"));
    ASSERT_EQ(status, 0) << out;
    EXPECT_TRUE(every_cell_passed(out)) << out;
    EXPECT_NE(out.find("-> sampler2D 'shaderTexture'"), std::string::npos) << out;
    const std::string ported_case = read_text(tmp.path() / "hlsl5/hlsl5_textured_diffuse.port.toml");
    EXPECT_NE(ported_case.find("[textures.glsl]"), std::string::npos) << ported_case;
    EXPECT_NE(ported_case.find("filter = \"linear\""), std::string::npos) << ported_case;
  }
}

TEST(PortCli, PortGoesNextToTheCaseAndIsNotOverwrittenWithoutForce) {
  TempDir tmp("port_cli");
  fs::create_directories(tmp.path() / "cases");
  fs::copy(kRoot / "tests/realworld/glsl330", tmp.path() / "glsl330", fs::copy_options::recursive);
  fs::copy_file(kRoot / "tests/realworld/cases/glsl330_blinn_phong.toml", tmp.path() / "cases/blinn.toml");
  const std::string args = (tmp.path() / "cases/blinn.toml").string() + " --to glsl-gl";
  {
    const auto [status, out] = port(args);
    ASSERT_EQ(status, 0) << out;
    EXPECT_TRUE(every_cell_passed(out)) << out;   // GLSL 330 to GLSL 330: the port in its own variant
    const fs::path dir = tmp.path() / "cases/blinn.port.glsl-gl";
    ASSERT_TRUE(fs::exists(dir / "blinn.port.toml")) << out;
    EXPECT_TRUE(fs::exists(dir / "blinn_phong.port.vert"));
    const std::string ported_case = read_text(dir / "blinn.port.toml");
    EXPECT_NE(ported_case.find("[variants.pixel_port]"), std::string::npos) << ported_case;
    EXPECT_NE(ported_case.find("variant = \"pixel\""), std::string::npos) << ported_case;
    EXPECT_NE(ported_case.find("vertex = \"../../glsl330/blinn_phong.vert\""), std::string::npos) << ported_case;
  }
  {
    const auto [status, out] = port(args);
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find("--force"), std::string::npos) << out;
  }
  {
    const auto [status, out] = port(args + " --force");
    EXPECT_EQ(status, 0) << out;
  }
}

TEST(PortCli, BadInputIsExitTwoWithOneLine) {
  TempDir tmp("port_cli");
  const std::string phong = (kRoot / "shaders/cases/phong.toml").string();
  {
    const auto [status, out] = port(phong + " --from hlsl --to msl --out-dir " + (tmp / "x"));
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find("glsl-gl"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(tmp.path() / "x"));
  }
  {
    const auto [status, out] = port((kRoot / "shaders/hlsl/phong_ps.hlsl").string() + " --to glsl --out-dir " + (tmp / "x"));
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find("shaderbed init"), std::string::npos) << out;
  }
  {
    const auto [status, out] = port(phong + " --to glsl --out-dir " + (tmp / "x"));
    EXPECT_EQ(status, 2) << out;
    EXPECT_NE(out.find("--from"), std::string::npos) << out;
  }
}

}  // namespace
