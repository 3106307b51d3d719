#include "twin/Divergence.h"

#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "twin/InstructionText.h"
#include "twin/ValueOrigin.h"

namespace twin {
namespace {

using Kind = DataFlow::Kind;

// Two values of the same quantity computed by two programs in double: equal but for the
// rounding of a differently spelt formula (1e-6 relative leaves room for cancellation in
// a few steps), or both tiny.
bool close(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= 1e-6 * std::max(std::abs(a), std::abs(b)) + 1e-9;
}

std::string number(double v) {
  std::ostringstream out;
  out.precision(4);
  out << v;
  return out.str();
}

bool opaque(const Module& m, uint32_t type) {
  const Type::Kind k = m.types[type].kind;
  return k == Type::Kind::image || k == Type::Kind::sampler || k == Type::Kind::sampled_image;
}

// Whether a value's slots may match a counterpart's in any position: structs and arrays
// (a port packs its uniforms and varyings as it likes).
bool loose(const Module& m, uint32_t type) {
  const Type::Kind k = m.types[type].kind;
  return k == Type::Kind::structure || k == Type::Kind::array;
}

struct Matcher {
  const ProgramTrace& port;
  std::span<const Counterpart> counterparts;
  const DataFlow& flow;
  ValueNames names;

  // A varying's component that is the same 0 or 1 at every pixel: padding (a vec4 texture
  // coordinate's z and w) that needs no counterpart.
  bool padding(const ValueFingerprint& v, uint32_t s) const {
    std::optional<double> seen;
    for (size_t p = 0; p < port.pixels.size(); ++p) {
      if (!v.present[p]) continue;
      const double x = v.values[p * v.slots + s];
      if (seen && *seen != x) return false;
      seen = x;
    }
    return seen && (*seen == 0 || *seen == 1);
  }

  // Slot s of port value v against slot k of counterpart c, over the pixels both computed.
  bool slot_matches(const ValueFingerprint& v, uint32_t s, const Counterpart& c, uint32_t k) const {
    size_t common = 0;
    for (size_t p = 0; p < port.pixels.size(); ++p) {
      if (!v.present[p] || p >= c.present.size() || !c.present[p]) continue;
      if (!close(v.values[p * v.slots + s], c.values[p * c.slots + k])) return false;
      ++common;
    }
    return common > 0;
  }
  // A vector's components match in their own positions (a swizzle that reorders them is a
  // different value); a scalar matches any component, as do the slots of a struct or array.
  bool slot_in(const ValueFingerprint& v, uint32_t s, const Counterpart& c, bool any_position) const {
    if (v.slots == 1 || c.slots == 1 || any_position) {
      for (uint32_t k = 0; k < c.slots; ++k)
        if (slot_matches(v, s, c, k)) return true;
      return false;
    }
    return s < c.slots && slot_matches(v, s, c, s);
  }

  int match(const ValueFingerprint& v) const {
    const Instruction& in = port.module->instructions[v.instruction];
    if (opaque(*port.module, in.result_type)) return -2;   // a handle: nothing to compare
    if (std::ranges::none_of(v.present, [](uint8_t p) { return p != 0; })) return -2;
    // What a stage reads (uniforms, varyings) may be packed or laid out as the port likes: a
    // transposed matrix or a texture coordinate in .zw is still the same values.
    const bool read = flow.kind[v.instruction] == DataFlow::Kind::read;
    const bool any_position = read || loose(*port.module, in.result_type);
    const bool varying = read && flow.read_variable[v.instruction] &&
                         spv::StorageClass(port.module->types[port.module->type_of[flow.read_variable[v.instruction]]].storage) ==
                             spv::StorageClass::Input;
    const std::string name = names(in.result);
    int best = -1;
    const auto better = [&](int c) {
      if (best < 0) return true;
      const Counterpart &a = counterparts[size_t(c)], &b = counterparts[size_t(best)];
      if ((a.name == name) != (b.name == name)) return a.name == name;
      if (a.on_output_path != b.on_output_path) return a.on_output_path;
      return (a.slots == v.slots) && (b.slots != v.slots);
    };
    for (size_t c = 0; c < counterparts.size(); ++c) {
      bool all = true;
      for (uint32_t s = 0; s < v.slots && all; ++s)
        all = slot_in(v, s, counterparts[c], any_position) || (varying && padding(v, s));
      if (all && better(int(c))) best = int(c);
    }
    if (best >= 0 || v.slots == 1) return best;
    // Slot by slot from different counterparts: a vector the original builds from scalars,
    // or what is read packed otherwise.
    int first = -2;
    for (uint32_t s = 0; s < v.slots; ++s) {
      int found = -1;
      for (size_t c = 0; c < counterparts.size() && found < 0; ++c)
        if ((any_position || counterparts[c].slots == 1) && slot_in(v, s, counterparts[c], true)) found = int(c);
      if (found < 0 && !(varying && padding(v, s))) return -1;
      if (first == -2 && found >= 0) first = found;
    }
    return first;
  }
};

// How far port value v is from counterpart c (component k of it when v is a scalar and c
// not): the relative RMS difference over the pixels both computed, and how they relate.
struct Relation {
  double distance = INFINITY;
  std::string text;
};

Relation relate(const ValueFingerprint& v, const Counterpart& c, uint32_t k, size_t pixels) {
  std::vector<std::pair<double, double>> pairs;   // (port, counterpart)
  for (size_t p = 0; p < pixels; ++p) {
    if (!v.present[p] || p >= c.present.size() || !c.present[p]) continue;
    for (uint32_t s = 0; s < v.slots; ++s) {
      const double a = v.values[p * v.slots + s];
      const double b = c.values[p * c.slots + (v.slots == 1 ? k : s)];
      if (std::isfinite(a) && std::isfinite(b)) pairs.emplace_back(a, b);
    }
  }
  Relation r;
  if (pairs.empty()) return r;
  double diff2 = 0, ref2 = 0;
  for (auto [a, b] : pairs) diff2 += (a - b) * (a - b), ref2 += b * b;
  r.distance = std::sqrt(diff2 / std::max(ref2, 1e-300));
  double lo = INFINITY, hi = -INFINITY, dlo = INFINITY, dhi = -INFINITY, worst = 0;
  size_t equal = 0, unscalable = 0;   // pairs within rounding; pairs no factor relates (b = 0, a not)
  for (auto [a, b] : pairs) {
    if (std::abs(b) > 1e-9) lo = std::min(lo, a / b), hi = std::max(hi, a / b);
    else if (std::abs(a) > 1e-9) ++unscalable;
    dlo = std::min(dlo, a - b), dhi = std::max(dhi, a - b);
    worst = std::max(worst, std::abs(a - b));
    equal += close(a, b);
  }
  const auto same = [](double x, double y) { return std::abs(x - y) <= 1e-4 * std::max({std::abs(x), std::abs(y), 1e-12}); };
  if (equal > 0 && equal < pairs.size())
    r.text = "equal at " + std::to_string(equal) + " of " + std::to_string(pairs.size()) + " values, up to " + number(worst) +
             " off at the others";
  else if (std::isfinite(lo) && unscalable == 0 && same(lo, hi)) r.text = "off by a factor of " + number((lo + hi) / 2);
  else if (same(dlo, dhi) || std::abs(dhi - dlo) <= 1e-9) r.text = "off by " + number((dlo + dhi) / 2);
  else if (std::isfinite(lo) && lo > 0 && unscalable == 0) r.text = "off by a factor that varies over the pixels (" + number(lo) + " to " + number(hi) + ")";
  else r.text = "differs by up to " + number(worst);
  return r;
}

}  // namespace

std::optional<SourceLine> varying_writer(const Module& vertex, int location) {
  // The value stored to the varying, followed back through copies (an HLSL entry point's
  // wrapper copies its outputs out at the function's first line) to where it is computed.
  const DataFlow flow = data_flow(vertex);
  std::optional<SourceLine> found;
  std::map<uint32_t, uint32_t> base;   // access chain -> its variable
  for (const Instruction& in : vertex.instructions) {
    const spv::Op op = spv::Op(in.op);
    if (op == spv::Op::OpAccessChain || op == spv::Op::OpInBoundsAccessChain) {
      const uint32_t b = vertex.operands_of(in)[0];
      base[in.result] = base.contains(b) ? base[b] : b;
    }
    if (op != spv::Op::OpStore || location < 0) continue;
    uint32_t target = vertex.operands_of(in)[0];
    if (base.contains(target)) target = base[target];
    if (vertex.decorations[target].location != location) continue;
    int32_t at = flow.defining[vertex.operands_of(in)[1]];
    for (int hops = 0; at >= 0 && flow.kind[size_t(at)] == DataFlow::Kind::copy && !flow.inputs[size_t(at)].empty() && hops < 8;
         ++hops)
      at = int32_t(flow.inputs[size_t(at)].back());
    const uint32_t line = at >= 0 && vertex.instructions[size_t(at)].line ? vertex.instructions[size_t(at)].line : in.line;
    if (line) found = vertex.lines[line];
  }
  return found;
}

namespace {

std::string joined(const std::vector<std::string>& parts) {
  std::string s;
  for (size_t i = 0; i < parts.size(); ++i) s += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return s;
}

}  // namespace

std::string Counterpart::label() const {
  if (file.empty()) return "the model's " + name;
  std::string s = file + ":" + std::to_string(line);
  if (!name.empty() && name[0] != '%') s += " " + name;
  return s;
}

std::vector<Counterpart> counterparts_of(const ProgramTrace& original) {
  const Module& m = *original.module;
  const DataFlow flow = data_flow(m);
  const ValueNames names(m);
  std::vector<Counterpart> out;
  for (const ValueFingerprint& v : original.values) {
    const Instruction& in = m.instructions[v.instruction];
    if (flow.kind[v.instruction] == Kind::copy || opaque(m, in.result_type)) continue;
    const SourceLine& l = line_of(m, in);
    out.push_back({l.file, l.line, names(in.result), v.slots, v.values, v.present, flow.reaches_output[v.instruction] != 0});
  }
  return out;
}

namespace {

std::vector<int> match_with(const ProgramTrace& port, std::span<const Counterpart> counterparts, const DataFlow& flow) {
  const Matcher matcher{port, counterparts, flow, ValueNames(*port.module)};
  std::vector<int> out;
  out.reserve(port.values.size());
  for (const ValueFingerprint& v : port.values) out.push_back(matcher.match(v));
  return out;
}

}  // namespace

std::vector<int> match_values(const ProgramTrace& port, std::span<const Counterpart> counterparts) {
  return match_with(port, counterparts, data_flow(*port.module));
}

Divergence localise_divergence(const ProgramTrace& port, std::span<const Counterpart> counterparts,
                               const std::string& against, bool trust_uniforms) {
  const Module& m = *port.module;
  const DataFlow flow = data_flow(m);
  const ValueNames names(m);
  const std::vector<int> match = match_with(port, counterparts, flow);
  Divergence d;
  d.pixels = port.pixels.size();
  d.against = against;

  // By instruction: departs (some execution matches nothing), and when it first ran.
  const size_t count = m.instructions.size();
  std::vector<uint8_t> departs(count, 0);
  std::vector<size_t> order(count, SIZE_MAX);
  std::vector<int> first_value(count, -1);
  // With trust_uniforms, what is computed from uniforms and constants alone (a parameter
  // squared) is trusted as the uniforms are. Two passes: the module lists a value's inputs
  // before it except through loops.
  std::vector<uint8_t> trusted(count, 0);
  for (int pass = 0; pass < 2 && trust_uniforms; ++pass)
    for (size_t i = 0; i < count; ++i) {
      const auto variable = flow.read_variable[i];
      if (flow.kind[i] == Kind::read)
        trusted[i] = !variable || spv::StorageClass(m.types[m.type_of[variable]].storage) != spv::StorageClass::Input;
      else if (flow.kind[i] == Kind::computed)
        trusted[i] = std::ranges::all_of(flow.inputs[i], [&](uint32_t j) { return trusted[j] != 0; });
    }
  for (size_t i = 0; i < port.values.size(); ++i) {
    const uint32_t in = port.values[i].instruction;
    // A value computed from constants alone (glslang builds vec3(0.0) at run time) is one.
    const bool from_constants = flow.kind[in] == Kind::computed && flow.inputs[in].empty();
    if (match[i] == -1 && !from_constants && !trusted[in]) departs[in] = 1;
    order[in] = std::min(order[in], i);
    if (first_value[in] < 0) first_value[in] = int(i);
  }
  // What departs on a path of departing values to an output.
  std::vector<uint8_t> divergent(count, 0);
  std::vector<uint32_t> work;
  for (size_t i = 0; i < count; ++i)
    if (flow.output[i] && departs[i]) divergent[i] = 1, work.push_back(uint32_t(i));
  if (work.empty()) {
    d.kind = Divergence::Kind::output_matches;
    return d;
  }
  while (!work.empty()) {
    const uint32_t i = work.back();
    work.pop_back();
    for (uint32_t j : flow.inputs[i])
      if (departs[j] && !divergent[j]) divergent[j] = 1, work.push_back(j);
  }
  const auto inputs_match = [&](size_t i) {
    return std::ranges::none_of(flow.inputs[i], [&](uint32_t j) { return departs[j] != 0; });
  };
  // Where the departure starts: the first departing value whose inputs all match, computed
  // before read (a uniform or varying the original lays out otherwise) before copied.
  std::optional<size_t> root;
  for (Kind kind : {Kind::computed, Kind::read, Kind::copy}) {
    for (size_t i = 0; i < count; ++i)
      if (divergent[i] && flow.kind[i] == kind && inputs_match(i) && (!root || order[i] < order[*root])) root = i;
    if (root) break;
  }
  d.kind = root ? Divergence::Kind::found : Divergence::Kind::unlocalised;
  if (!root)   // the first departing value on the way out, for the report
    for (size_t i = 0; i < count; ++i)
      if (divergent[i] && (!root || order[i] < order[*root])) root = i;
  const Instruction& in = m.instructions[*root];
  const SourceLine& line = line_of(m, in);
  const bool vertex_stage = spv::ExecutionModel(m.execution_model) == spv::ExecutionModel::Vertex;
  d.stage = vertex_stage ? "vertex" : "fragment";
  d.file = line.file;
  d.line = line.line;
  d.operation = operation_name(m, in);
  d.value = names(in.result);
  if (flow.kind[*root] == Kind::read && flow.read_variable[*root] && !vertex_stage) {
    const uint32_t variable = flow.read_variable[*root];
    if (spv::StorageClass(m.types[m.type_of[variable]].storage) == spv::StorageClass::Input &&
        m.decorations[variable].builtin < 0)
      d.varying_location = m.decorations[variable].location;
  }
  d.source_text = source_line_text(m, d.file, d.line);

  // Its operands by name: unnamed temporaries on the same line are opened up to the named
  // values and constants they are computed from.
  const auto label_of = [&](uint32_t instruction) -> std::string {
    const int v = first_value[instruction];
    if (v < 0) return "";
    return match[size_t(v)] >= 0 ? counterparts[size_t(match[size_t(v)])].label() : "";
  };
  std::vector<uint32_t> seen;
  std::function<void(uint32_t, int)> add = [&](uint32_t id, int depth) {
    if (std::ranges::find(seen, id) != seen.end()) return;
    seen.push_back(id);
    if (m.is_constant[id]) {
      const auto& c = m.constants[id];
      if (c.size() == 1) d.operands.push_back({number(c[0]), "constant"});
      return;
    }
    const int32_t def = flow.defining[id];
    if (def < 0) return;
    const std::string name = names(id);
    const Instruction& from = m.instructions[size_t(def)];
    const SourceLine &here = line_of(m, in), &there = line_of(m, from);
    if (name[0] == '%' && there.line == here.line && there.file == here.file && depth < 6 &&
        flow.kind[size_t(def)] == Kind::computed) {
      for (uint32_t op : value_operands(m, from))
        if (is_value(m, flow, op)) add(op, depth + 1);
      return;
    }
    d.operands.push_back({name, label_of(uint32_t(def))});
  };
  if (flow.kind[*root] != Kind::read)
    for (uint32_t op : value_operands(m, in))
      if (is_value(m, flow, op)) add(op, 0);

  // The counterpart the result comes closest to: one of the same name, else the nearest.
  if (first_value[*root] >= 0 && !counterparts.empty()) {
    const ValueFingerprint& v = port.values[size_t(first_value[*root])];
    int best = -1;
    uint32_t best_k = 0;
    Relation best_r;
    for (size_t c = 0; c < counterparts.size(); ++c) {
      const Counterpart& cp = counterparts[c];
      if (!cp.on_output_path || (v.slots != 1 && cp.slots != v.slots)) continue;
      for (uint32_t k = 0; k < (v.slots == 1 ? cp.slots : 1); ++k) {
        Relation r = relate(v, cp, k, port.pixels.size());
        if (!std::isfinite(r.distance)) continue;
        const bool named = !d.value.empty() && d.value[0] != '%' && cp.name == d.value;
        const bool best_named = best >= 0 && counterparts[size_t(best)].name == d.value;
        if (best < 0 || (named && !best_named) || (named == best_named && r.distance < best_r.distance))
          best = int(c), best_k = k, best_r = std::move(r);
      }
    }
    if (best >= 0) {
      const Counterpart& cp = counterparts[size_t(best)];
      std::string name = cp.name[0] == '%' ? "" : cp.name;
      if (!name.empty() && v.slots == 1 && cp.slots > 1) name += "." + std::string(1, "xyzw"[std::min(best_k, 3u)]);
      d.nearest = Divergence::Nearest{cp.file, cp.line, name, best_r.text};
    }
  }
  return d;
}

Divergence into_vertex_stage(const Divergence& fragment, const ProgramTrace& vertex,
                             std::span<const Counterpart> vertex_counterparts) {
  if (fragment.kind != Divergence::Kind::found || fragment.varying_location < 0) return fragment;
  if (!vertex_counterparts.empty()) {
    // A computed value of the vertex stage; a uniform it reads that matches nothing is more
    // likely laid out otherwise than the cause, so the varying's own line says more then.
    Divergence d = localise_divergence(vertex, vertex_counterparts, fragment.against);
    if (d.kind == Divergence::Kind::found && d.operation != "OpLoad") return d;
  }
  Divergence d = fragment;
  if (auto written = varying_writer(*vertex.module, fragment.varying_location)) {
    d.stage = "vertex";
    d.file = written->file;
    d.line = written->line;
    d.source_text = source_line_text(*vertex.module, d.file, d.line);
    d.operands.clear();
    d.nearest.reset();
  }
  return d;
}

std::string Divergence::describe() const {
  if (kind == Kind::output_matches)
    return "no line departs: the shader's twin computes " + against + "'s values at all " + std::to_string(pixels) +
           " traced pixels (a render that fails all the same differs outside the shader's arithmetic)";
  std::string s = (file.empty() ? std::string("(no source line)") : file + ":" + std::to_string(line));
  if (stage == "vertex") s += " (vertex stage)";
  if (!source_text.empty()) s += "  " + source_text;
  if (kind == Kind::unlocalised)
    return s + "  is the first value on the way to the output that matches nothing in " + against +
           ", but its operands do not all match either (no single line isolated)";
  std::vector<std::string> matched, labels, unmatched, constants;
  std::string file_before;
  for (const Operand& o : operands) {
    if (o.matches == "constant") {
      constants.push_back(o.name);
    } else if (o.matches.empty()) {
      unmatched.push_back(o.name);
    } else {
      matched.push_back(o.name);
      // "original.hlsl:31 R" -> "original.hlsl:31", then ":28" for the same file.
      std::string where = o.matches.substr(0, o.matches.find(' '));
      const size_t colon = where.rfind(':');
      const std::string f = colon == std::string::npos ? "" : where.substr(0, colon);
      if (!f.empty() && f == file_before) where = where.substr(colon);
      else file_before = f;
      labels.push_back(o.matches.starts_with("the model's") ? o.matches : where);
    }
  }
  s += " ";
  if (varying_location >= 0 && stage == "vertex") {
    s += " the varying it writes matches nothing in " + against + " where the fragments read it";
  } else if (operands.empty() && operation == "OpLoad") {
    s += " the value read (" + value + ") matches nothing in " + against;
  } else {
    if (!matched.empty()) s += " " + joined(matched) + (matched.size() == 1 ? " matches " : " match ") + joined(labels);
    if (!constants.empty()) s += std::string(matched.empty() ? " " : ", with ") + "constant " + joined(constants);
    s += std::string(matched.empty() && constants.empty() ? " " : "; ") + "the result" +
         (value.empty() || value[0] == '%' ? "" : " (" + value + ")") + " matches nothing in " + against;
  }
  if (nearest)
    s += " (nearest: " + (nearest->file.empty() ? "the model's " + nearest->name
                                                 : nearest->file + ":" + std::to_string(nearest->line) +
                                                       (nearest->name.empty() ? "" : " " + nearest->name)) +
         ", " + nearest->relation + ")";
  return s;
}

}  // namespace twin
