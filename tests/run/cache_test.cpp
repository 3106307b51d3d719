// The caches through the real binary and drivers (docs/caches.md): a cold run, a warm
// run and a run with both caches off give identical metrics and byte-identical images;
// the warm run compiles nothing and adds nothing to Mesa's cache; caches off writes
// nothing. Plus the Mesa environment's precedence rules and the root-level options
// after every subcommand.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TempDir.h"
#include "ShellCommand.h"
#include "backends/MesaEnvironment.h"
#include "core/CacheSettings.h"
#include "report/JsonReport.h"

namespace shaderbed {
namespace {

namespace fs = std::filesystem;

using test::TempDir;

// The CLI with SHADERBED_CACHE_DIR = `cache_root` and no Mesa cache variables of ours
// or the user's: the binary decides. Returns the exit status and stdout+stderr.
std::pair<int, std::string> shaderbed_cli(const fs::path& cache_root, const std::string& args) {
  return test::run_shell("env -u MESA_SHADER_CACHE_DIR -u MESA_SHADER_CACHE_DISABLE -u MESA_GLSL_CACHE_DIR "
                         "-u MESA_GLSL_CACHE_DISABLE -u SHADERBED_MESA_SHADER_CACHE SHADERBED_CACHE_DIR='" +
                         cache_root.string() + "' " + SHADERBED_BINARY + " " + args);
}

// Every file under `dir` with its size, by relative path.
std::map<std::string, uintmax_t> snapshot(const fs::path& dir) {
  std::map<std::string, uintmax_t> files;
  if (!fs::exists(dir)) return files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = e.file_size();
  return files;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An EXR file's bytes with the capture date (the "capDate" header attribute the writer
// stamps with the time of writing) blanked: everything else, the pixels included, must
// match byte for byte.
std::string exr_without_capture_date(std::string bytes) {
  static const std::string attribute("capDate\0string\0", 15);
  const size_t at = bytes.find(attribute);
  if (at == std::string::npos || at + attribute.size() + 4 > bytes.size()) return bytes;
  uint32_t size = 0;
  std::memcpy(&size, bytes.data() + at + attribute.size(), 4);
  const size_t value = at + attribute.size() + 4;
  if (value + size <= bytes.size()) std::fill_n(bytes.begin() + value, size, '0');
  return bytes;
}

nlohmann::json load_json(const fs::path& p) { return nlohmann::json::parse(read_bytes(p)); }

std::map<std::string, nlohmann::json> cells_by_id(const nlohmann::json& report) {
  std::map<std::string, nlohmann::json> cells;
  for (const nlohmann::json& c : report["results"]) cells[c["id"].get<std::string>()] = c;
  return cells;
}

TEST(Caches, ColdWarmAndOffRunsGiveIdenticalMetricsAndImages) {
  TempDir work;
  const fs::path root = work.path() / "cache";
  const std::string cells = "run --case phong,ward_iso --size 32 --repeat 0";

  auto [cold_status, cold_out] = shaderbed_cli(root, cells + " --json " + work / "A.json" + " --keep-images all --out " + work / "A");
  ASSERT_EQ(cold_status, 0) << cold_out;
  const auto mesa_cold = snapshot(root / "mesa");
  const auto compile_cold = snapshot(root / "compile");
  EXPECT_FALSE(mesa_cold.empty()) << "Mesa's shader cache is on by default, in <root>/mesa";
  EXPECT_FALSE(compile_cold.empty()) << "the compile cache is on by default, in <root>/compile";
  const nlohmann::json a = load_json(work / "A.json");
  EXPECT_EQ(a["cache"]["driver"]["enabled"], true);
  EXPECT_EQ(fs::path(a["cache"]["driver"]["dir"].get<std::string>()), root / "mesa");
  EXPECT_EQ(a["cache"]["compile"]["enabled"], true);
  EXPECT_GT(a["cache"]["compile"]["misses"].get<size_t>(), 0u);
  // The reader gives the field back, and writes it again unchanged.
  auto parsed = read_json(work / "A.json");
  ASSERT_TRUE(parsed) << parsed.error().to_string();
  ASSERT_TRUE(parsed->cache);
  EXPECT_TRUE(parsed->cache->driver_cache);
  EXPECT_EQ(parsed->cache->compile_cache_dir, (root / "compile").string());
  EXPECT_EQ(parsed->cache->compile_misses, a["cache"]["compile"]["misses"].get<size_t>());
  EXPECT_EQ(parsed->cache->compile_hits, a["cache"]["compile"]["hits"].get<size_t>());
  EXPECT_EQ(parsed->cache->compile_memory_hits, a["cache"]["compile"]["memory_hits"].get<size_t>());
  EXPECT_EQ(nlohmann::json::parse(to_json(*parsed))["cache"], a["cache"]);

  auto [warm_status, warm_out] = shaderbed_cli(root, cells + " --json " + work / "B.json" + " --keep-images all --out " + work / "B");
  ASSERT_EQ(warm_status, 0) << warm_out;
  const nlohmann::json b = load_json(work / "B.json");
  EXPECT_GT(b["cache"]["compile"]["hits"].get<size_t>(), 0u);
  EXPECT_EQ(b["cache"]["compile"]["misses"].get<size_t>(), 0u) << "a warm run compiles nothing";
  EXPECT_EQ(snapshot(root / "mesa"), mesa_cold) << "every pipeline a Mesa cache hit: nothing new written";
  EXPECT_EQ(snapshot(root / "compile"), compile_cold);

  auto [off_status, off_out] = shaderbed_cli(
      root, "--no-driver-cache " + cells + " --no-compile-cache --json " + work / "C.json" + " --keep-images all --out " + work / "C");
  ASSERT_EQ(off_status, 0) << off_out;
  const nlohmann::json c = load_json(work / "C.json");
  EXPECT_EQ(c["cache"]["driver"]["enabled"], false);
  EXPECT_EQ(c["cache"]["compile"]["enabled"], false);
  EXPECT_EQ(c["cache"]["compile"]["hits"].get<size_t>() + c["cache"]["compile"]["misses"].get<size_t>(),
            a["cache"]["compile"]["hits"].get<size_t>() + a["cache"]["compile"]["misses"].get<size_t>());
  EXPECT_EQ(snapshot(root / "mesa"), mesa_cold) << "caches off: nothing written";
  EXPECT_EQ(snapshot(root / "compile"), compile_cold) << "caches off: nothing written";

  // Every cell's metrics, exactly; and status, hashes and instruction counts with them.
  const auto cells_a = cells_by_id(a), cells_b = cells_by_id(b), cells_c = cells_by_id(c);
  ASSERT_GT(cells_a.size(), 50u);
  ASSERT_EQ(cells_a.size(), cells_b.size());
  ASSERT_EQ(cells_a.size(), cells_c.size());
  for (const auto& [id, cell] : cells_a) {
    for (const auto* other : {&cells_b, &cells_c}) {
      ASSERT_TRUE(other->contains(id)) << id;
      const nlohmann::json& o = other->at(id);
      EXPECT_EQ(cell["metrics"], o["metrics"]) << id;
      EXPECT_EQ(cell["status"], o["status"]) << id;
      EXPECT_EQ(cell["spirv_hash"], o["spirv_hash"]) << id;
      EXPECT_EQ(cell["instructions"], o["instructions"]) << id;
    }
  }
  // Every image, byte for byte (but for the time it was written).
  size_t images = 0, different = 0;
  for (const auto& [file, size] : snapshot(work.path() / "A")) {
    if (!file.ends_with(".exr")) continue;
    const std::string bytes = exr_without_capture_date(read_bytes(work.path() / "A" / file));
    for (const char* run : {"B", "C"})
      if (exr_without_capture_date(read_bytes(work.path() / run / file)) != bytes) {
        ADD_FAILURE() << file << " differs in run " << run << " (B warm, C caches off)";
        ++different;
      }
    ++images;
  }
  EXPECT_EQ(different, 0u);
  EXPECT_GE(images, cells_a.size()) << "a render per cell, plus errors";
}

// A run that draws nothing on GL compiles no GL target: two Vulkan stages instead of four
// stages and two SPIRV-Cross outputs, so a cold Vulkan-only cell pays half the compiles.
TEST(Caches, VulkanOnlyRunsCompileOnlyTheVulkanTarget) {
  const auto misses = [](const std::string& backends) {
    TempDir root;
    const std::string json = root / "r.json";
    const auto [status, out] = shaderbed_cli(root.path(), "run --case lambert --variant pixel --lang glsl --shape sphere "
                                                          "--size 32 --repeat 0 --quiet --backend " + backends +
                                                          " --json " + json);
    EXPECT_EQ(status, 0) << out;
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const nlohmann::json& r : j["results"]) EXPECT_EQ(r["status"], "pass") << r.dump();
    return j["cache"]["compile"]["misses"].get<size_t>();
  };
  const size_t vulkan = misses("vulkan"), both = misses("vulkan,gl");
  EXPECT_EQ(vulkan, 2u) << "vertex and fragment, Vulkan target";
  EXPECT_GT(both, vulkan) << "GL-target stages and SPIRV-Cross output on top";
}

TEST(Caches, RootOptionsAreAcceptedAfterEverySubcommand) {
  TempDir work;
  // Each command stopped by a bad name: the options parsed if the error is about the name.
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"run --case no_such_case", "no_such_case"},
      {"eval no_such_model --L 0,1,0 --V 0,1,0", "no_such_model"},
      {"merge " + work / "no_such.json", "no_such.json"},
      {"stats --case no_such_case", "no_such_case"},
      {"sweep no_such_case", "no_such_case"},
      {"hard --case no_such_case", "no_such_case"},
      {"bench --case no_such_case", "no_such_case"}};
  for (const auto& [command, name] : commands) {
    auto [status, out] = shaderbed_cli(
        work.path(), command + " --no-driver-cache --no-compile-cache --cache-dir " + work / "elsewhere");
    EXPECT_NE(status, 0) << command;
    EXPECT_EQ(out.find("not expected"), std::string::npos) << command << ": " << out;
    EXPECT_NE(out.find(name), std::string::npos) << command << ": " << out;
  }
  // Before the subcommand too; and --cache-dir moves both caches.
  auto [status, out] = shaderbed_cli(work.path(), "--cache-dir " + work / "moved" +
                                                      " run --case ambient --variant vertex --lang glsl "
                                                      "--backend vulkan --shape sphere --size 16 --repeat 0");
  ASSERT_EQ(status, 0) << out;
  EXPECT_FALSE(snapshot(work.path() / "moved" / "compile").empty());
  EXPECT_FALSE(snapshot(work.path() / "moved" / "mesa").empty());
  EXPECT_FALSE(fs::exists(work.path() / "compile")) << "SHADERBED_CACHE_DIR was overridden";
}

// ---- Mesa's environment ----------------------------------------------------------------

class ScopedMesaEnvironment {
 public:
  ScopedMesaEnvironment() : settings_(cache_settings()) {
    for (const char* n : kNames) {
      const char* v = std::getenv(n);
      saved_.push_back(v ? std::optional<std::string>(v) : std::nullopt);
      ::unsetenv(n);
    }
  }
  ~ScopedMesaEnvironment() {
    for (size_t i = 0; i < std::size(kNames); ++i)
      if (saved_[i]) ::setenv(kNames[i], saved_[i]->c_str(), 1);
      else ::unsetenv(kNames[i]);
    set_cache_settings(settings_);
  }

 private:
  static constexpr const char* kNames[] = {"MESA_SHADER_CACHE_DIR", "MESA_SHADER_CACHE_DISABLE", "MESA_GLSL_CACHE_DIR",
                                           "MESA_GLSL_CACHE_DISABLE", "SHADERBED_MESA_SHADER_CACHE"};
  CacheSettings settings_;
  std::vector<std::optional<std::string>> saved_;
};

std::string env_or(const char* name, const char* otherwise = "(unset)") {
  const char* v = std::getenv(name);
  return v ? v : otherwise;
}

TEST(MesaEnvironment, OnByDefaultInTheCacheRoot) {
  ScopedMesaEnvironment scoped;
  TempDir root;
  set_cache_settings(CacheSettings{root.path().string(), true, true});
  isolate_mesa_shader_cache();
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DIR"), root / "mesa");
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DISABLE"), "(unset)");
  EXPECT_TRUE(fs::is_directory(root.path() / "mesa"));
  const MesaShaderCacheState state = mesa_shader_cache_state();
  EXPECT_TRUE(state.enabled);
  EXPECT_EQ(state.dir, root / "mesa");
  isolate_mesa_shader_cache();   // idempotent
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DIR"), root / "mesa");
}

TEST(MesaEnvironment, TheUsersOwnSettingsAreRespected) {
  ScopedMesaEnvironment scoped;
  TempDir root;
  set_cache_settings(CacheSettings{root.path().string(), true, true});
  ::setenv("MESA_SHADER_CACHE_DIR", "/tmp/users-own-mesa-cache", 1);
  isolate_mesa_shader_cache();
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DIR"), "/tmp/users-own-mesa-cache");
  EXPECT_EQ(mesa_shader_cache_state().dir, "/tmp/users-own-mesa-cache");
  ::unsetenv("MESA_SHADER_CACHE_DIR");
  ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  isolate_mesa_shader_cache();
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DIR"), "(unset)");
  EXPECT_FALSE(mesa_shader_cache_state().enabled);
  EXPECT_FALSE(fs::exists(root.path() / "mesa"));
}

TEST(MesaEnvironment, NoDriverCacheDisablesEvenTheUsersCache) {
  ScopedMesaEnvironment scoped;
  TempDir root;
  ::setenv("MESA_SHADER_CACHE_DIR", "/tmp/users-own-mesa-cache", 1);
  set_cache_settings(CacheSettings{root.path().string(), false, true});
  isolate_mesa_shader_cache();
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DISABLE"), "true");
  EXPECT_FALSE(mesa_shader_cache_state().enabled);
  // No cache root at all: disabled, never the user's ~/.cache.
  ::unsetenv("MESA_SHADER_CACHE_DISABLE");
  ::unsetenv("SHADERBED_MESA_SHADER_CACHE");
  set_cache_settings(CacheSettings{"", true, true});
  isolate_mesa_shader_cache();
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DISABLE"), "true");
}

TEST(MesaEnvironment, ValuesAParentShaderbedSetAreNotTheUsers) {
  ScopedMesaEnvironment scoped;
  TempDir parent, child;
  set_cache_settings(CacheSettings{parent.path().string(), true, true});
  isolate_mesa_shader_cache();   // what a parent process leaves in its children's environment
  set_cache_settings(CacheSettings{child.path().string(), true, true});
  isolate_mesa_shader_cache();   // the child, with its own settings
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DIR"), child / "mesa");
  set_cache_settings(CacheSettings{child.path().string(), false, true});
  isolate_mesa_shader_cache();
  set_cache_settings(CacheSettings{child.path().string(), true, true});
  isolate_mesa_shader_cache();   // an inherited DISABLE of ours is not the user's either
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DIR"), child / "mesa");
  EXPECT_EQ(env_or("MESA_SHADER_CACHE_DISABLE"), "(unset)");
}

}  // namespace
}  // namespace shaderbed
