// `stats --from` and `--baseline` name files a user chose (issue 30, item 12): /dev/zero,
// a FIFO or a field of the wrong type is one line naming the file and exit 2, at once.
#include <sys/stat.h>

#include <string>

#include <gtest/gtest.h>

#include "ShellCommand.h"
#include "TempDir.h"

namespace {

using shaderbed::test::TempDir;

// The CLI with a deadline (a FIFO with no writer would block forever) and a memory bound
// (a read of /dev/zero would take all of it; this machine is shared).
std::pair<int, std::string> bounded_cli(const std::string& args) {
  return shaderbed::test::run_shell("ulimit -v 4000000; timeout 10 " + std::string(SHADERBED_BINARY) + " " + args);
}

TEST(StatsInput, ADeviceOrAFifoIsOneErrorNamingIt) {
  TempDir dir("stats_fifo");
  const std::string fifo = dir / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string valid = dir.write("valid.json", R"({"entries": []})");
  for (const std::string& bad : {std::string("/dev/zero"), fifo})
    for (const std::string& args : {"stats --quiet --from " + bad, "stats --quiet --from " + valid + " --baseline " + bad}) {
      auto [status, out] = bounded_cli(args);
      EXPECT_EQ(status, 2) << args << "\n" << out;
      EXPECT_NE(out.find("shaderbed: " + bad + ": stats: stats JSON is not a regular file"), std::string::npos)
          << args << "\n" << out;
    }
}

TEST(StatsInput, AFieldOfTheWrongTypeIsOneErrorNamingIt) {
  TempDir dir("stats_types");
  const std::string valid = dir.write("valid.json", R"({"entries": []})");
  for (const char* text : {R"({"entries": [{"case": 1, "variant": "v", "language": "glsl", "stage": "vertex"}]})",
                           R"({"entries": [{"case": "c", "variant": "v", "language": "glsl", "stage": "vertex",
                                           "glsl_lines": "many"}]})",
                           R"({"entries": [{"case": "c", "variant": "v", "language": "glsl", "stage": "vertex",
                                           "spirv": {"total": [1]}}]})",
                           R"({"entries": [{"case": "c", "variant": "v", "language": "glsl", "stage": "vertex",
                                           "nir": {"vulkan": {"alu": "x"}}}]})",
                           R"({"entries": [7]})", R"([1, 2])"}) {
    const std::string file = dir.write("typed.json", text);
    for (const std::string& args : {"stats --quiet --from " + file, "stats --quiet --from " + valid + " --baseline " + file}) {
      auto [status, out] = bounded_cli(args);
      EXPECT_EQ(status, 2) << args << "\n" << out;
      EXPECT_EQ(out.rfind("shaderbed: " + file + ": ", 0), 0u) << args << "\n" << out;
      EXPECT_EQ(out.find('\n'), out.size() - 1) << "one line\n" << out;
    }
  }
}

}  // namespace
