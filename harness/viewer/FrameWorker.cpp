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

void FrameWorker::inspect(InspectRequest request) {
  {
    const std::lock_guard lock(mutex_);
    pending_inspection_ = std::move(request);
  }
  wake_.notify_all();
}

std::optional<Inspection> FrameWorker::take_inspection() {
  const std::lock_guard lock(mutex_);
  return std::exchange(inspected_, std::nullopt);
}

void FrameWorker::loop() {
  // Made here, so the backends start (and their contexts are current) on this thread.
  CellRenderer renderer(probe_binary_);
  for (;;) {
    std::optional<FrameRequest> request;
    std::optional<InspectRequest> inspection;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || pending_ || pending_inspection_; });
      if (stopping_) return;
      if (pending_) request = std::exchange(pending_, std::nullopt);
      else inspection = std::exchange(pending_inspection_, std::nullopt);
    }
    if (request) {
      Frame frame = renderer.draw(*request);
      const std::lock_guard lock(mutex_);
      finished_ = std::move(frame);
    } else {
      Inspection inspected = renderer.inspect(*inspection);
      const std::lock_guard lock(mutex_);
      inspected_ = std::move(inspected);
    }
    if (on_frame_) on_frame_();
  }
}

}  // namespace shaderbed::viewer
