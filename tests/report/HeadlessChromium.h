#pragma once
// Headless Chromium for the HTML report tests: load a page, let its script run, and dump
// the DOM or take a screenshot; with the small text helpers those tests share.
#include <sys/wait.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "ReportTestSupport.h"

namespace shaderbed::test {

// Debian's package; SHADERBED_CHROMIUM overrides (e.g. to check the missing-browser message).
inline std::string chromium_path() {
  const char* env = std::getenv("SHADERBED_CHROMIUM");
  return env && *env ? env : "/usr/bin/chromium";
}

inline std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline size_t count(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
  return n;
}

// The attribute of <body> in a dumped DOM ("" when absent).
inline std::string body_attr(const std::string& dom, const std::string& name) {
  const size_t start = dom.find("<body");
  if (start == std::string::npos) return "";
  const std::string tag = dom.substr(start, dom.find('>', start) - start);
  std::smatch m;
  return std::regex_search(tag, m, std::regex(name + "=\"([^\"]*)\"")) ? m[1].str() : "";
}

// file:// URL of a local path (percent-encoding what a URL cannot hold raw).
inline std::string file_url(const fs::path& path, const std::string& fragment = "") {
  std::string out = "file://";
  for (unsigned char c : fs::absolute(path).string()) {
    if (std::isalnum(c) || std::string("/-_.~").find(char(c)) != std::string::npos) out += char(c);
    else {
      static const char* hex = "0123456789ABCDEF";
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return fragment.empty() ? out : out + "#" + fragment;
}

class Chromium {
 public:
  Chromium() : work_(test::fresh_dir("chromium")) {}
  ~Chromium() { fs::remove_all(work_); }

  // The flags that make headless Chromium quiet, offline and root-safe, with a fresh profile.
  std::string base(const std::string& name) const {
    const fs::path profile = work_ / ("profile-" + name);
    fs::create_directories(profile);
    return "timeout 120 " + quote(chromium_path()) +
           " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking"
           " --disable-component-update --disable-sync --disable-dev-shm-usage --hide-scrollbars"
           " --user-data-dir=" + quote(profile.string());
  }

  // The DOM after the page's script ran (virtual time lets timers and image decoding settle).
  // `window`: --window-size's value, for a layout that a screenshot of the same size repeats.
  std::string dump_dom(const std::string& url, const std::string& name, const std::string& window = "") {
    const fs::path dom = work_ / (name + ".html"), log = work_ / (name + ".log");
    last_command_ = base(name) + " --virtual-time-budget=10000" + (window.empty() ? "" : " --window-size=" + window) +
                    " --dump-dom " + quote(url);
    const int status = std::system((last_command_ + " > " + quote(dom.string()) + " 2> " + quote(log.string())).c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << last_command_ << "\n" << slurp(log);
    return slurp(dom);
  }

  bool screenshot(const std::string& url, const fs::path& png) {
    fs::remove(png);
    const fs::path log = work_ / "screenshot.log";
    last_command_ = base("shot") + " --virtual-time-budget=10000 --window-size=1280,900 --screenshot=" +
                    quote(png.string()) + " " + quote(url);
    const int status = std::system((last_command_ + " > " + quote(log.string()) + " 2>&1").c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << last_command_ << "\n" << slurp(log);
    return fs::exists(png);
  }

  const std::string& last_command() const { return last_command_; }

 private:
  fs::path work_;
  std::string last_command_;
};

}  // namespace shaderbed::test
