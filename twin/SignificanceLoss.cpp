#include "twin/SignificanceLoss.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "twin/InstructionText.h"

namespace twin {
namespace {

// One float-typed result of the traced lane, with its operands' values when it computed it.
struct Event {
  uint32_t index = 0, occurrence = 0;
  std::vector<double> values;
  std::vector<std::pair<uint32_t, std::optional<std::vector<double>>>> operands;   // id, values if known
};

class Recorder final : public Observer {
 public:
  explicit Recorder(const Module& m) : m_(m) {}
  void value(uint32_t index, std::span<const double> values) override {
    const Instruction& in = m_.instructions[index];
    if (float_typed(m_, in.result_type)) {
      Event e{.index = index, .occurrence = occurrences_[index]++, .values = {values.begin(), values.end()}, .operands = {}};
      for (uint32_t id : value_operands(m_, in)) {
        if (id == 0 || id >= m_.bound) continue;
        std::optional<std::vector<double>> v;
        if (m_.is_constant[id]) v = m_.constants[id];
        else if (auto it = seen_.find(id); it != seen_.end()) v = it->second;
        e.operands.emplace_back(id, std::move(v));
      }
      events.push_back(std::move(e));
    }
    seen_[in.result].assign(values.begin(), values.end());
  }
  std::vector<Event> events;

 private:
  const Module& m_;
  std::unordered_map<uint32_t, std::vector<double>> seen_;
  std::unordered_map<uint32_t, uint32_t> occurrences_;
};

double max_relative(const std::vector<double>& f, const std::vector<double>& d, double tiny) {
  double worst = 0;
  for (size_t i = 0; i < std::min(f.size(), d.size()); ++i) worst = std::max(worst, relative_error(f[i], d[i], tiny));
  return worst;
}

std::string both_text(const std::vector<double>& f, const std::vector<double>& d) {
  if (d.empty()) return values_text(f);
  return values_text(f) + " [double " + values_text(d) + "]";
}

std::string error_text(double e) { return std::isinf(e) ? "infinite" : number_text(float(e)); }

}  // namespace

double relative_error(double f, double d, double tiny) {
  if (std::isnan(f) && std::isnan(d)) return 0;
  if (!std::isfinite(f) || !std::isfinite(d)) return f == d ? 0 : std::numeric_limits<double>::infinity();
  return std::abs(f - d) / std::max(std::abs(d), tiny);
}

std::string SignificanceLoss::describe() const {
  std::string s = origin.file.empty() ? std::string("(no source line)") : origin.file + ":" + std::to_string(origin.line);
  if (!origin.source_text.empty()) s += " `" + origin.source_text + "`";
  s += ": " + origin.operation + "(";
  for (size_t i = 0; i < origin.operands.size(); ++i)
    s += (i ? ", " : "") + origin.operands[i].first + " = " +
         both_text(origin.operands[i].second, i < exact_operands.size() ? exact_operands[i] : std::vector<double>{});
  s += ") = " + both_text(origin.values, exact_values);
  if (!origin.result.empty() && origin.result[0] != '%') s += " (" + origin.result + ")";
  return s + ": relative error " + error_text(relative_error) + ", operands " + error_text(operand_relative_error);
}

TwinResult<std::optional<SignificanceLoss>> significance_loss(const DrawInput& input, int x, int y,
                                                              const SignificanceOptions& options) {
  const Module& m = *input.program.fragment;

  // The float trace reads the uniform blocks' floats, as the device does.
  BoundResources device_resources = input.resources;
  for (auto& [binding, buffer] : device_resources.buffers) buffer.words = {};
  device_resources.push_constants.words = {};
  DrawInput exact = input;
  exact.precision = Precision::exact;
  exact.threads = 1;
  // DrawInput holds its resources by reference: a copy that points at the device's.
  const DrawInput single{.program = input.program, .resources = device_resources, .streams = input.streams,
                         .vertex_count = input.vertex_count, .indices = input.indices, .width = input.width,
                         .height = input.height, .precision = Precision::single, .cull = input.cull, .threads = 1,
                         .work_limit = input.work_limit};
  Recorder in_float(m), in_double(m);
  if (auto ok = trace_pixel(single, x, y, in_float); !ok) return std::unexpected(ok.error());
  if (auto ok = trace_pixel(exact, x, y, in_double); !ok) return std::unexpected(ok.error());

  std::map<std::pair<uint32_t, uint32_t>, const Event*> exact_events;
  for (const Event& e : in_double.events) exact_events[{e.index, e.occurrence}] = &e;

  for (const Event& f : in_float.events) {
    auto match = exact_events.find({f.index, f.occurrence});
    if (match == exact_events.end()) continue;   // the double trace took another path
    const Event& d = *match->second;
    double operand_error = 0;
    bool known = false;
    for (size_t i = 0; i < f.operands.size() && i < d.operands.size(); ++i) {
      if (!f.operands[i].second || !d.operands[i].second) continue;
      known = true;
      operand_error = std::max(operand_error, max_relative(*f.operands[i].second, *d.operands[i].second, options.tiny));
    }
    // A load, an input or a built-in read: no operand to compare with.
    if (!known) continue;
    const double error = max_relative(f.values, d.values, options.tiny);
    if (!(error > options.floor && error > options.factor * operand_error)) continue;

    const Instruction& in = m.instructions[f.index];
    const ValueNames name(m);
    SignificanceLoss loss;
    const SourceLine& line = m.lines[in.line];
    loss.origin.file = line.file;
    loss.origin.line = line.line;
    loss.origin.source_text = source_line_text(m, line.file, line.line);
    loss.origin.operation = operation_name(m, in);
    loss.origin.result = name(in.result);
    loss.origin.values = f.values;
    loss.exact_values = d.values;
    for (size_t i = 0; i < f.operands.size(); ++i) {
      if (!f.operands[i].second) continue;
      loss.origin.operands.push_back({name(f.operands[i].first), *f.operands[i].second});
      loss.exact_operands.push_back(i < d.operands.size() && d.operands[i].second ? *d.operands[i].second
                                                                                  : std::vector<double>{});
    }
    loss.relative_error = error;
    loss.operand_relative_error = operand_error;
    return std::optional<SignificanceLoss>(std::move(loss));
  }
  return std::optional<SignificanceLoss>{};
}

}  // namespace twin
