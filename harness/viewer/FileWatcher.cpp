#include "viewer/FileWatcher.h"

#include <sys/stat.h>

#include <algorithm>


namespace shaderbed::viewer {

FileWatcher::Stamp FileWatcher::stamp(const std::string& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return {};
  return {true, (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec, (long long)st.st_size, st.st_ino};
}

void FileWatcher::watch(const std::vector<std::string>& files) {
  files_ = files;
  stamps_.clear();
  for (const std::string& f : files_) stamps_.push_back(stamp(f));
}

std::vector<std::string> FileWatcher::changed() {
  std::vector<std::string> out;
  for (size_t i = 0; i < files_.size(); ++i) {
    const Stamp now = stamp(files_[i]);
    if (now == stamps_[i]) continue;
    stamps_[i] = now;
    out.push_back(files_[i]);
  }
  return out;
}

std::vector<std::string> case_files(const Case& c) {
  std::vector<std::string> files{c.path};
  for (const Variant& v : c.variants)
    for (const auto& [language, shaders] : v.shaders)
      for (const std::string* f : {&shaders.vertex, &shaders.fragment})
        if (!f->empty() && std::ranges::find(files, *f) == files.end()) files.push_back(*f);
  return files;
}

}  // namespace shaderbed::viewer
