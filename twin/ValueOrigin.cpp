#include "twin/ValueOrigin.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "twin/InstructionText.h"

namespace twin {
namespace {

// Records every value of the traced lane and stops at the first non-finite one.
class NonFiniteSearch final : public Observer {
 public:
  explicit NonFiniteSearch(const Module& m) : m_(m) {}
  void value(uint32_t index, std::span<const double> values) override {
    const Instruction& in = m_.instructions[index];
    seen_[in.result].assign(values.begin(), values.end());
    if (found_) return;
    if (!float_typed(m_, in.result_type)) return;   // what can hold a NaN
    for (double v : values)
      if (!std::isfinite(v)) {
        found_ = index;
        return;
      }
  }
  std::optional<uint32_t> found() const { return found_; }
  const std::vector<double>* values_of(uint32_t id) const {
    if (m_.is_constant[id]) return &m_.constants[id];
    auto it = seen_.find(id);
    return it == seen_.end() ? nullptr : &it->second;
  }

 private:
  const Module& m_;
  std::map<uint32_t, std::vector<double>> seen_;
  std::optional<uint32_t> found_;
};

}  // namespace

std::string ValueOrigin::describe() const {
  std::string s = file.empty() ? std::string("(no source line)") : file + ":" + std::to_string(line);
  if (!source_text.empty()) s += " `" + source_text + "`";
  s += ": " + operation + "(";
  for (size_t i = 0; i < operands.size(); ++i)
    s += (i ? ", " : "") + operands[i].first + " = " + values_text(operands[i].second);
  return s + ") = " + values_text(values) + (result.empty() || result[0] == '%' ? "" : " (" + result + ")");
}

std::string source_line_text(const Module& module, const std::string& file, int line) {
  if (line <= 0) return "";
  // The module's own copy of the text (OpSource), else the file it names.
  auto it = module.sources.find(file);
  std::ifstream from_disk;
  std::istringstream from_module;
  std::istream* source = &from_module;
  if (it != module.sources.end()) {
    from_module.str(it->second);
  } else {
    from_disk.open(file);
    if (!from_disk) return "";
    source = &from_disk;
  }
  std::istream& in = *source;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n)
    if (n == line) {
      const size_t first = text.find_first_not_of(" \t");
      const size_t last = text.find_last_not_of(" \t\r");
      return first == std::string::npos ? "" : text.substr(first, last - first + 1);
    }
  return "";
}

TwinResult<std::optional<ValueOrigin>> first_nonfinite(const DrawInput& input, int x, int y) {
  const Module& m = *input.program.fragment;
  NonFiniteSearch search(m);
  if (auto ok = trace_pixel(input, x, y, search); !ok) return std::unexpected(ok.error());
  if (!search.found()) return std::optional<ValueOrigin>{};
  const Instruction& in = m.instructions[*search.found()];
  ValueOrigin origin;
  const SourceLine& line = m.lines[in.line];
  origin.file = line.file;
  origin.line = line.line;
  origin.source_text = source_line_text(m, line.file, line.line);
  const auto operands = value_operands(m, in);
  origin.operation = operation_name(m, in);
  const ValueNames name(m);
  origin.result = name(in.result);
  origin.values = *search.values_of(in.result);
  for (uint32_t id : operands)
    if (id < m.bound)
      if (const std::vector<double>* v = search.values_of(id)) origin.operands.push_back({name(id), *v});
  return std::optional<ValueOrigin>(std::move(origin));
}

std::vector<SourceLine> relaxed_lines(const Module& module) {
  std::vector<SourceLine> lines;
  for (const Instruction& in : module.instructions) {
    if (!in.result || !module.decorations[in.result].relaxed || in.line == 0) continue;
    const SourceLine& l = module.lines[in.line];
    if (std::none_of(lines.begin(), lines.end(), [&](const SourceLine& s) { return s.file == l.file && s.line == l.line; }))
      lines.push_back(l);
  }
  return lines;
}

}  // namespace twin
