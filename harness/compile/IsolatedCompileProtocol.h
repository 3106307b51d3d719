#pragma once
// What a command and its compile child (compile/IsolatedCompile.h) say to each other over
// one socket: length-prefixed frames (a u64 byte count, then the bytes, ModuleCodec's
// binary form). The command sends the cache settings once, then one request per stage;
// the child answers each with the module or the compile's error.
#include <chrono>
#include <optional>
#include <string>

#include "compile/Compiler.h"
#include "core/CacheSettings.h"
#include "core/Error.h"

namespace shaderbed {

struct StageRequest {
  Language language = Language::glsl;
  Target target = Target::vulkan;
  ShaderSource source;
};

std::string encode_cache_settings(const CacheSettings& settings);
std::optional<CacheSettings> decode_cache_settings(std::string_view bytes);

std::string encode_stage_request(const StageRequest& request);
std::optional<StageRequest> decode_stage_request(std::string_view bytes);

std::string encode_stage_answer(const Result<ShaderModule>& answer);
// nullopt: not a whole answer (the error is then the caller's to name).
std::optional<Result<ShaderModule>> decode_stage_answer(std::string_view bytes);

// One frame, whole; false when the other side is gone. Writes never raise SIGPIPE.
bool send_frame(int socket, const std::string& payload);
// Waits for a whole frame until `deadline` (none: for ever). No payload: the other side
// closed or failed, or the deadline passed (timed_out).
struct ReceivedFrame {
  std::optional<std::string> payload;
  bool timed_out = false;
};
ReceivedFrame receive_frame(int socket, std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

}  // namespace shaderbed
