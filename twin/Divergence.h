#pragma once
// Where a port departs from what it is judged against: its values at a set of pixels
// (twin/ProgramTrace.h) matched by fingerprint to the values of its original (or to a
// library model's named quantities), and the first computation on the way to the port's
// output whose operands all have counterparts but whose result has none. Names are not
// needed to match (ports rename); they only break ties and name things in the report.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "twin/DataFlow.h"
#include "twin/ProgramTrace.h"

namespace twin {

// A value the port may match: one of the original's, or a model's named quantity.
struct Counterpart {
  std::string file;   // where the original computes it ("" for a model's quantity)
  int line = 0;
  std::string name;   // OpName, or the quantity's name ("N·L")
  uint32_t slots = 1;
  std::vector<double> values;     // [pixel * slots + slot]
  std::vector<uint8_t> present;   // per pixel
  bool on_output_path = true;     // the original's output depends on it
  // "original.hlsl:31 spec", "original.hlsl:31", "the model's N·L".
  std::string label() const;
};

// Every value of a traced original (its copies left out: a load of what was stored matches
// the same thing).
std::vector<Counterpart> counterparts_of(const ProgramTrace& original);

struct Divergence {
  enum class Kind {
    found,           // the line below departs
    output_matches,  // the port's output matches the original's at every traced pixel
    unlocalised,     // the output departs, but no computation has all its operands matched
  };
  Kind kind = Kind::unlocalised;
  std::string stage;          // "fragment", or "vertex" when a varying departs
  std::string file;
  int line = 0;
  std::string source_text;
  std::string operation;      // "GLSL.std.450 Pow"
  std::string value;          // the result's name
  struct Operand {
    std::string name;
    std::string matches;      // the counterpart's label; "constant" (the name is then its value); "" none
  };
  std::vector<Operand> operands;
  struct Nearest {
    std::string file;
    int line = 0;
    std::string name;
    std::string relation;     // "off by a factor of 2", "off by a factor that varies over the pixels (0.5 to 0.9)"
  };
  std::optional<Nearest> nearest;
  size_t pixels = 0;
  std::string against = "the original";   // what the counterparts are ("the model")
  // The departing value is a varying read at this location (-1: not a varying): the vertex
  // stage computes it (localise that stage, or name varying_writer's line).
  int varying_location = -1;
  // `port.frag:23  float spec = ...;  R, V and shininess match original.hlsl:31, :28, :12; the
  // result matches nothing in the original (nearest: original.hlsl:33 spec, off by ...)`.
  std::string describe() const;
};

// `port`: the port's trace (either stage); `counterparts` at the same pixels or vertices.
// `trust_uniforms`: what the stage reads from uniforms never departs (a model shows its
// quantities, not every value a shader is given).
Divergence localise_divergence(const ProgramTrace& port, std::span<const Counterpart> counterparts,
                               const std::string& against = "the original", bool trust_uniforms = false);

// The line of a vertex stage that writes the varying at `location` (its last store).
std::optional<SourceLine> varying_writer(const Module& vertex, int location);

// A fragment divergence that starts at a varying, followed into the port's vertex stage:
// that stage's own divergence when its values (`vertex`, at some vertices) depart from
// `vertex_counterparts`, else the line that writes the varying. Any other divergence as it is.
Divergence into_vertex_stage(const Divergence& fragment, const ProgramTrace& vertex,
                             std::span<const Counterpart> vertex_counterparts);

// Which counterpart each of the port's values matches (all of its slots), by index into
// the trace's values; -1: none. The matching localise_divergence uses, for listings.
std::vector<int> match_values(const ProgramTrace& port, std::span<const Counterpart> counterparts);

}  // namespace twin
