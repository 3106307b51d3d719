#pragma once
// Live reload: the files a view depends on (the case file and its shaders), polled. An
// editor's save changes a file's modification time, size or inode (a save by rename), so
// a stat per file a few times a second sees every save and costs nothing when idle.
#include <string>
#include <vector>

#include <sys/types.h>

#include "scene/CaseFile.h"

namespace shaderbed::viewer {

class FileWatcher {
 public:
  // Watches exactly these files from now on (their current state is the baseline).
  void watch(const std::vector<std::string>& files);

  // The watched files that changed (modified, replaced, removed or created) since the
  // baseline or the last call that returned them.
  std::vector<std::string> changed();

  const std::vector<std::string>& files() const { return files_; }

 private:
  struct Stamp {
    bool exists = false;
    long long mtime_ns = 0;
    long long size = 0;
    ino_t inode = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stamp(const std::string& file);

  std::vector<std::string> files_;
  std::vector<Stamp> stamps_;
};

// The files a case's view reads: the case file and every shader file its variants name.
std::vector<std::string> case_files(const Case& c);

}  // namespace shaderbed::viewer
