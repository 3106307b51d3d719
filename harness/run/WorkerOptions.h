#pragma once
// What an isolated worker is told before its first group (run/IsolatedRun.h): the suite
// selection it plans the same groups from, the settings its cells are drawn with, and the
// process-wide settings the command line chose. One encoder and one decoder, as one line
// of JSON; decoding changes nothing in the process (the worker applies the result).
#include <string>
#include <string_view>

#include "backends/Backend.h"
#include "core/CacheSettings.h"
#include "core/Error.h"
#include "run/RunOptions.h"

namespace shaderbed {

struct ProcessSettings {
  CacheSettings caches;
  std::string vulkan_device;   // --vulkan-device ("" = lavapipe)
  GlPlatformChoice gl_platform;   // --gl-platform, --gl-device
  bool operator==(const ProcessSettings& o) const {
    return caches.root == o.caches.root && caches.driver == o.caches.driver && caches.compile == o.caches.compile &&
           vulkan_device == o.vulkan_device && gl_platform == o.gl_platform;
  }
};

struct WorkerOptions {
  SuiteSelection select;
  CellSettings cell;
  ProcessSettings process;
  bool operator==(const WorkerOptions&) const = default;
};

// The run's options as its workers need them, with this process's settings.
WorkerOptions worker_options(const RunOptions& options);

std::string encode_worker_options(const WorkerOptions& options);
Result<WorkerOptions> decode_worker_options(std::string_view line);

// Makes this process's settings the ones the options carry (the worker, once, at start).
void apply_process_settings(const ProcessSettings& settings);

}  // namespace shaderbed
