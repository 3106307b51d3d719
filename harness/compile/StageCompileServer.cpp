#include "compile/StageCompileServer.h"

#include <unistd.h>

#include <chrono>
#include <thread>

#include <fmt/format.h>

#include "compile/IsolatedCompileProtocol.h"
#include "compile/StageCache.h"

namespace shaderbed {

int serve_stage_compiles(int fd) {
  // A command that dies while glslang hangs here would never close the socket: the child
  // ends itself once it has been handed to another parent.
  std::thread([parent = ::getppid()] {
    while (::getppid() == parent) std::this_thread::sleep_for(std::chrono::milliseconds(500));
    _exit(0);
  }).detach();
  const ReceivedFrame settings = receive_frame(fd);
  if (!settings.payload) return 0;
  const std::optional<CacheSettings> caches = decode_cache_settings(*settings.payload);
  if (!caches) {
    fmt::print(stderr, "shaderbed __compile-stages: garbled cache settings\n");
    return 2;
  }
  set_cache_settings(*caches);
  for (ReceivedFrame frame; (frame = receive_frame(fd)).payload;) {
    const std::optional<StageRequest> request = decode_stage_request(*frame.payload);
    if (!request) {
      fmt::print(stderr, "shaderbed __compile-stages: garbled request\n");
      return 2;
    }
    if (!send_frame(fd, encode_stage_answer(compile_stage_cached(request->language, request->source, request->target))))
      return 0;   // the command is gone
  }
  return 0;
}

}  // namespace shaderbed
