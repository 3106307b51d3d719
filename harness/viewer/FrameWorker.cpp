#include "viewer/FrameWorker.h"

namespace shaderbed::viewer {

FrameWorker::FrameWorker(std::string probe_binary, std::function<void()> on_frame)
    : probe_binary_(std::move(probe_binary)), on_frame_(std::move(on_frame)), thread_([this] { loop(); }) {}

FrameWorker::~FrameWorker() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void FrameWorker::submit(FrameRequest request) {
  {
    const std::lock_guard lock(mutex_);
    if (pending_ && pending_->sources_changed) request.sources_changed = true;
    pending_ = std::move(request);
  }
  wake_.notify_all();
}

std::optional<Frame> FrameWorker::take() {
  const std::lock_guard lock(mutex_);
  return std::exchange(finished_, std::nullopt);
}

void FrameWorker::loop() {
  // Made here, so the backends start (and their contexts are current) on this thread.
  CellRenderer renderer(probe_binary_);
  for (;;) {
    FrameRequest request;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || pending_; });
      if (stopping_) return;
      request = std::move(*pending_);
      pending_.reset();
    }
    Frame frame = renderer.draw(request);
    {
      const std::lock_guard lock(mutex_);
      finished_ = std::move(frame);
    }
    if (on_frame_) on_frame_();
  }
}

}  // namespace shaderbed::viewer
