#pragma once
// Compiling a user's shader in a child process, for the commands that otherwise compile in
// their own (init, port, stats, sweep, hard): glslang 12 still crashes on some inputs
// (10^5 nested parentheses, an unnamed entry parameter, frexp into a struct member), and
// such a crash must cost one shader an error, not the command its life and its output.
//
// Once a command calls isolate_compiles(), every stage compile_stage_cached() would run
// (a miss in the process's memory and disk caches, StageCache.h) goes to one child,
// `shaderbed __compile-stages`, started on first use and kept for the rest of the command,
// which answers with the SPIR-V and reflection (or the compile's error); the command then
// draws with that module in its own process. A child that crashes or takes longer than the
// timeout is the error "glslang crashed (signal 11, SIGSEGV) compiling foo.hlsl" /
// "... took longer than 30 s", with the file and stage; the next compile starts a new
// child. `run` needs none of this: its workers are child processes already.
#include <string>

#include "compile/Compiler.h"
#include "core/Error.h"

namespace shaderbed {

// From now on, stage compiles in this process go to a child started from this executable
// (core/ThisExecutable.h; when it cannot be found, compiles stay in process), each
// answered within `timeout_s`. Call before any compile.
void isolate_compiles(double timeout_s = 30);
bool compiles_isolated();

// Whether `e` is a compile that did not finish (the child crashed, hung or could not be
// started), as opposed to a shader the compiler refused: a command may treat the one as
// bad input even where it reports the other and goes on.
bool compiler_did_not_finish(const Error& e);

// One stage in the child (isolate_compiles() must have been called). Thread-safe: the
// requests of several threads take turns.
Result<ShaderModule> compile_stage_isolated(Language language, const ShaderSource& source, Target target);

}  // namespace shaderbed
