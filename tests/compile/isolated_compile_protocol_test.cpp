// The wire between a command and its compile child (compile/IsolatedCompileProtocol.h):
// a request and both kinds of answer come back whole, anything cut short or garbled
// decodes to nothing (never to a wrong module), and a frame read waits no longer than its
// deadline.
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>

#include <gtest/gtest.h>

#include "compile/IsolatedCompileProtocol.h"
#include "compile/ModuleCodec.h"

namespace {

using namespace shaderbed;

TEST(IsolatedCompileProtocol, RequestsAndAnswersComeBackWhole) {
  const StageRequest request{.language = Language::hlsl,
                             .target = Target::opengl,
                             .source = {.stage = Stage::fragment,
                                        .path = "/tmp/p.hlsl",
                                        .text = "float4 main() : COLOR0 { return 1; }\n",
                                        .entry_point = "PS",
                                        .defines = {{"A", "1"}, {"B", ""}},
                                        .include_dirs = {"/inc"}}};
  const std::optional<StageRequest> back = decode_stage_request(encode_stage_request(request));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->language, Language::hlsl);
  EXPECT_EQ(back->target, Target::opengl);
  EXPECT_EQ(back->source.stage, Stage::fragment);
  EXPECT_EQ(back->source.path, request.source.path);
  EXPECT_EQ(back->source.text, request.source.text);
  EXPECT_EQ(back->source.entry_point, "PS");
  EXPECT_EQ(back->source.defines, request.source.defines);
  EXPECT_EQ(back->source.include_dirs, request.source.include_dirs);

  // A real module, compiled here, survives the trip byte for byte.
  auto module = compile_stage(Language::glsl,
                              {.stage = Stage::fragment, .path = "f.frag",
                               .text = "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(1); }\n"},
                              Target::vulkan);
  ASSERT_TRUE(module) << module.error().to_string();
  const auto ok = decode_stage_answer(encode_stage_answer(*module));
  ASSERT_TRUE(ok && *ok);
  EXPECT_EQ(encode_module(**ok), encode_module(*module));

  const Error error{.message = "undeclared identifier", .file = "f.frag", .line = 3, .column = 7,
                    .stage = ErrorStage::compile, .backend = "", .skipped = true};
  const auto refused = decode_stage_answer(encode_stage_answer(std::unexpected(error)));
  ASSERT_TRUE(refused && !*refused);
  EXPECT_EQ((*refused).error().to_string(), error.to_string());
  EXPECT_TRUE((*refused).error().skipped);

  const CacheSettings caches{.root = "/c", .driver = false, .compile = true};
  const auto settings = decode_cache_settings(encode_cache_settings(caches));
  ASSERT_TRUE(settings);
  EXPECT_EQ(settings->root, "/c");
  EXPECT_FALSE(settings->driver);
  EXPECT_TRUE(settings->compile);
}

TEST(IsolatedCompileProtocol, CutOrGarbledBytesDecodeToNothing) {
  const std::string request = encode_stage_request({.source = {.path = "a", .text = "b"}});
  for (size_t n = 0; n < request.size(); ++n) EXPECT_FALSE(decode_stage_request(request.substr(0, n))) << n;
  EXPECT_FALSE(decode_stage_request(request + "x"));
  std::string bad_language = request;
  bad_language[0] = 9;   // no such language
  EXPECT_FALSE(decode_stage_request(bad_language));
  const std::string answer = encode_stage_answer(std::unexpected(Error{.message = "m", .stage = ErrorStage::compile}));
  for (size_t n = 0; n < answer.size(); ++n) EXPECT_FALSE(decode_stage_answer(answer.substr(0, n))) << n;
}

TEST(IsolatedCompileProtocol, FramesArriveWholeAndAReadWaitsOnlyUntilItsDeadline) {
  int pair[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
  ASSERT_TRUE(send_frame(pair[0], "hello"));
  ASSERT_TRUE(send_frame(pair[0], ""));
  EXPECT_EQ(receive_frame(pair[1]).payload, "hello");
  EXPECT_EQ(receive_frame(pair[1]).payload, "");

  // Nothing sent: the read gives up at its deadline, saying so (a read that waited on
  // would hang the test, which ctest's timeout reports).
  const ReceivedFrame nothing = receive_frame(pair[1], std::chrono::steady_clock::now() + std::chrono::milliseconds(100));
  EXPECT_FALSE(nothing.payload);
  EXPECT_TRUE(nothing.timed_out);

  ::close(pair[0]);
  const ReceivedFrame closed = receive_frame(pair[1]);
  EXPECT_FALSE(closed.payload);
  EXPECT_FALSE(closed.timed_out);
  EXPECT_FALSE(send_frame(pair[1], "nobody there"));   // no SIGPIPE: this test would end here
  ::close(pair[1]);
}

}  // namespace
