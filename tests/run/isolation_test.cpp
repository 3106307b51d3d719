// Isolation through the CLI: a shader that crashes glslang, a draw that never ends, a
// source that is /dev/zero and an interrupt each cost their own cells (or end the run with
// what it has), never the run. Each case is differential against a Lambert original that
// compiles and draws, so the same run shows the good cells still passing.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "FileContents.h"
#include "ShellCommand.h"
#include "TempDir.h"
#include "core/AddressSanitizer.h"

namespace {

using shaderbed::test::read_json;
using shaderbed::test::shaderbed_cli;

namespace fs = std::filesystem;
using nlohmann::json;

// A Lambert original in HLSL and one more variant, `port`, in `language` with the given
// vertex and fragment text; its bindings name what the good shaders declare.
std::string write_case(const shaderbed::test::TempDir& dir, const std::string& language, const std::string& vertex,
                       const std::string& fragment, const std::string& extra_bindings = "") {
  dir.write("good.hlsl", R"(// Lambert diffuse (book §5.5): the original every cell of these cases is judged against.
float4x4 Transform;
float3 LightDir;
struct VertexIn { float4 Position : POSITION; float3 Normal : NORMAL; };
struct VertexOut { float4 Position : POSITION; float3 Normal : TEXCOORD0; };
VertexOut VS(VertexIn i) { VertexOut o; o.Position = mul(Transform, i.Position); o.Normal = i.Normal; return o; }
float4 PS(VertexOut i) : COLOR0 { float d = saturate(dot(normalize(i.Normal), LightDir)); return float4(d, d, d, 1); }
)");
  const std::string ext = language == "glsl" ? "" : "." + language;
  const std::string vs = language == "glsl" ? "port.vert" : "port_vs" + ext;
  const std::string ps = language == "glsl" ? "port.frag" : "port_ps" + ext;
  dir.write(vs, vertex);
  dir.write(ps, fragment);
  return dir.write("c.toml", "reference = { language = \"hlsl\", variant = \"original\" }\n"
                             "[variants.original]\n"
                             "hlsl = { vertex = \"good.hlsl\", fragment = \"good.hlsl\", vertex_entry = \"VS\", "
                             "fragment_entry = \"PS\" }\n"
                             "[variants.port]\n" +
                                 language + " = { vertex = \"" + vs + "\", fragment = \"" + ps + "\" }\n"
                                 "[bindings.hlsl]\nTransform = \"transform\"\nLightDir = \"light_vector\"\n" +
                                 (language == "hlsl" ? "" : "[bindings." + language + "]\n" + extra_bindings));
}

const char* const kGlslVertex = R"(// Pass-through vertex stage (book §6.3.1) for the isolation tests.
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 vNormal;
layout(binding = 0) uniform T { mat4 Transform; };
void main() { gl_Position = Transform * position; vNormal = normal; }
)";

const char* const kSlowFragment = R"(// A fragment stage whose draw takes minutes: llvmpipe ends every loop after 65535
// iterations (its guard against hangs), so the body does eight sin()s a turn; the bound is
// a uniform no compiler can see through.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 colour;
layout(binding = 1) uniform S { int n; };
void main() {
  float x = vNormal.x;
  for (int i = 0; i < n; ++i) {
    x = sin(x * 1.0001 + float(i)); x = sin(x * 1.0002 + 0.5); x = sin(x * 1.0003 + 0.25); x = sin(x * 1.0004 + 0.125);
    x = sin(x * 1.0005 + 0.1); x = sin(x * 1.0006 + 0.2); x = sin(x * 1.0007 + 0.3); x = sin(x * 1.0008 + 0.4);
  }
  colour = vec4(vNormal, x);
}
)";

// A Cg case whose fragment entry parameter has no name: it crashes glslang 12 through the
// Cg dialect layer (6 of 3400 mutation-fuzzing runs of the library's Cg shaders).
std::string write_crashing_cg_case(const shaderbed::test::TempDir& dir) {
  return write_case(dir, "cg", R"(// Lambert's vertex stage (book §5.5) in Cg.
float4 main(float4 p : POSITION, uniform float4x4 Transform) : POSITION { return mul(Transform, p); }
)",
                                          R"(// A Cg fragment program with an unnamed entry parameter (crashes glslang 12).
float4 main(float3 : TEXCOORD0) : COLOR { return float4(1, 1, 1, 1); }
)",
                                          "Transform = \"transform\"\n");
}

TEST(Isolation, ACompilerCrashIsAnErrorCellAndTheRunGoesOn) {
  shaderbed::test::TempDir dir("isolation");
  const std::string the_case = write_crashing_cg_case(dir);
  const std::string results = dir / "r.json";
  const auto [status, out] = shaderbed_cli("run --case " + the_case + " --shape sphere,cube --size 32 --repeat 0 -q --json " + results);
  EXPECT_EQ(status, 1) << out;
  const json j = read_json(results);
  int crashed = 0, passed = 0;
  for (const json& r : j["results"]) {
    if (r["variant"] == "port") {
      EXPECT_EQ(r["status"], "error") << r["id"];
      const std::string message = r["message"];
      EXPECT_NE(message.find("compiler crashed: signal 11 (SIGSEGV) while compiling c's cg shaders"), std::string::npos)
          << message;
      EXPECT_NE(message.find("port_ps.cg"), std::string::npos) << message;
      ++crashed;
    } else {
      EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
      ++passed;
    }
  }
  EXPECT_EQ(crashed, 6) << "cg on vulkan/spirv, gl/spirv, gl/cross for two shapes";
  EXPECT_EQ(passed, 6);
}

// The crashing port in the original's own language: the original's cells, which share the
// binding table with it, still pass (nothing compiles the port in their name).
TEST(Isolation, ACrashingVariantDoesNotTakeItsLanguagesOtherVariantsDown) {
  shaderbed::test::TempDir dir("isolation");
  // glslang 12 dereferences null on an HLSL entry parameter without a name (checked on glslang 12.0).
  const std::string the_case = write_case(dir, "hlsl", R"(// Lambert's vertex stage (book §5.5).
float4x4 Transform;
float4 main(float4 p : POSITION) : POSITION { return mul(Transform, p); }
)",
                                          R"(// A pixel stage with an unnamed parameter (crashes glslang 12).
float4 main(int) : COLOR0 { return 1; }
)");
  const std::string results = dir / "r.json";
  const auto [status, out] = shaderbed_cli("run --case " + the_case + " --shape sphere --size 32 --repeat 0 -q --json " + results);
  EXPECT_EQ(status, 1) << out;
  const json j = read_json(results);
  int errors = 0, passed = 0;
  for (const json& r : j["results"]) {
    const bool port = r["variant"] == "port";
    EXPECT_EQ(r["status"], port ? "error" : "pass") << r["id"] << ": " << r["message"];
    (port ? errors : passed) += 1;
  }
  EXPECT_EQ(errors, 3);
  EXPECT_EQ(passed, 3);
}

TEST(Isolation, ADrawThatNeverEndsIsATimeoutOnBothBackends) {
  shaderbed::test::TempDir dir("isolation");
  const std::string the_case = write_case(dir, "glsl", kGlslVertex, kSlowFragment,
                                          "Transform = \"transform\"\nn = 1000000000\n");
  const std::string results = dir / "r.json";
  const auto [status2, out2] = shaderbed_cli("run --case " + the_case + " --shape sphere --size 128 --repeat 0 -q "
                                             "--draw-timeout 1.5 --json " + results);
  EXPECT_EQ(status2, 1) << out2;
  const json j = read_json(results);
  int timeouts = 0;
  for (const json& r : j["results"]) {
    if (r["variant"] == "port") {
      EXPECT_EQ(r["status"], "error") << r["id"];
      EXPECT_NE(r["message"].get<std::string>().find("timeout: the draw took longer than 1.5 s (--draw-timeout)"),
                std::string::npos) << r["message"];
      ++timeouts;
    } else {
      EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
    }
  }
  EXPECT_EQ(timeouts, 4) << "glsl on vulkan/spirv, gl/glsl, gl/spirv, gl/cross";
}

TEST(Isolation, SourcesThatAreNotRegularFilesAreRefused) {
  shaderbed::test::TempDir dir("isolation");
  const std::string the_case = write_case(dir, "hlsl", R"(// Includes /dev/zero: must be refused, not read until memory runs out.
#include "/dev/zero"
float4 main(float4 p : POSITION) : POSITION { return p; }
)",
                                          "float4 main() : COLOR0 { return 1; }\n");
  const std::string results = dir / "r.json";
  const auto [status, out] = shaderbed_cli("run --case " + the_case + " --variant port --shape sphere --backend vulkan --size 16 --repeat 0 -q --json " + results);
  EXPECT_EQ(status, 1) << out;
  const json j = read_json(results);
  ASSERT_EQ(j["results"].size(), 1u);
  EXPECT_EQ(j["results"][0]["status"], "error");
  EXPECT_NE(j["results"][0]["message"].get<std::string>().find("not a regular file"), std::string::npos)
      << j["results"][0]["message"];
}

TEST(Isolation, AnInterruptedRunWritesWhatItHasMarkedIncomplete) {
  shaderbed::test::TempDir dir("isolation");
  const std::string the_case = write_case(dir, "glsl", kGlslVertex, kSlowFragment,
                                          "Transform = \"transform\"\nn = 1000000000\n");
  const std::string results = dir / "r.json";
  // SIGINT once the first progress line says cells have finished (the original's: the
  // port's draw never ends), however slow the machine (a sanitizer build, a busy CI).
  const std::string progress = dir / "progress.txt";
  const auto [status, out] = shaderbed::test::run_shell(
      "( " + std::string(SHADERBED_BINARY) + " run --case " + the_case + " --size 128 --repeat 0 -j2 --draw-timeout 600 --json " +
      results + " > " + progress + " 2>&1 & pid=$!; for i in $(seq 1200); do grep -q '^progress: ' " + progress +
      " && break; sleep 0.1; done; kill -INT $pid; wait $pid; echo \"exit status $?\"; cat " + progress + " )");
  EXPECT_NE(out.find("exit status 130"), std::string::npos) << out;
  EXPECT_NE(out.find("INCOMPLETE: interrupted by SIGINT after"), std::string::npos) << out;
  const json j = read_json(results);
  ASSERT_TRUE(j.contains("incomplete")) << j.dump(2);
  EXPECT_EQ(j["incomplete"]["signal"], 2);
  EXPECT_GT(j["results"].size(), 0u) << "the original's cells finished before the endless draw";
  for (const json& r : j["results"]) EXPECT_EQ(r["variant"], "original");
}

// A worker that replaces a crashed one and is killed before its hello (every later one
// too, through the test hook): the slot gives up after a few tries, the cells it had left
// are errors saying so, and the run still writes its report.
TEST(Isolation, AReplacementWorkerKilledBeforeItsHelloCostsItsCellsNotTheRun) {
  shaderbed::test::TempDir dir("isolation");
  const std::string the_case = write_crashing_cg_case(dir);
  const std::string results = dir / "r.json";
  const auto [status, out] = shaderbed::test::run_shell(
      "SHADERBED_TEST_WORKER_FAULT=KILL@start:2+ timeout -s KILL 120 " + std::string(SHADERBED_BINARY) +
      " run --case " + the_case + " --shape sphere,cube --backend vulkan --size 16 --repeat 0 -j1 -q --json " + results);
  EXPECT_EQ(status, 1) << out;
  const json j = read_json(results);
  EXPECT_FALSE(j.contains("incomplete")) << j.dump(2);
  int crashed = 0, not_started = 0;
  for (const json& r : j["results"]) {
    const std::string message = r["message"];
    if (message.find("compiler crashed") != std::string::npos) ++crashed;
    if (message.find("worker could not be started: signal 9 (SIGKILL") != std::string::npos) {
      EXPECT_NE(message.find("(3 tries)"), std::string::npos) << message;
      ++not_started;
    }
    if (r["status"] != "pass") {
      EXPECT_EQ(r["status"], "error") << r["id"] << ": " << message;
    }
  }
  EXPECT_EQ(crashed, 1) << "the port's first group, on its first worker\n" << j.dump(2);
  EXPECT_GE(not_started, 1) << "the port's other shape, left to the replacements\n" << j.dump(2);
  EXPECT_EQ(j["results"].size(), 4u);
}

// Every worker killed before its hello, the first too: no cell can be drawn, and the run
// still writes its report, every cell an error saying why (the slow probe
// tests/reliability/supervisor_signals.py found the run ending with no report).
TEST(Isolation, NoWorkerEverStartingStillWritesTheReport) {
  shaderbed::test::TempDir dir("isolation");
  const std::string results = dir / "r.json";
  const auto [status, out] = shaderbed::test::run_shell(
      "SHADERBED_TEST_WORKER_FAULT=KILL@start:1+ timeout -s KILL 120 " + std::string(SHADERBED_BINARY) +
      " run --case lambert --variant pixel --lang glsl --shape sphere,cube --backend vulkan --size 16 --repeat 0 -j1 -q"
      " --json " + results);
  EXPECT_EQ(status, 1) << out;
  const json j = read_json(results);
  ASSERT_EQ(j["results"].size(), 2u) << j.dump(2);
  for (const json& r : j["results"]) {
    EXPECT_EQ(r["status"], "error") << r["id"];
    EXPECT_NE(std::string(r["message"]).find("worker could not be started"), std::string::npos) << r["message"];
  }
}

// SIGHUP (a closed terminal) ends the run like SIGINT, and the Ctrl-C presses that follow
// it while the report is written do not end the process before it is.
TEST(Isolation, AHangUpAndRepeatedInterruptsStillWriteThePartialReport) {
  shaderbed::test::TempDir dir("isolation");
  const std::string the_case = write_case(dir, "glsl", kGlslVertex, kSlowFragment,
                                          "Transform = \"transform\"\nn = 1000000000\n");
  const std::string results = dir / "r.json";
  const std::string progress = dir / "progress.txt";
  const auto [status, out] = shaderbed::test::run_shell(
      "( " + std::string(SHADERBED_BINARY) + " run --case " + the_case + " --shape sphere --size 32 --repeat 0 -j2 "
      "--draw-timeout 600 --json " + results + " --junit " + (dir / "r.xml") + " > " + progress +
      " 2>&1 & pid=$!; for i in $(seq 1200); do grep -q '^progress: ' " + progress +
      " && break; sleep 0.1; done; kill -HUP $pid; while kill -INT $pid 2>/dev/null; do sleep 0.002; done; wait $pid; "
      "echo \"exit status $?\"; cat " + progress + " )");
  EXPECT_NE(out.find("exit status 129"), std::string::npos) << out;
  EXPECT_NE(out.find("INCOMPLETE: interrupted by SIGHUP after"), std::string::npos) << out;
  const json j = read_json(results);
  ASSERT_TRUE(j.contains("incomplete")) << j.dump(2);
  EXPECT_EQ(j["incomplete"]["signal"], 1);
  EXPECT_GT(j["results"].size(), 0u);
  EXPECT_TRUE(fs::exists(dir / "r.xml"));
}

// Every step has a deadline (--step-timeout): a worker stopped (SIGSTOP, through the test
// hook) while judging a cell or preparing a group's reference is killed, the cell (or the
// group) is an error naming the step, and a fresh worker finishes the run.
TEST(Isolation, AWorkerStoppedInAnyStepIsATimeoutNamingTheStep) {
  for (const auto& [step, expected] :
       {std::pair<std::string, std::string>{"judge", "timeout in judge: the step took longer than 1.5 s (--step-timeout) "
                                                      "while judging this cell [stage judge]"},
        std::pair<std::string, std::string>{"reference", "timeout in reference: the step took longer than 1.5 s "
                                                          "(--step-timeout) while preparing the reference of "
                                                          "lambert/pixel/sphere [stage reference]"}}) {
    shaderbed::test::TempDir dir("isolation");
    const std::string results = dir / "r.json";
    const auto [status, out] = shaderbed::test::run_shell(
        "SHADERBED_TEST_WORKER_FAULT=STOP@" + step + ":1 timeout -s KILL 120 " + std::string(SHADERBED_BINARY) +
        " run --case lambert --variant pixel --lang glsl --backend vulkan --shape sphere,cube --size 16 "
        "--repeat 0 -j1 -q --step-timeout 1.5 --json " + results);
    EXPECT_EQ(status, 1) << step << ": " << out;
    const json j = read_json(results);
    ASSERT_EQ(j["results"].size(), 2u) << j.dump(2);
    for (const json& r : j["results"]) {
      if (r["shape"] == "sphere") {
        EXPECT_EQ(r["status"], "error") << r["id"];
        EXPECT_NE(r["message"].get<std::string>().find(expected), std::string::npos) << r["message"];
      } else {
        EXPECT_EQ(r["status"], "pass") << r["id"] << ": " << r["message"];
      }
    }
  }
}

// A worker's allocation past its address-space limit (--worker-memory) is "out of
// memory", not a crash of the step it was in: a 4096 px reference needs about 2 GiB and
// fails at once under 1.5 GiB, where a worker starts in about 1.1 GiB (with llvmpipe's
// threads pinned, whose stacks count against the limit).
TEST(Isolation, AnAllocationPastTheWorkersLimitIsOutOfMemory) {
  if (shaderbed::address_sanitizer_build) GTEST_SKIP() << "workers have no address-space limit under AddressSanitizer";
  shaderbed::test::TempDir dir("isolation");
  const std::string results = dir / "r.json";
  const auto [status, out] = shaderbed::test::run_shell(
      "LP_NUM_THREADS=2 " + std::string(SHADERBED_BINARY) +
      " run --case lambert --variant pixel --lang glsl --backend vulkan --shape sphere --size 4096 --repeat 0 -j1 "
      "-q --worker-memory 1536 --json " + results);
  EXPECT_EQ(status, 1) << out;
  const json j = read_json(results);
  ASSERT_EQ(j["results"].size(), 1u) << j.dump(2);
  EXPECT_EQ(j["results"][0]["status"], "error");
  const std::string message = j["results"][0]["message"];
  EXPECT_NE(message.find("out of memory: the worker's allocations passed its 1536 MiB limit (--worker-memory)"),
            std::string::npos) << message;
  EXPECT_EQ(message.find("crashed"), std::string::npos) << message;
}

}  // namespace
