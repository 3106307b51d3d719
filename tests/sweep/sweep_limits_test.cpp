// `shaderbed sweep` within bounds: axes that multiply past --max-points are refused before
// anything is drawn, with the count and the flag that raises it; and a SIGINT or SIGTERM
// during the sweep leaves a JSON of the points finished so far, marked interrupted, with
// the shell's exit status (130, 143). The signal is sent once the progress on stderr shows
// the first point finished: no sleep decides what the sweep has done by then.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TempDir.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(SweepLimits, AxesOverTheLimitAreRefusedBeforeAnythingIsDrawn) {
  shaderbed::test::TempDir dir("sweep_limits");
  const std::string out = dir / "points.json";
  // 1000 x 11 = 11,000 points (hours of drawing): over the default 10,000. `timeout`
  // keeps a sweep that does not refuse from running that long here.
  const auto [status, text] = shaderbed::test::run_shell(
      "timeout 30 " + std::string(SHADERBED_BINARY) +
      " sweep cook_torrance --param slope_m=0.1:1:1000 --param fresnel_r0=0.1:0.9:11 --size 16 --json " + out);
  EXPECT_EQ(status, 2) << text;
  EXPECT_NE(text.find("the axes make 11000 points (1000 slope_m x 11 fresnel_r0 x 1 precision)"), std::string::npos) << text;
  EXPECT_NE(text.find("more than the limit of 10000"), std::string::npos) << text;
  EXPECT_NE(text.find("--max-points 11000"), std::string::npos) << text;
  EXPECT_EQ(text.find("[1/"), std::string::npos) << "no point drawn: " << text;
  EXPECT_FALSE(fs::exists(out));

  // The flag lowers the limit as well as raising it: 6 x 3 = 18 points against 10.
  const auto [lowered, why] = shaderbed::test::shaderbed_cli(
      "sweep oren_nayar --param lut_size=8:256:6 --param tessellation=8:64:3 --max-points 10 --size 16");
  EXPECT_EQ(lowered, 2) << why;
  EXPECT_NE(why.find("18 points"), std::string::npos) << why;
}

struct Interrupted {
  int exit_status = -1;
  std::string stderr_text;
};

// Starts a sweep of many quick points, reads its progress until point 2 starts (point 1 is
// then finished), sends `signal` and waits for the sweep to end.
Interrupted interrupt_sweep(const std::string& json_path, int signal) {
  int err[2];
  if (::pipe(err) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(err[1], STDERR_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::close(err[0]);
    ::execl(SHADERBED_BINARY, SHADERBED_BINARY, "sweep", "oren_nayar", "--variant", "pixel_lut", "--param",
            "lut_size=8:256:200", "--size", "16", "--repeat", "1", "--warmup", "0", "--json", json_path.c_str(),
            static_cast<char*>(nullptr));
    _exit(127);
  }
  ::close(err[1]);
  Interrupted out;
  bool sent = false;
  char buffer[4096];
  for (ssize_t n; (n = ::read(err[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    out.stderr_text.append(buffer, size_t(n));
    if (!sent && out.stderr_text.find("\n[2/") != std::string::npos) {
      ::kill(pid, signal);
      sent = true;
    }
  }
  ::close(err[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  out.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  if (!sent) out.stderr_text += "\n(the sweep ended before its second point: no signal sent)";
  return out;
}

void expect_partial_json(const std::string& path, const char* signal_name, const std::string& log) {
  ASSERT_TRUE(fs::exists(path)) << log;
  std::ifstream f(path);
  const json j = json::parse(f, nullptr, /*allow_exceptions=*/false);
  ASSERT_TRUE(j.is_object()) << "not valid JSON: " << path;
  EXPECT_EQ(j.at("interrupted"), true);
  EXPECT_EQ(j.at("interrupted_by"), signal_name);
  const size_t done = j.at("steps_done"), planned = j.at("steps_planned");
  EXPECT_GE(done, 1u);
  EXPECT_LT(done, planned);
  ASSERT_EQ(j.at("points").size(), done) << "one variant: a point per step";
  for (const json& p : j.at("points")) {
    EXPECT_EQ(p.at("status"), "pass") << p.dump();
    EXPECT_TRUE(p.at("time_ms").is_number());
  }
}

TEST(SweepLimits, SigintWritesThePointsFinishedSoFarMarkedInterrupted) {
  shaderbed::test::TempDir dir("sweep_limits");
  const std::string out = dir / "points.json";
  const Interrupted run = interrupt_sweep(out, SIGINT);
  EXPECT_EQ(run.exit_status, 130) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("shaderbed: sweep: interrupted by SIGINT after "), std::string::npos) << run.stderr_text;
  expect_partial_json(out, "SIGINT", run.stderr_text);
}

TEST(SweepLimits, SigtermDoesTheSameWithItsOwnStatus) {
  shaderbed::test::TempDir dir("sweep_limits");
  const std::string out = dir / "points.json";
  const Interrupted run = interrupt_sweep(out, SIGTERM);
  EXPECT_EQ(run.exit_status, 143) << run.stderr_text;
  expect_partial_json(out, "SIGTERM", run.stderr_text);
}

}  // namespace
