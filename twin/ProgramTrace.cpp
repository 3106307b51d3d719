#include "twin/ProgramTrace.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace twin {
namespace {

// One pixel's values in the order computed, each keyed by (instruction, occurrence).
class PixelRecorder final : public Observer {
 public:
  struct Event {
    uint32_t instruction, occurrence;
    std::vector<double> values;
  };
  void value(uint32_t instruction, std::span<const double> values) override {
    events.push_back({instruction, seen_[instruction]++, {values.begin(), values.end()}});
  }
  std::vector<Event> events;

 private:
  std::map<uint32_t, uint32_t> seen_;
};

// Each point's recorded values gathered into fingerprints, keyed by (instruction, occurrence).
ProgramTrace gather(std::shared_ptr<const Module> module, std::vector<PixelAt> pixels,
                    std::vector<PixelRecorder>& recorders) {
  ProgramTrace trace{std::move(module), std::move(pixels), {}};
  std::map<std::pair<uint32_t, uint32_t>, size_t> index;
  const size_t n = trace.pixels.size();
  for (size_t p = 0; p < n; ++p)
    for (PixelRecorder::Event& e : recorders[p].events) {
      auto [it, added] = index.try_emplace({e.instruction, e.occurrence}, trace.values.size());
      if (added) {
        const auto slots = uint32_t(e.values.size());
        trace.values.push_back({e.instruction, e.occurrence, slots,
                                std::vector<double>(n * slots, std::numeric_limits<double>::quiet_NaN()),
                                std::vector<uint8_t>(n, 0)});
      }
      ValueFingerprint& v = trace.values[it->second];
      if (e.values.size() != v.slots) continue;   // cannot happen for one instruction; kept from a bad write
      std::copy(e.values.begin(), e.values.end(), v.values.begin() + std::ptrdiff_t(p * v.slots));
      v.present[p] = 1;
    }
  return trace;
}

}  // namespace

TwinResult<ProgramTrace> trace_program(const DrawInput& input, std::span<const PixelAt> pixels) {
  DrawInput exact = input;
  exact.precision = Precision::exact;
  std::vector<PixelRecorder> recorders(pixels.size());
  if (auto ok = trace_pixels(exact, pixels, [&](size_t i) { return &recorders[i]; }); !ok)
    return std::unexpected(ok.error());
  return gather(input.program.fragment, {pixels.begin(), pixels.end()}, recorders);
}

TwinResult<ProgramTrace> trace_vertex_program(const DrawInput& input, size_t count) {
  DrawInput exact = input;
  exact.precision = Precision::exact;
  std::vector<uint32_t> vertices;
  const size_t step = std::max<size_t>(1, input.vertex_count / std::max<size_t>(1, count));
  for (size_t v = step / 2; v < input.vertex_count && vertices.size() < count; v += step) vertices.push_back(uint32_t(v));
  std::vector<PixelRecorder> recorders(vertices.size());
  if (auto ok = trace_vertices(exact, vertices, [&](size_t i) { return &recorders[i]; }); !ok)
    return std::unexpected(ok.error());
  std::vector<PixelAt> points;
  for (uint32_t v : vertices) points.push_back({int(v), 0});
  return gather(input.program.vertex, std::move(points), recorders);
}

}  // namespace twin
