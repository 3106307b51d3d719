#pragma once
// The viewer's render thread: it owns the CellRenderer (and so the backends: the OSMesa
// context is current on this thread only, apart from the window's GLX context on the main
// thread) and draws the latest request. A request that arrives while another waits
// replaces it, so a fast mouse drag costs one frame per draw, not one per motion event.
// The pixel inspector's requests are answered here too (the twins draw through the same
// renderer), after any frame waiting.
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

#include "viewer/CellRenderer.h"

namespace shaderbed::viewer {

class FrameWorker {
 public:
  // `on_frame` runs on the render thread after each frame (the viewer wakes its window).
  FrameWorker(std::string probe_binary, std::function<void()> on_frame);
  ~FrameWorker();
  FrameWorker(const FrameWorker&) = delete;
  FrameWorker& operator=(const FrameWorker&) = delete;

  // Draw this next (replacing a request not yet started; sources_changed accumulates).
  void submit(FrameRequest request);
  // The newest finished frame since the last call, if any.
  std::optional<Frame> take();
  // Inspect this pixel next, after the frame waiting, if any (replacing an inspection not
  // yet started: the last click is the one answered).
  void inspect(InspectRequest request);
  // The inspection finished since the last call, if any.
  std::optional<Inspection> take_inspection();

 private:
  void loop();

  std::string probe_binary_;
  std::function<void()> on_frame_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<FrameRequest> pending_;
  std::optional<Frame> finished_;
  std::optional<InspectRequest> pending_inspection_;
  std::optional<Inspection> inspected_;
  bool stopping_ = false;
  std::thread thread_;   // last: started once the rest is ready
};

}  // namespace shaderbed::viewer
