#pragma once
// The child's side of compile/IsolatedCompile.h (`shaderbed __compile-stages`): reads the
// cache settings and then stage requests from the socket at `fd`, compiles each as the
// command itself would (compile_stage_cached: memory and disk caches), and answers each
// (compile/IsolatedCompileProtocol.h). Returns 0 when the command closes the socket, 2 on
// a garbled request.
namespace shaderbed {

int serve_stage_compiles(int fd);

}  // namespace shaderbed
