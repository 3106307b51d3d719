// A compile-cache entry whose payload was edited is recompiled, never served: entries
// are checked by SHA-256 of their content, so a forger who recomputes the FNV-1a checksum
// the old layout ended with (issue 30, item 10) gets a miss.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "compile/CompileCache.h"
#include "compile/Compiler.h"
#include "core/Fnv1a.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

std::string forgery_read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(CompileCacheForgery, AnEditedPayloadWithItsFnvRecomputedIsRecompiledNotUsed) {
  test::TempDir dir("forgery");
  CompileToolchain toolchain = current_compile_toolchain();
  toolchain.stage_code = "compile_cache_forgery_test";
  CompileCache cache(dir.path(), toolchain);
  const ShaderSource src{.stage = Stage::fragment,
                         .path = "forged.frag",
                         .text = "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(0.25); }\n",
                         .entry_point = "main"};
  auto compiled = cache.stage(Language::glsl, src, Target::vulkan);
  ASSERT_TRUE(compiled) << compiled.error().to_string();
  ASSERT_TRUE(cache.find_stage(Language::glsl, src, Target::vulkan));
  fs::path entry;
  for (const auto& e : fs::directory_iterator(dir.path())) entry = e.path();
  ASSERT_FALSE(entry.empty());

  // The forger edits the SPIR-V inside the entry (the constant 0.25 becomes 0.5, so the
  // module still decodes and would draw another colour) and recomputes FNV-1a over the
  // body into the last 8 bytes, as the old entries were checked.
  std::string bytes = forgery_read(entry);
  const float quarter = 0.25f, half = 0.5f;
  const std::string from(reinterpret_cast<const char*>(&quarter), sizeof quarter);
  const std::string to(reinterpret_cast<const char*>(&half), sizeof half);
  const size_t at = bytes.rfind(from);
  ASSERT_NE(at, std::string::npos) << "the constant is in the stored SPIR-V";
  bytes.replace(at, to.size(), to);
  std::string body = bytes.substr(0, bytes.size() - sizeof(uint64_t));
  const uint64_t fnv = fnv1a64(body);
  body.append(reinterpret_cast<const char*>(&fnv), sizeof fnv);
  std::ofstream(entry, std::ios::binary | std::ios::trunc) << body;

  EXPECT_FALSE(cache.find_stage(Language::glsl, src, Target::vulkan)) << "a forged entry is a miss";
  const size_t compiles = cache.counts().compiles;
  auto again = cache.stage(Language::glsl, src, Target::vulkan);
  ASSERT_TRUE(again);
  EXPECT_EQ(cache.counts().compiles, compiles + 1) << "recompiled";
  EXPECT_TRUE(*again == *compiled) << "the module is the compiler's, not the forger's";
  EXPECT_EQ(entry.filename().string().size(), 64u + std::string(".stage").size()) << "named by SHA-256 of the key";
}

}  // namespace
}  // namespace shaderbed
