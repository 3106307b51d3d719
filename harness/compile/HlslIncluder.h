#pragma once
// `#include` for HLSL (and DX9 effects), as fxc resolves it with /I folders: relative to
// the including file, then in the case's `include_dirs` in order (`"file"` and `<file>`
// alike: shaderbed has no system include paths of its own), `#pragma once` honoured. A missing header is an error naming it, at the
// including file's line (glslang reports it there). Every file read is recorded with its
// exact text, so the disk compile cache can re-check it on a hit. The Cg front end
// (CgFrontEnd.cpp) is the same includer with its own per-file pass: prepare().
#include <deque>
#include <set>
#include <string>
#include <vector>

#include <glslang/Public/ShaderLang.h>

#include "compile/Compiler.h"

namespace shaderbed {

class HlslIncluder : public glslang::TShader::Includer {
 public:
  HlslIncluder(std::vector<SourceFile>& read, std::vector<std::string> include_dirs)
      : read_(read), include_dirs_(std::move(include_dirs)) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* result) override { delete result; }

 protected:
  struct Prepared {
    std::string text;          // what the compiler reads
    bool pragma_once = false;
  };
  // A file as read -> what the compiler reads of it; an error fails the #include with
  // its message. HLSL: the text as it is.
  virtual Result<Prepared> prepare(const std::string& text, const std::string& name, const char* includer);
  IncludeResult* failure(std::string message);
  // Where `header` is: the including file's folder first, then each include folder; the
  // first candidate when none has it (the error names it).
  std::string resolve(const char* header, const char* includer) const;
  bool has_include_dirs() const { return !include_dirs_.empty(); }

 private:
  std::vector<SourceFile>& read_;
  std::vector<std::string> include_dirs_;
  std::set<std::string> once_;
  std::deque<std::string> texts_;  // stable storage for the returned contents
};

}  // namespace shaderbed
