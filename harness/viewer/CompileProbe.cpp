#include "viewer/CompileProbe.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/AddressSanitizer.h"
#include "core/CacheSettings.h"
#include "run/ProgramCache.h"

namespace shaderbed::viewer {
namespace {

std::string signal_text(int signal) {
  const char* name = sigabbrev_np(signal);
  return name ? fmt::format("signal {} (SIG{})", signal, name) : fmt::format("signal {}", signal);
}

std::string files_of(const ShaderFiles& files) {
  const std::string vertex = std::filesystem::path(files.vertex).filename().string();
  const std::string fragment = std::filesystem::path(files.fragment).filename().string();
  return vertex == fragment ? vertex : vertex + ", " + fragment;
}

bool write_all(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += size_t(n);
  }
  return true;
}

}  // namespace

CompileProbe::CompileProbe(std::string binary, double timeout_s) : binary_(std::move(binary)), timeout_s_(timeout_s) {}

CompileProbe::~CompileProbe() {
  if (pid_ > 0) (void)stop();
}

Result<void> CompileProbe::start() {
  int in[2], out[2];
  if (::pipe2(in, O_CLOEXEC) != 0) return fail(ErrorStage::compile, std::string("pipe: ") + std::strerror(errno));
  if (::pipe2(out, O_CLOEXEC) != 0) {
    ::close(in[0]), ::close(in[1]);
    return fail(ErrorStage::compile, std::string("pipe: ") + std::strerror(errno));
  }
  std::vector<std::string> args{binary_, "__view-compile"};
  const CacheSettings caches = cache_settings();
  if (!caches.root.empty()) args.insert(args.end(), {"--cache-dir", caches.root});
  if (!caches.compile_enabled()) args.push_back("--no-compile-cache");
  if (!caches.driver) args.push_back("--no-driver-cache");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env = environment_keeping_crash_signals();   // a compiler crash is reported by its signal
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const int spawned = ::posix_spawn(&pid_, binary_.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  ::close(in[0]);
  ::close(out[1]);
  if (spawned != 0) {
    pid_ = -1;
    ::close(in[1]), ::close(out[0]);
    return fail(ErrorStage::compile, fmt::format("cannot start {}: {}", binary_, std::strerror(spawned)));
  }
  to_child_ = in[1];
  from_child_ = out[0];
  buffer_.clear();
  return {};
}

std::string CompileProbe::stop() {
  if (to_child_ >= 0) ::close(to_child_), to_child_ = -1;
  if (from_child_ >= 0) ::close(from_child_), from_child_ = -1;
  if (pid_ <= 0) return "not running";
  int status = 0;
  // Its input is closed: a healthy child ends by itself; one that hangs is killed.
  for (int i = 0; i < 50 && ::waitpid(pid_, &status, WNOHANG) == 0; ++i) ::usleep(10000);
  if (::waitpid(pid_, &status, WNOHANG) == 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, &status, 0);
  }
  pid_ = -1;
  if (WIFSIGNALED(status)) return signal_text(WTERMSIG(status));
  return fmt::format("exit {}", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

void CompileProbe::prepare() {
  if (!binary_.empty() && pid_ <= 0) (void)start();
}

Result<void> CompileProbe::compile(const Case& c, const Variant& variant, Language language) {
  if (binary_.empty()) return {};
  if (pid_ <= 0)
    if (auto ok = start(); !ok) return ok;
  const ShaderFiles& files = variant.shaders.at(language);
  const auto crashed = [&](const std::string& how) -> Result<void> {
    return std::unexpected(Error{.message = fmt::format("compiler crashed: {} while compiling {}'s {} shaders ({})", how,
                                                        c.name, to_string(language), files_of(files)),
                                 .file = files.fragment,
                                 .stage = ErrorStage::compile});
  };
  if (!write_all(to_child_, fmt::format("{}\t{}\t{}\n", c.path, variant.name, to_string(language))))
    return crashed(stop());
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s_);
  size_t newline;
  while ((newline = buffer_.find('\n')) == std::string::npos) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      (void)stop();
      return std::unexpected(Error{.message = fmt::format("compiling {}'s {} shaders ({}) took over {:g} s: stopped",
                                                          c.name, to_string(language), files_of(files), timeout_s_),
                                   .file = files.fragment,
                                   .stage = ErrorStage::compile});
    }
    pollfd p{from_child_, POLLIN, 0};
    const int ready = ::poll(&p, 1, int(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char chunk[4096];
    const ssize_t n = ::read(from_child_, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return crashed(stop());   // the child is gone
    buffer_.append(chunk, size_t(n));
  }
  const std::string line = buffer_.substr(0, newline);
  buffer_.erase(0, newline + 1);
  const auto parsed = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
  if (!parsed.is_object()) return fail(ErrorStage::compile, "the compile probe answered '" + line + "'");
  if (parsed.empty()) return {};
  return std::unexpected(Error{.message = parsed.value("message", std::string()),
                               .file = parsed.value("file", std::string()),
                               .line = parsed.value("line", 0),
                               .column = parsed.value("column", 0),
                               .stage = parse_error_stage(parsed.value("stage", std::string("compile")))
                                            .value_or(ErrorStage::compile)});
}

int serve_compile_probe() {
  std::string line;
  while (std::getline(std::cin, line)) {
    const size_t a = line.find('\t'), b = line.find('\t', a == std::string::npos ? a : a + 1);
    Error error;
    if (a == std::string::npos || b == std::string::npos) {
      error = {.message = "expected: case file, variant, language", .stage = ErrorStage::compile};
    } else {
      const std::string file = line.substr(0, a), variant = line.substr(a + 1, b - a - 1), language = line.substr(b + 1);
      auto c = load_case(file);
      auto lang = parse_language(language);
      if (!c) error = c.error();
      else if (!lang) error = lang.error();
      else {
        error = {.message = "no variant '" + variant + "' in " + language, .file = file, .stage = ErrorStage::case_file};
        for (const Variant& v : c->variants)
          if (v.name == variant && v.shaders.contains(*lang)) {
            ProgramCache programs({.opengl = true});   // fresh: the files changed since the last line
            const CachedProgram& compiled = programs.get(*c, v, *lang);
            error = compiled.program ? Error{} : compiled.program.error();
          }
      }
    }
    const nlohmann::json answer =
        error.message.empty() ? nlohmann::json::object()
                              : nlohmann::json{{"message", error.message}, {"file", error.file}, {"line", error.line},
                                               {"column", error.column}, {"stage", to_string(error.stage)}};
    std::cout << answer.dump() << '\n' << std::flush;
  }
  return 0;
}

}  // namespace shaderbed::viewer
