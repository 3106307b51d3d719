#include "compile/IsolatedCompileProtocol.h"

#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>

#include "compile/ModuleCodec.h"

namespace shaderbed {
namespace {

// An enum read back only when it is one of the enum's values.
template <typename E>
bool read_enum(ByteReader& in, E& value, E last) {
  uint32_t v = 0;
  if (!in.u32(v) || v > uint32_t(last)) return false;
  value = E(v);
  return true;
}

}  // namespace

std::string encode_cache_settings(const CacheSettings& s) {
  ByteWriter out;
  out.str(s.root);
  out.boolean(s.driver);
  out.boolean(s.compile);
  return out.take();
}

std::optional<CacheSettings> decode_cache_settings(std::string_view bytes) {
  ByteReader in(bytes);
  CacheSettings s;
  if (!in.str(s.root) || !in.boolean(s.driver) || !in.boolean(s.compile) || !in.at_end()) return std::nullopt;
  return s;
}

std::string encode_stage_request(const StageRequest& r) {
  ByteWriter out;
  out.u32(uint32_t(r.language));
  out.u32(uint32_t(r.target));
  out.u32(uint32_t(r.source.stage));
  out.str(r.source.path);
  out.str(r.source.text);
  out.str(r.source.entry_point);
  out.u64(r.source.defines.size());
  for (const auto& [name, value] : r.source.defines) out.str(name), out.str(value);
  out.u64(r.source.include_dirs.size());
  for (const std::string& dir : r.source.include_dirs) out.str(dir);
  return out.take();
}

std::optional<StageRequest> decode_stage_request(std::string_view bytes) {
  ByteReader in(bytes);
  StageRequest r;
  ShaderSource& s = r.source;
  if (!read_enum(in, r.language, Language::cg) || !read_enum(in, r.target, Target::opengl) ||
      !read_enum(in, s.stage, Stage::fragment) || !in.str(s.path) || !in.str(s.text) || !in.str(s.entry_point))
    return std::nullopt;
  uint64_t n = 0;
  if (!in.u64(n) || n > in.remaining()) return std::nullopt;
  s.defines.resize(n);
  for (Define& d : s.defines)
    if (!in.str(d.first) || !in.str(d.second)) return std::nullopt;
  if (!in.u64(n) || n > in.remaining()) return std::nullopt;
  s.include_dirs.resize(n);
  for (std::string& dir : s.include_dirs)
    if (!in.str(dir)) return std::nullopt;
  if (!in.at_end()) return std::nullopt;
  return r;
}

std::string encode_stage_answer(const Result<ShaderModule>& answer) {
  ByteWriter out;
  out.boolean(answer.has_value());
  if (answer) {
    write_module(out, *answer);
    return out.take();
  }
  const Error& e = answer.error();
  out.str(e.message);
  out.str(e.file);
  out.u32(uint32_t(e.line));
  out.u32(uint32_t(e.column));
  out.u32(uint32_t(e.stage));
  out.str(e.backend);
  out.boolean(e.skipped);
  return out.take();
}

std::optional<Result<ShaderModule>> decode_stage_answer(std::string_view bytes) {
  ByteReader in(bytes);
  bool ok = false;
  if (!in.boolean(ok)) return std::nullopt;
  if (ok) {
    ShaderModule module;
    if (!read_module(in, module) || !in.at_end()) return std::nullopt;
    return Result<ShaderModule>(std::move(module));
  }
  Error e;
  uint32_t line = 0, column = 0;
  if (!in.str(e.message) || !in.str(e.file) || !in.u32(line) || !in.u32(column) ||
      !read_enum(in, e.stage, ErrorStage::worker) || !in.str(e.backend) || !in.boolean(e.skipped) || !in.at_end())
    return std::nullopt;
  e.line = int(line);
  e.column = int(column);
  return Result<ShaderModule>(std::unexpected(std::move(e)));
}

bool send_frame(int socket, const std::string& payload) {
  ByteWriter header;
  header.u64(payload.size());
  const std::string frame = header.bytes() + payload;
  size_t done = 0;
  while (done < frame.size()) {
    const ssize_t n = ::send(socket, frame.data() + done, frame.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += size_t(n);
  }
  return true;
}

ReceivedFrame receive_frame(int socket, std::optional<std::chrono::steady_clock::time_point> deadline) {
  ReceivedFrame out;
  const auto read_exactly = [&](char* p, size_t n) {
    while (n > 0) {
      int wait_ms = -1;
      if (deadline) {
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(*deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return !(out.timed_out = true);
        wait_ms = int(std::min<long long>(left.count(), 1 << 30));
      }
      pollfd ready{socket, POLLIN, 0};
      const int polled = ::poll(&ready, 1, wait_ms);
      if (polled < 0 && errno != EINTR) return false;
      if (polled <= 0) continue;
      const ssize_t got = ::recv(socket, p, n, 0);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) return false;
      p += got;
      n -= size_t(got);
    }
    return true;
  };
  uint64_t size = 0;
  if (!read_exactly(reinterpret_cast<char*>(&size), sizeof size)) return out;
  if (size > (uint64_t(1) << 32)) return out;   // no request or module comes near 4 GiB
  std::string payload(size, '\0');
  if (!read_exactly(payload.data(), size)) return out;
  out.payload = std::move(payload);
  return out;
}

}  // namespace shaderbed
