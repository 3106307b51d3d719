#pragma once
// What the viewer's end-to-end tests drive: a virtual X server (xvfb-run -a) held for the
// test, the viewer running on it as a child process, keys sent to its window with xdotool
// (found by its title once mapped), its title read back, and its screenshots and output
// files waited for. Every process here is the test's own child, stopped by its pid.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "ShellCommand.h"
#include "FileContents.h"
#include "TempDir.h"
#include "imageio/ImageIoModule.h"

extern char** environ;

namespace shaderbed::test {

namespace fs = std::filesystem;

inline bool wait_until(const std::function<bool()>& done, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// `xvfb-run -a` picks the first display without a lock file, so two tests starting one at
// the same moment can pick the same: the start is serialised by this lock (ctest -j).
class XvfbStartLock {
 public:
  XvfbStartLock() : fd_(::open("/tmp/shaderbed-xvfb-run.lock", O_CREAT | O_RDWR | O_CLOEXEC, 0666)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~XvfbStartLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  XvfbStartLock(const XvfbStartLock&) = delete;
  XvfbStartLock& operator=(const XvfbStartLock&) = delete;

 private:
  int fd_;
};

// A child process: `/bin/sh -c command`, stopped (SIGKILL, by its pid) if still running
// when it goes out of scope.
class Process {
 public:
  explicit Process(const std::string& command) {
    const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
    if (::posix_spawn(&pid_, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) != 0) pid_ = -1;
  }
  ~Process() {
    if (pid_ > 0 && !status_) {
      ::kill(pid_, SIGKILL);
      int status;
      ::waitpid(pid_, &status, 0);
    }
  }
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;

  bool started() const { return pid_ > 0; }
  // The exit status once it has ended (-1 killed by a signal); nothing after the timeout.
  std::optional<int> wait(double timeout_s) {
    wait_until([&] {
      int status = 0;
      if (status_ || pid_ <= 0) return true;
      if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
      status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      return true;
    }, timeout_s);
    return status_;
  }

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
};

// An X server for the test: `xvfb-run -a` running a script that reports the display and
// its authority file and waits until told to stop.
class VirtualDisplay {
 public:
  explicit VirtualDisplay(const TempDir& dir) : info_(dir / "display.txt"), stop_(dir / "display.stop") {
    const std::string hold = dir.write("hold-display.sh",
                                       "echo \"$DISPLAY $XAUTHORITY\" > \"$1.tmp\" && mv \"$1.tmp\" \"$1\"\n"
                                       "while [ ! -e \"$2\" ]; do sleep 0.05; done\n");
    XvfbStartLock lock;
    process_.emplace("exec xvfb-run -a sh " + hold + " " + info_ + " " + stop_ + " >/dev/null 2>&1");
    wait_until([&] { return fs::exists(info_) || process_->wait(0); }, 30);
    std::istringstream words(read_text(info_));
    words >> display_ >> authority_;
  }
  ~VirtualDisplay() {
    std::ofstream(stop_) << "stop\n";
    process_->wait(10);
  }
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;

  bool ready() const { return !display_.empty(); }
  // The environment a command needs to reach the display: "DISPLAY=:99 XAUTHORITY=... ".
  std::string env() const { return "DISPLAY=" + display_ + " XAUTHORITY=" + authority_ + " "; }

 private:
  std::string info_, stop_;
  std::optional<Process> process_;
  std::string display_, authority_;
};

// `shaderbed view ARGS` on the display, its stdout and stderr in files, its window found.
class ViewerSession {
 public:
  ViewerSession(const VirtualDisplay& display, const TempDir& dir, const std::string& args)
      : display_(display), out_(dir / "viewer.out"), err_(dir / "viewer.err"),
        process_(display.env() + "exec " + std::string(SHADERBED_BINARY) + " view " + args + " >" + out_ + " 2>" + err_) {
    // The window exists once it is mapped with the viewer's title.
    const auto [status, id] = run_shell(display_.env() + "timeout 30 xdotool search --sync --name '^shaderbed view'");
    if (status == 0) window_ = id.substr(0, id.find('\n'));
  }

  bool has_window() const { return !window_.empty(); }
  // The viewer makes its window again when it changes how it presents (B between vulkan
  // and gl): waits until the one window with its title is a new one, and sends keys there.
  bool follow_new_window(double timeout_s = 20) {
    const std::string old = window_;
    return wait_until([&] {
      const auto [status, ids] = run_shell(display_.env() + "xdotool search --name '^shaderbed view'");
      if (status != 0 || ids.find('\n') + 1 != ids.size()) return false;   // none yet, or the old one still there
      const std::string id = ids.substr(0, ids.find('\n'));
      if (id == old) return false;
      window_ = id;
      return true;
    }, timeout_s);
  }
  // xdotool key names: "c", "M", "greater", "plus", "Tab" ...
  void keys(const std::string& names) { run_shell(display_.env() + "xdotool key --window " + window_ + " " + names); }
  // The pointer to window position (x, y); a right click there.
  void pointer(int x, int y) {
    run_shell(display_.env() + "xdotool mousemove --window " + window_ + " " + std::to_string(x) + " " + std::to_string(y));
  }
  void click(int x, int y) {
    pointer(x, y);
    run_shell(display_.env() + "xdotool click --window " + window_ + " 3");
  }
  std::string title() const {
    auto [status, name] = run_shell(display_.env() + "xdotool getwindowname " + window_);
    while (!name.empty() && name.back() == '\n') name.pop_back();
    return name;
  }
  std::string output() const { return read_text(out_); }
  std::string errors() const { return read_text(err_); }
  bool wait_for_output(const std::string& text, double timeout_s = 20) const {
    return wait_until([&] { return output().find(text) != std::string::npos; }, timeout_s);
  }
  bool wait_for_errors(const std::string& text, double timeout_s = 20) const {
    return wait_until([&] { return errors().find(text) != std::string::npos; }, timeout_s);
  }
  // Presses c (after `first`, in the same xdotool call) and waits for the screenshot it
  // writes; returns its stem (".png", ".exr" follow).
  std::string screenshot(const std::string& first = "") {
    const size_t before = count("screenshot: ");
    keys(first.empty() ? "c" : "--delay 0 " + first + " c");
    if (!wait_until([&] { return count("screenshot: ") > before; }, 20)) return "";
    const std::string text = output();
    size_t at = std::string::npos;
    for (size_t i = 0, found = 0; (found = text.find("screenshot: ", i)) != std::string::npos; i = found + 1) at = found;
    const std::string png = text.substr(at + 12, text.find(' ', at + 12) - at - 12);
    return png.substr(0, png.size() - 4);
  }
  // q, and the exit status.
  std::optional<int> quit() {
    keys("q");
    return process_.wait(20);
  }

 private:
  size_t count(const std::string& what) const {
    const std::string text = output();
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  }

  const VirtualDisplay& display_;
  std::string out_, err_;
  Process process_;
  std::string window_;
};

// ---- images -------------------------------------------------------------------------

inline ImagePixels read_exr(const std::string& path) {
  auto image = read_image_file(path);
  return image ? *image : ImagePixels{};
}

// Pixels whose alpha is not 0 (drawn).
inline size_t drawn_pixels(const ImagePixels& image) {
  size_t n = 0;
  for (size_t i = 3; i < image.values.size(); i += size_t(image.channels)) n += image.values[i] != 0;
  return n;
}

// Pixels where any channel differs.
inline size_t differing_pixels(const ImagePixels& a, const ImagePixels& b) {
  if (a.values.size() != b.values.size()) return std::max(a.values.size(), b.values.size());
  size_t n = 0;
  for (size_t p = 0; p < a.values.size(); p += size_t(a.channels))
    for (int c = 0; c < a.channels; ++c)
      if (a.values[p + size_t(c)] != b.values[p + size_t(c)] &&
          !(std::isnan(a.values[p + size_t(c)]) && std::isnan(b.values[p + size_t(c)]))) {
        ++n;
        break;
      }
  return n;
}

}  // namespace shaderbed::test
