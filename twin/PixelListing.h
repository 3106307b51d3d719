#pragma once
// A pixel debugger's listing: every source line a traced program executed at one pixel, in
// the order first executed, with the values computed on it there — by the variable each is
// stored into, else the line's last value — and, given the counterparts (an original's or a
// model's), what each value matches or that it departs.
#include <span>
#include <string>
#include <vector>

#include "twin/Divergence.h"
#include "twin/ProgramTrace.h"

namespace twin {

struct ListedValue {
  std::string name;              // "" for a line's unnamed last value
  std::vector<double> values;
  std::string matches;           // the counterpart's label ("" when none or not asked)
  bool departs = false;          // matches nothing, when counterparts were given
};

struct ListedLine {
  std::string file;
  int line = 0;
  std::string text;
  std::vector<ListedValue> values;
};

// Point `point` (an index into trace.pixels) of `trace`.
std::vector<ListedLine> pixel_listing(const ProgramTrace& trace, size_t point, std::span<const Counterpart> counterparts);

// "file:line  text\n      name = (0.1, 0.2, 0.3)   matches original.hlsl:12 n"
std::string listing_text(const std::vector<ListedLine>& lines);

}  // namespace twin
