// The disk compile cache (harness/compile/CompileCache.h) on real glslang: a hit is the
// module a compile gives, byte for byte; anything that changes the output misses (source,
// entry point, target, an #included file, a toolchain version, the compile stage's own
// code); corrupt or colliding entries miss; failures are not stored; and a process served
// from the cache never starts glslang.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "SourceTree.h"
#include "TempDir.h"
#include "compile/CompileCache.h"
#include "compile/Compiler.h"
#include "compile/GlslangFrontEnd.h"
#include "compile/ModuleCodec.h"
#include "compile/StageCache.h"
#include "compile/ToolVersions.h"
#include "core/CacheSettings.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

using test::kShaders;

using test::TempDir;

// Every file in a folder (entries and anything a writer left behind).
std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::exists(dir)) return files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  return files;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

// The real toolchain with a test-only fingerprint, so these entries never meet others.
CompileToolchain test_toolchain() {
  CompileToolchain t = current_compile_toolchain();
  t.stage_code = "compile_cache_test";
  return t;
}

ShaderSource cache_source(Stage stage, std::string text, std::string path, std::string entry = "main") {
  return ShaderSource{.stage = stage, .path = std::move(path), .text = std::move(text), .entry_point = std::move(entry)};
}

const char* kGlslFragment =
    "#version 450\n"
    "layout(location = 0) in vec3 n;\n"
    "layout(location = 0) out vec4 c;\n"
    "layout(binding = 0) uniform Material { vec4 tint; float power; } m;\n"
    "void main() { c = m.tint * pow(max(n.y, 0.0), m.power); }\n";

const char* kHlslPixel =
    "float4 tint;\n"
    "sampler2D lut;\n"
    "float4 main(float2 uv : TEXCOORD0) : COLOR { return tint * tex2D(lut, uv); }\n"
    "float4 other(float2 uv : TEXCOORD0) : COLOR { return tint.zyxw; }\n";

// ---- hits are exactly what a compile gives ------------------------------------------

TEST(CompileCache, MissThenHitGivesTheCompiledModuleForEveryLibraryShader) {
  TempDir dir;
  CompileCache cache(dir.path(), test_toolchain());
  size_t shaders = 0;
  for (const auto& [folder, language] : {std::pair{"hlsl", Language::hlsl}, std::pair{"glsl", Language::glsl},
                                         std::pair{"cg", Language::cg}})
    for (const auto& entry : fs::directory_iterator(kShaders / folder)) {
      const std::string name = entry.path().filename().string();
      const std::string ext = entry.path().extension().string();
      if (ext == ".cgh") continue;
      const bool fragment = ext == ".frag" || name.find("_ps") != std::string::npos || name.ends_with("_fp.cg");
      auto src = load_shader_source(fragment ? Stage::fragment : Stage::vertex, entry.path().string());
      ASSERT_TRUE(src) << src.error().to_string();
      for (Target target : {Target::vulkan, Target::opengl}) {
        const CompileCacheCounts before = cache.counts();
        auto cold = cache.stage(language, *src, target);
        ASSERT_TRUE(cold) << name << ": " << cold.error().to_string();
        auto warm = cache.stage(language, *src, target);
        ASSERT_TRUE(warm) << name << ": " << warm.error().to_string();
        const CompileCacheCounts d = cache.counts() - before;
        EXPECT_EQ(d.compiles, 1u) << name;
        EXPECT_EQ(d.disk_hits, 1u) << name;
        // Identical SPIR-V words and reflection (every field: ShaderModule's == is defaulted),
        // and identical to an uncached compile.
        EXPECT_TRUE(*warm == *cold) << name;
        EXPECT_EQ(warm->spirv, cold->spirv) << name;
        EXPECT_TRUE(warm->reflection == cold->reflection) << name;
        auto direct = compile_stage(language, *src, target);
        ASSERT_TRUE(direct);
        EXPECT_TRUE(*warm == *direct) << name;
        ++shaders;
      }
    }
  EXPECT_GE(shaders, 2u * 60u);
}

TEST(CompileCache, CrossGlslMissThenHitIsTheSameText) {
  TempDir dir;
  CompileCache cache(dir.path(), test_toolchain());
  auto module = compile_stage(Language::hlsl, cache_source(Stage::fragment, kHlslPixel, "p.hlsl"), Target::opengl);
  ASSERT_TRUE(module) << module.error().to_string();
  auto cold = cache.cross_glsl(module->spirv, Stage::fragment);
  ASSERT_TRUE(cold) << cold.error().to_string();
  auto warm = cache.cross_glsl(module->spirv, Stage::fragment);
  ASSERT_TRUE(warm);
  EXPECT_EQ(*warm, *cold);
  EXPECT_EQ(cache.counts().compiles, 1u);
  EXPECT_EQ(cache.counts().disk_hits, 1u);
  // Other SPIR-V, or the same words for another stage, is another entry.
  std::vector<uint32_t> other = module->spirv;
  other.push_back(0);   // not valid SPIR-V any more: SPIRV-Cross may fail, but it must run
  EXPECT_FALSE(cache.find_cross_glsl(other, Stage::fragment));
  EXPECT_FALSE(cache.find_cross_glsl(module->spirv, Stage::vertex));
}

// ---- everything that affects the bytes is in the key ---------------------------------

TEST(CompileCache, ChangedSourceEntryTargetPathLanguageOrStageMisses) {
  TempDir dir;
  CompileCache cache(dir.path(), test_toolchain());
  const ShaderSource base = cache_source(Stage::fragment, kHlslPixel, "p.hlsl");
  ASSERT_TRUE(cache.stage(Language::hlsl, base, Target::vulkan));
  ASSERT_TRUE(cache.find_stage(Language::hlsl, base, Target::vulkan));

  ShaderSource text = base;
  text.text += "\n";   // one byte more
  EXPECT_FALSE(cache.find_stage(Language::hlsl, text, Target::vulkan));
  ShaderSource entry = base;
  entry.entry_point = "other";
  EXPECT_FALSE(cache.find_stage(Language::hlsl, entry, Target::vulkan));
  EXPECT_FALSE(cache.find_stage(Language::hlsl, base, Target::opengl));
  ShaderSource path = base;
  path.path = "elsewhere/p.hlsl";
  EXPECT_FALSE(cache.find_stage(Language::hlsl, path, Target::vulkan));
  EXPECT_FALSE(cache.find_stage(Language::cg, base, Target::vulkan));
  ShaderSource stage = base;
  stage.stage = Stage::vertex;
  EXPECT_FALSE(cache.find_stage(Language::hlsl, stage, Target::vulkan));

  // The other entry point compiles to other SPIR-V, and each is then served as its own.
  auto main_module = cache.stage(Language::hlsl, base, Target::vulkan);
  auto other_module = cache.stage(Language::hlsl, entry, Target::vulkan);
  ASSERT_TRUE(main_module && other_module);
  EXPECT_NE(main_module->spirv, other_module->spirv);
  EXPECT_EQ(cache.find_stage(Language::hlsl, entry, Target::vulkan)->spirv, other_module->spirv);
  EXPECT_EQ(cache.find_stage(Language::hlsl, base, Target::vulkan)->spirv, main_module->spirv);
}

TEST(CompileCache, AnotherToolchainVersionOrCompileStageFingerprintMisses) {
  TempDir dir;
  const ShaderSource src = cache_source(Stage::fragment, kGlslFragment, "f.frag");
  {
    CompileCache cache(dir.path(), test_toolchain());
    ASSERT_TRUE(cache.stage(Language::glsl, src, Target::vulkan));
    ASSERT_TRUE(cache.find_stage(Language::glsl, src, Target::vulkan));
  }
  for (std::string CompileToolchain::*field : {&CompileToolchain::glslang, &CompileToolchain::spirv_tools,
                                               &CompileToolchain::spirv_cross, &CompileToolchain::stage_code}) {
    CompileToolchain other = test_toolchain();
    other.*field += "+1";
    CompileCache cache(dir.path(), other);
    EXPECT_FALSE(cache.find_stage(Language::glsl, src, Target::vulkan)) << other.*field;
  }
  // And the real build's fingerprint is a SHA-256 generated at build time.
  EXPECT_EQ(compile_stage_fingerprint().size(), 64u);
  EXPECT_EQ(current_compile_toolchain().stage_code, compile_stage_fingerprint());
}

TEST(CompileCache, ChangedIncludedFileMissesAndTheNewTextIsCompiled) {
  TempDir dir;
  TempDir cache_dir;
  CompileCache cache(cache_dir.path(), test_toolchain());
  const std::string header = dir.write("inc/scale.cgh", "float scale() { return 2.0; }\n");
  dir.write("inc/deeper.cgh", "#pragma once\nfloat offset() { return 0.25; }\n");
  const std::string main = dir.write("prog_fp.cg",
                                     "#include \"inc/scale.cgh\"\n"
                                     "#include \"inc/deeper.cgh\"\n"
                                     "float4 main(float3 n : TEXCOORD0) : COLOR { return float4(n * scale() + offset(), 1); }\n");
  auto src = load_shader_source(Stage::fragment, main);
  ASSERT_TRUE(src);
  auto first = cache.stage(Language::cg, *src, Target::vulkan);
  ASSERT_TRUE(first) << first.error().to_string();
  auto again = cache.stage(Language::cg, *src, Target::vulkan);
  ASSERT_TRUE(again);
  EXPECT_EQ(cache.counts().compiles, 1u) << "unchanged includes: a hit";
  EXPECT_EQ(again->spirv, first->spirv);

  // The same length, one byte different, in the first include.
  dir.write("inc/scale.cgh", "float scale() { return 3.0; }\n");
  EXPECT_FALSE(cache.find_stage(Language::cg, *src, Target::vulkan)) << "a changed #include must miss";
  auto changed = cache.stage(Language::cg, *src, Target::vulkan);
  ASSERT_TRUE(changed);
  EXPECT_NE(changed->spirv, first->spirv) << "the new include text was compiled";
  EXPECT_EQ(cache.find_stage(Language::cg, *src, Target::vulkan)->spirv, changed->spirv);

  // A nested include counts too, and so does one that went away.
  dir.write("inc/deeper.cgh", "#pragma once\nfloat offset() { return 0.5; }\n");
  EXPECT_FALSE(cache.find_stage(Language::cg, *src, Target::vulkan));
  ASSERT_TRUE(cache.stage(Language::cg, *src, Target::vulkan));
  fs::remove(header);
  EXPECT_FALSE(cache.find_stage(Language::cg, *src, Target::vulkan));
  EXPECT_FALSE(cache.stage(Language::cg, *src, Target::vulkan)) << "the missing include is an error again";
}

TEST(CompileCache, LibraryCgIncludesAreRecordedAndChecked) {
  // lighting.cgh is included by the library's Cg shaders: copy one with it and edit the copy.
  TempDir dir;
  TempDir cache_dir;
  CompileCache cache(cache_dir.path(), test_toolchain());
  fs::path program;
  for (const auto& e : fs::directory_iterator(kShaders / "cg")) {
    const std::string text = read_bytes(e.path());
    if (e.path().extension() == ".cg" && text.find("#include \"lighting.cgh\"") != std::string::npos) {
      program = e.path();
      break;
    }
  }
  ASSERT_FALSE(program.empty()) << "no library Cg shader includes lighting.cgh";
  const std::string main = dir.write(program.filename().string(), read_bytes(program));
  const std::string header = dir.write("lighting.cgh", read_bytes(kShaders / "cg" / "lighting.cgh"));
  const Stage stage = program.stem().string().ends_with("_fp") ? Stage::fragment : Stage::vertex;
  auto src = load_shader_source(stage, main);
  ASSERT_TRUE(src);
  ASSERT_TRUE(cache.stage(Language::cg, *src, Target::vulkan));
  EXPECT_TRUE(cache.find_stage(Language::cg, *src, Target::vulkan));
  dir.write("lighting.cgh", read_bytes(header) + "// edited\n");
  EXPECT_FALSE(cache.find_stage(Language::cg, *src, Target::vulkan));
}

// ---- only whole, matching, successful entries are served -----------------------------

TEST(CompileCache, CorruptTruncatedOrForeignEntriesAreMissesNotErrors) {
  TempDir dir;
  CompileCache cache(dir.path(), test_toolchain());
  const ShaderSource src = cache_source(Stage::fragment, kGlslFragment, "f.frag");
  auto compiled = cache.stage(Language::glsl, src, Target::vulkan);
  ASSERT_TRUE(compiled);
  const std::vector<fs::path> entries = files_in(dir.path());
  ASSERT_EQ(entries.size(), 1u);
  const fs::path entry = entries[0];
  EXPECT_EQ(entry.filename().string(), CompileCache::entry_name(cache.stage_key(Language::glsl, src, Target::vulkan), "stage"));
  const std::string good = read_bytes(entry);

  const auto misses_with = [&](const std::string& bytes, const char* what) {
    write_bytes(entry, bytes);
    EXPECT_FALSE(cache.find_stage(Language::glsl, src, Target::vulkan)) << what;
  };
  misses_with("", "empty");
  misses_with(good.substr(0, good.size() / 2), "truncated");
  misses_with(good.substr(0, good.size() - 1), "one byte short");
  misses_with(good + "x", "one byte more");
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x40;
  misses_with(flipped, "one bit flipped in the middle (SPIR-V)");
  misses_with(std::string(good.size(), '\x7f'), "garbage");
  for (size_t n = 0; n < good.size(); n += 97) misses_with(good.substr(0, n), "a prefix");

  // Recompiled and stored again: a hit, equal to the first compile.
  auto again = cache.stage(Language::glsl, src, Target::vulkan);
  ASSERT_TRUE(again);
  EXPECT_TRUE(*again == *compiled);
  EXPECT_TRUE(cache.find_stage(Language::glsl, src, Target::vulkan));

  // A colliding name: another key's (valid) entry under this key's file name.
  const ShaderSource other = cache_source(Stage::fragment, std::string(kGlslFragment) + "// other\n", "f.frag");
  ASSERT_TRUE(cache.stage(Language::glsl, other, Target::vulkan));
  const fs::path other_entry =
      dir.path() / CompileCache::entry_name(cache.stage_key(Language::glsl, other, Target::vulkan), "stage");
  write_bytes(entry, read_bytes(other_entry));
  EXPECT_FALSE(cache.find_stage(Language::glsl, src, Target::vulkan)) << "the stored key is compared, not the hash";
}

TEST(CompileCache, FailedCompilesAreNotStored) {
  TempDir dir;
  CompileCache cache(dir.path(), test_toolchain());
  const ShaderSource broken = cache_source(Stage::fragment, "#version 450\nvoid main() { undefined_name; }\n", "b.frag");
  EXPECT_FALSE(cache.stage(Language::glsl, broken, Target::vulkan));
  EXPECT_FALSE(cache.stage(Language::glsl, broken, Target::vulkan));
  EXPECT_EQ(cache.counts().compiles, 2u);
  EXPECT_TRUE(files_in(dir.path()).empty());
}

TEST(CompileCache, ConcurrentWritersOfOneEntryLeaveOneWholeEntry) {
  TempDir dir;
  const ShaderSource src = cache_source(Stage::fragment, kHlslPixel, "p.hlsl");
  auto expected = compile_stage(Language::hlsl, src, Target::vulkan);
  ASSERT_TRUE(expected);
  std::vector<std::thread> threads;
  std::atomic<int> wrong{0};
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      CompileCache cache(dir.path(), test_toolchain());   // one per worker, one folder
      for (int i = 0; i < 3; ++i) {
        auto m = cache.stage(Language::hlsl, src, Target::vulkan);
        if (!m || !(*m == *expected)) ++wrong;
      }
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(wrong, 0);
  const std::vector<fs::path> left = files_in(dir.path());
  ASSERT_EQ(left.size(), 1u) << "no temporary files left behind";
  CompileCache reader(dir.path(), test_toolchain());
  auto hit = reader.find_stage(Language::hlsl, src, Target::vulkan);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(*hit == *expected);
}

TEST(CompileCache, AFolderThatCannotBeWrittenMeansNoCachingNotAnError) {
  TempDir dir;
  const std::string not_a_folder = dir.write("file", "x");
  CompileCache cache(fs::path(not_a_folder) / "compile", test_toolchain());
  const ShaderSource src = cache_source(Stage::fragment, kGlslFragment, "f.frag");
  EXPECT_TRUE(cache.stage(Language::glsl, src, Target::vulkan));
  EXPECT_TRUE(cache.stage(Language::glsl, src, Target::vulkan));
  EXPECT_EQ(cache.counts().compiles, 2u);
}

// ---- the codec ---------------------------------------------------------------------

TEST(ModuleCodec, EveryFieldRoundTripsAndEveryPrefixIsRejected) {
  ShaderModule m;
  m.stage = Stage::fragment;
  m.source_file = "dir/file.hlsl";
  m.entry_point = "ps_main";
  m.spirv = {0x07230203, 1, 2, 3, 0xffffffff};
  UniformMember member{.name = "M",
                       .offset = 16,
                       .size = 64,
                       .is_float = false,
                       .vecsize = 4,
                       .columns = 4,
                       .matrix_stride = 16,
                       .column_registers = false,
                       .array_size = 3,
                       .array_stride = 80};
  m.reflection.uniform_blocks.push_back({.name = "$Global", .set = 1, .binding = 8, .size = 256, .members = {member, {}}});
  m.reflection.inputs.push_back({.location = 2, .name = "in.var.NORMAL", .semantic = "NORMAL", .components = 3});
  m.reflection.samplers.push_back({.name = "lut", .set = 1, .binding = 9, .dimensions = 3});
  const std::string bytes = encode_module(m);
  auto back = decode_module(bytes);
  ASSERT_TRUE(back);
  EXPECT_TRUE(*back == m);
  for (size_t n = 0; n < bytes.size(); ++n) EXPECT_FALSE(decode_module(std::string_view(bytes).substr(0, n))) << n;
  EXPECT_FALSE(decode_module(bytes + '\0'));
}

// ---- settings ------------------------------------------------------------------------

class ScopedEnv {
 public:
  explicit ScopedEnv(std::vector<std::string> names) : names_(std::move(names)) {
    for (const std::string& n : names_) {
      const char* v = std::getenv(n.c_str());
      saved_.push_back(v ? std::optional<std::string>(v) : std::nullopt);
    }
  }
  ~ScopedEnv() {
    for (size_t i = 0; i < names_.size(); ++i)
      if (saved_[i]) ::setenv(names_[i].c_str(), saved_[i]->c_str(), 1);
      else ::unsetenv(names_[i].c_str());
  }

 private:
  std::vector<std::string> names_;
  std::vector<std::optional<std::string>> saved_;
};

TEST(CacheSettings, RootFromShaderbedCacheDirThenXdgThenHome) {
  ScopedEnv env({"SHADERBED_CACHE_DIR", "XDG_CACHE_HOME", "HOME"});
  ::setenv("SHADERBED_CACHE_DIR", "/tmp/sb-root", 1);
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  ::setenv("HOME", "/tmp/home", 1);
  CacheSettings s = cache_settings_from_environment();
  EXPECT_EQ(s.root, "/tmp/sb-root");
  EXPECT_EQ(s.driver_dir(), "/tmp/sb-root/mesa");
  EXPECT_EQ(s.compile_dir(), "/tmp/sb-root/compile");
  EXPECT_TRUE(s.driver && s.compile);
  ::setenv("SHADERBED_CACHE_DIR", "", 1);   // empty counts as unset
  EXPECT_EQ(cache_settings_from_environment().root, "/tmp/xdg/shaderbed");
  ::unsetenv("SHADERBED_CACHE_DIR");
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(cache_settings_from_environment().root, "/tmp/home/.cache/shaderbed");
  ::unsetenv("HOME");
  s = cache_settings_from_environment();
  EXPECT_EQ(s.root, "");
  EXPECT_FALSE(s.driver_enabled());
  EXPECT_FALSE(s.compile_enabled());
  // A relative root is made absolute (Mesa would resolve it against its own cwd).
  ::setenv("SHADERBED_CACHE_DIR", "relative/cache", 1);
  EXPECT_EQ(fs::path(cache_settings_from_environment().root), (fs::current_path() / "relative/cache").lexically_normal());
}

// ---- the layers compile_program() goes through, and a warm process -------------------

class ScopedSettings {
 public:
  explicit ScopedSettings(CacheSettings s) : saved_(cache_settings()) { set_cache_settings(std::move(s)); }
  ~ScopedSettings() { set_cache_settings(saved_); }

 private:
  CacheSettings saved_;
};

// A program no other test compiles, so this process's memory layer has not seen it.
ProgramSource unique_program(const std::string& tag) {
  const std::string vs = "float4x4 mvp;\nfloat4 main(float4 p : POSITION, float3 n : NORMAL, out float3 o : TEXCOORD0) "
                         ": POSITION { o = n; return mul(mvp, p); }\n// " + tag + "\n";
  const std::string ps = std::string(kHlslPixel) + "// " + tag + "\n";
  return ProgramSource{Language::hlsl, cache_source(Stage::vertex, vs, "unique_vs.hlsl"), cache_source(Stage::fragment, ps, "unique_ps.hlsl")};
}

TEST(StageCache, DiskLayerUnderTheMemoryLayerAndOffSwitch) {
  TempDir dir;
  const std::string tag = "layers " + dir.path().string();
  {
    ScopedSettings settings(CacheSettings{dir.path().string(), false, true});
    const CompileCacheCounts before = compile_cache_counts();
    auto cold = compile_program(unique_program(tag));
    ASSERT_TRUE(cold) << cold.error().to_string();
    CompileCacheCounts d = compile_cache_counts() - before;
    EXPECT_EQ(d.compiles, 6u) << "4 stages + 2 cross compiles";
    EXPECT_EQ(d.hits(), 0u);
    EXPECT_EQ(files_in(fs::path(dir.path()) / "compile").size(), 6u);
    auto again = compile_program(unique_program(tag));
    ASSERT_TRUE(again);
    d = compile_cache_counts() - before;
    EXPECT_EQ(d.compiles, 6u);
    EXPECT_EQ(d.memory_hits, 4u) << "stages from memory";
    EXPECT_EQ(d.disk_hits, 2u) << "cross GLSL from disk";
    EXPECT_EQ(again->fragment_cross_glsl, cold->fragment_cross_glsl);
  }
  {
    // Off: nothing read or written, even with a folder set.
    TempDir off;
    ScopedSettings settings(CacheSettings{off.path().string(), true, false});
    const CompileCacheCounts before = compile_cache_counts();
    auto program = compile_program(unique_program("off " + off.path().string()));
    ASSERT_TRUE(program);
    EXPECT_EQ((compile_cache_counts() - before).compiles, 6u);
    EXPECT_EQ((compile_cache_counts() - before).disk_hits + (compile_cache_counts() - before).disk_misses, 0u);
    EXPECT_FALSE(fs::exists(off.path() / "compile"));
  }
}

// A warm process must not start glslang. gtest runs every test in one process, and other
// tests start glslang, so this one runs its warm half in a fresh process: the
// "threadsafe" death-test style re-executes this binary with only this test selected.
// The parent fills the cache and names it in an environment variable; the re-executed
// child finds the variable set, skips the filling and runs only the warm half.
constexpr const char* kWarmCacheEnv = "SHADERBED_TEST_WARM_COMPILE_CACHE";

[[noreturn]] void warm_process(const std::string& dir) {
  set_cache_settings(CacheSettings{dir, false, true});
  if (glslang_initialised()) {
    std::fprintf(stderr, "glslang was started before the test\n");
    std::exit(3);
  }
  const CompileCacheCounts before = compile_cache_counts();
  auto program = compile_program(unique_program("warm " + dir));
  (void)compiler_versions();
  (void)current_compile_toolchain();
  const CompileCacheCounts d = compile_cache_counts() - before;
  if (!program) {
    std::fprintf(stderr, "compile failed: %s\n", program.error().to_string().c_str());
    std::exit(4);
  }
  if (d.compiles != 0 || d.disk_hits != 6) {
    std::fprintf(stderr, "expected 6 disk hits and no compile, got %zu hits, %zu compiles\n", d.disk_hits, d.compiles);
    std::exit(5);
  }
  if (glslang_initialised()) {
    std::fprintf(stderr, "a warm process started glslang\n");
    std::exit(6);
  }
  std::exit(0);
}

TEST(CompileCacheDeathTest, AWarmProcessDoesNotStartGlslang) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  std::optional<TempDir> dir;
  if (std::getenv(kWarmCacheEnv) == nullptr) {   // the parent: fill the cache
    dir.emplace();
    ::setenv(kWarmCacheEnv, dir->path().c_str(), 1);
    ScopedSettings settings(CacheSettings{dir->path().string(), false, true});
    auto cold = compile_program(unique_program("warm " + dir->path().string()));
    ASSERT_TRUE(cold) << cold.error().to_string();
  }
  const std::string cache_dir = std::getenv(kWarmCacheEnv);
  EXPECT_EXIT(warm_process(cache_dir), ::testing::ExitedWithCode(0), "");
  ::unsetenv(kWarmCacheEnv);
}

}  // namespace
}  // namespace shaderbed
