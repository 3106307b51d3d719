#pragma once
// Nothing a shader does takes the viewer down: before the viewer compiles a program in
// its own process, a child process (`shaderbed __view-compile`, kept warm across reloads
// like `run`'s workers) compiles it first. glslang 12 still dereferences null on some
// valid-looking HLSL and Cg (tests/run/isolation_test.cpp); when it does, the child dies, the viewer says
// "compiler crashed" and keeps the last good image, and the next compile starts a new
// child. When the child succeeds, its SPIR-V is in the disk compile cache, so the
// viewer's own compile does not start glslang at all (with the cache off it compiles text
// the child has just compiled without crashing). Not covered: a crash in the driver while
// drawing (the viewer draws in its own process).
#include <sys/types.h>

#include <string>

#include "compile/ShaderModule.h"
#include "core/Error.h"
#include "scene/CaseFile.h"

namespace shaderbed::viewer {

class CompileProbe {
 public:
  // `binary`: the shaderbed executable; "" = no child (every compile is in-process).
  explicit CompileProbe(std::string binary, double timeout_s = 30);
  ~CompileProbe();
  CompileProbe(const CompileProbe&) = delete;
  CompileProbe& operator=(const CompileProbe&) = delete;

  // Compiles `variant` of the case file in `language` in the child, with this process's
  // cache settings: the compile error (with its file and line), or a crash ("compiler
  // crashed: signal 11 (SIGSEGV) while compiling ...") or a timeout.
  Result<void> compile(const Case& c, const Variant& variant, Language language);

  // Starts the child now if it is not running, without waiting for it (its start-up then
  // overlaps whatever the caller does next).
  void prepare();

 private:
  Result<void> start();
  // Kills (if needed) and reaps the child; how it ended ("signal 11 (SIGSEGV)", "exit 1").
  std::string stop();

  std::string binary_;
  double timeout_s_;
  pid_t pid_ = -1;
  int to_child_ = -1, from_child_ = -1;
  std::string buffer_;
};

// The child's side: reads "case file<TAB>variant<TAB>language" lines, compiles each, and
// answers each with one JSON line ({} or the error's fields). Returns at end of input.
int serve_compile_probe();

}  // namespace shaderbed::viewer
