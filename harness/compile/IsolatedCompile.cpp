#include "compile/IsolatedCompile.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <mutex>

#include <fmt/format.h>

#include "compile/IsolatedCompileProtocol.h"
#include "core/AddressSanitizer.h"
#include "core/CacheSettings.h"
#include "core/ThisExecutable.h"

namespace shaderbed {
namespace {

// How every error the child did not answer itself begins (compiler_did_not_finish()).
constexpr const char* kUnfinished[] = {"glslang crashed (", "glslang took longer than ", "glslang's child process "};

std::string signal_text(int signal) {
  const char* name = sigabbrev_np(signal);
  return name ? fmt::format("signal {}, SIG{}", signal, name) : fmt::format("signal {}", signal);
}

// The one child of this process, started on first use; a crashed or stopped one is
// replaced at the next request.
class CompileChild {
 public:
  ~CompileChild() { (void)stop(false); }

  void configure(std::string binary, double timeout_s) {
    const std::lock_guard lock(mutex_);
    binary_ = std::move(binary);
    timeout_s_ = timeout_s;
    configured_ = !binary_.empty();
  }
  // Not behind the mutex: asked on every compile, while another thread's may be under way.
  bool configured() const { return configured_; }

  Result<ShaderModule> compile(const StageRequest& request) {
    const std::lock_guard lock(mutex_);
    const std::string name = request.source.path.empty() ? std::string("a shader")
                                                          : std::filesystem::path(request.source.path).filename().string();
    const auto failed = [&](std::string message) -> Result<ShaderModule> {
      return std::unexpected(Error{.message = std::move(message), .file = request.source.path, .stage = ErrorStage::compile});
    };
    const std::string what = fmt::format("{} ({} stage)", name, to_string(request.source.stage));
    if (pid_ <= 0)
      if (auto ok = start(); !ok) return failed(fmt::format("glslang's child process {} compiling {}", ok.error().message, what));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                                 std::chrono::duration<double>(timeout_s_));
    ReceivedFrame answer;
    if (send_frame(socket_, encode_stage_request(request))) answer = receive_frame(socket_, deadline);
    if (answer.timed_out) {
      (void)stop(true);
      return failed(fmt::format("glslang took longer than {:g} s compiling {}: stopped", timeout_s_, what));
    }
    if (!answer.payload) {
      const auto [signal, code] = stop(false);
      if (signal) return failed(fmt::format("glslang crashed ({}) compiling {}", signal_text(signal), what));
      return failed(fmt::format("glslang's child process ended (exit {}) compiling {}", code, what));
    }
    std::optional<Result<ShaderModule>> module = decode_stage_answer(*answer.payload);
    if (!module) {
      (void)stop(true);
      return failed("glslang's child process answered garbled compiling " + what);
    }
    return std::move(*module);
  }

 private:
  // Started much as run's workers are (run/IsolatedRun.cpp): its own process group (a
  // terminal's Ctrl-C reaches the command only), with run's stack and memory limits. Not
  // PR_SET_PDEATHSIG: that fires when the forking *thread* ends, and a compile may come
  // from a short-lived thread; the child watches for its parent instead
  // (StageCompileServer.cpp).
  Result<void> start() {
    int pair[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
      return fail(ErrorStage::compile, std::string("could not start (socketpair: ") + std::strerror(errno) + ")");
    const int null = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    // Everything the child needs is built before fork: only async-signal-safe calls after it.
    std::vector<std::string> env_text = environment_keeping_crash_signals();
    std::vector<char*> envp;
    for (std::string& e : env_text) envp.push_back(e.data());
    envp.push_back(nullptr);
    std::string program = binary_, verb = "__compile-stages";
    char* argv[] = {program.data(), verb.data(), nullptr};
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
      ::close(pair[0]), ::close(pair[1]);
      if (null >= 0) ::close(null);
      return fail(ErrorStage::compile, std::string("could not start (fork: ") + std::strerror(errno) + ")");
    }
    if (pid == 0) {
      ::setpgid(0, 0);
      if (::getppid() != parent) _exit(126);
      if constexpr (!address_sanitizer_build) {
        const rlimit as{rlim_t(8192) << 20, rlim_t(8192) << 20};
        ::setrlimit(RLIMIT_AS, &as);
      }
      const rlimit stack{rlim_t(64) << 20, rlim_t(64) << 20};
      ::setrlimit(RLIMIT_STACK, &stack);
      if (null >= 0) ::dup2(null, 0);
      ::dup2(2, 1);   // the answers go over the socket: nothing the compiler prints can garble them
      ::dup2(pair[1], 3);
      ::execve(program.c_str(), argv, envp.data());
      _exit(127);
    }
    ::close(pair[1]);
    if (null >= 0) ::close(null);
    pid_ = pid;
    socket_ = pair[0];
    if (!send_frame(socket_, encode_cache_settings(cache_settings()))) {
      (void)stop(true);
      return fail(ErrorStage::compile, "did not start");
    }
    return {};
  }

  // Closes the socket and reaps the child (killed when `kill_it`, or when it does not end
  // within a second of its input closing); the signal that ended it, else its exit code.
  std::pair<int, int> stop(bool kill_it) {
    if (socket_ >= 0) ::close(socket_), socket_ = -1;
    if (pid_ <= 0) return {0, 0};
    if (kill_it) ::kill(pid_, SIGKILL);
    int status = 0;
    pid_t reaped = 0;
    for (int i = 0; i < 100 && (reaped = ::waitpid(pid_, &status, WNOHANG)) == 0; ++i) ::usleep(10000);
    if (reaped == 0) {
      ::kill(pid_, SIGKILL);
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
    }
    pid_ = -1;
    if (WIFSIGNALED(status)) return {WTERMSIG(status), 0};
    return {0, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
  }

  std::mutex mutex_;
  std::atomic<bool> configured_{false};
  std::string binary_;
  double timeout_s_ = 30;
  pid_t pid_ = -1;
  int socket_ = -1;
};

CompileChild& child() {
  static CompileChild instance;
  return instance;
}

}  // namespace

void isolate_compiles(double timeout_s) { child().configure(this_executable().string(), timeout_s); }

bool compiles_isolated() { return child().configured(); }

bool compiler_did_not_finish(const Error& e) {
  return e.stage == ErrorStage::compile &&
         std::any_of(std::begin(kUnfinished), std::end(kUnfinished), [&](const char* p) { return e.message.starts_with(p); });
}

Result<ShaderModule> compile_stage_isolated(Language language, const ShaderSource& source, Target target) {
  return child().compile({.language = language, .target = target, .source = source});
}

}  // namespace shaderbed
