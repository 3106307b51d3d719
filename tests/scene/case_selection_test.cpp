// --case takes names from the cases folder and case files from anywhere; a case file's
// shader paths are relative to the folder holding cases/, else to the case's own folder.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "scene/CaseSelection.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

void write_case(const fs::path& file, const std::string& shader) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "model = \"lambert\"\n[variants.pixel]\nhlsl = { vertex = \"" << shader << "\", fragment = \""
                      << shader << "\" }\n[tolerance]\ninterior = { max_abs = 1e-5, reason = \"r\" }\n"
                      << "silhouette = { max_abs = 1e-4, reason = \"r\" }\n";
}

TEST(CaseSelection, ACaseFileNextToItsShaderResolvesPathsFromItsOwnFolder) {
  test::TempDir dir("case_selection");
  write_case(dir.path() / "port" / "phong.toml", "phong.hlsl");
  write_case(dir.path() / "suite" / "cases" / "lib.toml", "hlsl/lib.hlsl");

  auto mine = load_selected_cases((dir.path() / "suite" / "cases").string(), {(dir.path() / "port" / "phong.toml").string()});
  ASSERT_TRUE(mine) << mine.error().to_string();
  ASSERT_EQ(mine->size(), 1u);
  EXPECT_EQ((*mine)[0].name, "phong");
  EXPECT_EQ((*mine)[0].variants[0].shaders.at(Language::hlsl).vertex, (dir.path() / "port" / "phong.hlsl").string());

  auto both = load_selected_cases((dir.path() / "suite" / "cases").string(),
                                  {"lib", (dir.path() / "port" / "phong.toml").string()});
  ASSERT_TRUE(both) << both.error().to_string();
  ASSERT_EQ(both->size(), 2u);
  EXPECT_EQ((*both)[1].variants[0].shaders.at(Language::hlsl).vertex,
            (dir.path() / "suite" / "hlsl" / "lib.hlsl").string())
      << "a case in a cases/ folder keeps the library's convention";
}

TEST(CaseSelection, AMissingCaseFileIsAnErrorNamingIt) {
  auto r = load_selected_cases(".", {"/no/such/dir/port.toml"});
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().file, "/no/such/dir/port.toml");
  EXPECT_NE(r.error().to_string().find("no such case file"), std::string::npos);
}

}  // namespace
}  // namespace shaderbed
