#include "twin/PixelListing.h"

#include <algorithm>
#include <map>

#include "twin/InstructionText.h"
#include "twin/ValueOrigin.h"

namespace twin {

std::vector<ListedLine> pixel_listing(const ProgramTrace& trace, size_t point, std::span<const Counterpart> counterparts) {
  const Module& m = *trace.module;
  const ValueNames names(m);
  const std::vector<int> match = counterparts.empty() ? std::vector<int>(trace.values.size(), -2)
                                                      : match_values(trace, counterparts);
  std::vector<ListedLine> lines;
  std::map<std::pair<std::string, int>, size_t> at;
  for (size_t i = 0; i < trace.values.size(); ++i) {
    const ValueFingerprint& v = trace.values[i];
    if (point >= v.present.size() || !v.present[point]) continue;
    const Instruction& in = m.instructions[v.instruction];
    const SourceLine& l = line_of(m, in);
    if (l.line == 0) continue;
    auto [it, added] = at.try_emplace({l.file, l.line}, lines.size());
    if (added) lines.push_back({l.file, l.line, source_line_text(m, l.file, l.line), {}});
    ListedLine& line = lines[it->second];
    ListedValue value{"", {v.values.begin() + std::ptrdiff_t(point * v.slots), v.values.begin() + std::ptrdiff_t((point + 1) * v.slots)},
                      match[i] >= 0 ? counterparts[size_t(match[i])].label() : "", !counterparts.empty() && match[i] == -1};
    if (std::string stored = names.stored_as(in.result); !stored.empty()) {
      value.name = std::move(stored);
      line.values.push_back(std::move(value));
    } else if (line.values.empty() || !line.values.back().name.empty()) {
      line.values.push_back(std::move(value));   // the line's last value so far
    } else {
      line.values.back() = std::move(value);
    }
  }
  // A line with a named value shows those only.
  for (ListedLine& line : lines) {
    const bool named = std::ranges::any_of(line.values, [](const ListedValue& v) { return !v.name.empty(); });
    if (named) std::erase_if(line.values, [](const ListedValue& v) { return v.name.empty(); });
  }
  return lines;
}

std::string listing_text(const std::vector<ListedLine>& lines) {
  std::string out;
  for (const ListedLine& l : lines) {
    out += l.file + ":" + std::to_string(l.line) + "  " + l.text + "\n";
    for (const ListedValue& v : l.values) {
      out += "      " + (v.name.empty() ? std::string("=") : v.name + " =") + " " + values_text(v.values);
      if (v.departs) out += "   matches nothing";
      else if (!v.matches.empty()) out += "   matches " + v.matches;
      out += "\n";
    }
  }
  return out;
}

}  // namespace twin
