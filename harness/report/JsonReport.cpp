#include "report/JsonReport.h"

#include "core/AtomicFile.h"
#include "core/BoundedFile.h"
#include "report/JsonValues.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace shaderbed {
namespace {

using ojson = nlohmann::ordered_json;
using json = nlohmann::json;


// A folder under $HOME as "~/..." (the default caches are there): a report names no
// user's home, so it reads the same on every machine and says nothing about who ran it.
std::string home_relative(const std::string& dir) {
  const char* home = std::getenv("HOME");
  if (!home || !*home || dir.empty()) return dir;
  const std::filesystem::path relative = std::filesystem::path(dir).lexically_relative(home);
  if (relative.empty() || *relative.begin() == "..") return dir;
  return relative == "." ? "~" : "~/" + relative.generic_string();
}

ojson value_counts(const ValueCounts& v) {
  return {{"nan", v.nan}, {"pos_inf", v.pos_inf}, {"neg_inf", v.neg_inf}, {"negative", v.negative}, {"above_one", v.above_one}};
}

ojson cell_json(const CellResult& r) {
  const CellMetrics& m = r.metrics;
  const CellArtefacts& a = r.artefacts;
  ojson cell = {{"id", r.id()},
                {"case", r.case_name},
                {"variant", r.variant},
                {"language", r.language},
                {"backend", r.backend},
                {"path", r.path},
                {"shape", r.shape},
                {"status", to_string(r.status)},
                {"message", r.message}};
  if (!r.error_stage.empty()) cell["error_stage"] = r.error_stage;
  cell["attribution"] = {{"verdict", r.attribution}, {"reason", r.attribution_reason}};
  cell["known_failure"] = {{"known", r.known_failure}, {"reason", r.known_reason}};
  if (!r.reference_note.empty()) cell["reference_note"] = r.reference_note;
  cell["warnings"] = r.warnings;
  cell["reference"] = {{"kind", r.reference.kind},
                       {"label", r.reference.label},
                       {"is_reference", r.reference.is_reference},
                       {"toolchain_note", r.reference.toolchain_note}};
  ojson explanations = ojson::array();
  for (const Explanation& e : r.explanations)
    explanations.push_back({{"name", e.name},
                            {"description", e.description},
                            {"summary", e.summary},
                            {"residual", json_number(e.residual)},
                            {"rmse", json_number(e.rmse)},
                            {"pixels", e.pixels},
                            {"fits", e.fits}});
  cell["explanations"] = std::move(explanations);
  cell["metrics"] = {{"max_abs", json_number(m.max_abs)},
                     {"rmse", json_number(m.rmse)},
                     {"psnr", json_number(m.psnr)},
                     {"bad_pixels", m.bad_pixels},
                     {"nonfinite", m.nonfinite},
                     {"nonfinite_mismatch", m.nonfinite_mismatch},
                     {"coverage_mismatch", m.coverage_mismatch},
                     {"silhouette_max_abs", json_number(m.silhouette_max_abs)},
                     {"min_passing", {{"interior", json_number(m.min_passing_interior)}, {"silhouette", json_number(m.min_passing_silhouette)}}},
                     {"tolerance_share", json_number(m.tolerance_share)},
                     {"coverage",
                      {{"interior_pixels", m.interior_pixels},
                       {"silhouette_pixels", m.silhouette_pixels},
                       {"covered_pixels", m.covered_pixels},
                       {"reference_covered_pixels", m.reference_covered_pixels},
                       {"expected_area", json_number(m.expected_area)}}},
                     {"values", {{"render", value_counts(m.render_values)}, {"reference", value_counts(m.reference_values)}}}};
  cell["tolerance"] = {{"interior", json_number(r.interior_threshold)},
                       {"silhouette", json_number(r.silhouette_threshold)},
                       {"interior_rel", json_number(r.interior_threshold_rel)},
                       {"silhouette_rel", json_number(r.silhouette_threshold_rel)},
                       {"reason", r.tolerance_reason},
                       {"lut", {{"bound", json_number(r.lut_bound)}, {"derivation", r.lut_derivation}}},
                       {"texels", {{"bound", json_number(r.texel_bound)}, {"derivation", r.texel_derivation}}}};
  if (r.sh)
    cell["sh"] = {{"summary", r.sh->summary},
                  {"render_vs_exact", json_number(r.sh->render_vs_exact)},
                  {"rmse_vs_exact", json_number(r.sh->rmse_vs_exact)},
                  {"truncation", json_number(r.sh->truncation)},
                  {"bound", json_number(r.sh->bound)},
                  {"precompute_ms", json_number(r.sh->precompute_ms)},
                  {"bytes_per_vertex", json_number(r.sh->bytes_per_vertex)}};
  if (const auto& d = r.divergence) {
    if (d->kind == "error") {
      cell["divergence"] = {{"error", d->error}};
    } else {
      ojson operands = ojson::array();
      for (const auto& o : d->operands) operands.push_back({{"name", o.name}, {"matches", o.matches}});
      cell["divergence"] = {{"kind", d->kind}, {"against", d->against}, {"stage", d->stage}, {"file", d->file},
                            {"line", d->line}, {"source", d->source}, {"operation", d->operation},
                            {"value", d->value}, {"operands", std::move(operands)}, {"text", d->text},
                            {"pixels", d->pixels}};
      for (const auto& [key, e] : {std::pair{"port_source", &d->port_source}, std::pair{"original_source", &d->original_source}})
        if (!e->lines.empty())
          cell["divergence"][key] = {{"file", e->file}, {"first", e->first}, {"mark", e->mark}, {"lines", e->lines}};
      if (!d->nearest_file.empty() || !d->nearest_value.empty())
        cell["divergence"]["nearest"] = {{"file", d->nearest_file}, {"line", d->nearest_line},
                                         {"value", d->nearest_value}, {"relation", d->nearest_relation}};
    }
  }
  if (r.twin)
    cell["twin"] = {{"precision", r.twin->precision},
                    {"max_abs", json_number(r.twin->max_abs)},
                    {"rmse", json_number(r.twin->rmse)},
                    {"share", json_number(r.twin->share)},
                    {"worst_pixel", {r.twin->worst_x, r.twin->worst_y}},
                    {"reference_max_abs", json_number(r.twin->reference_max_abs)},
                    {"self_error", json_number(r.twin->self_error)},
                    {"ms", json_number(r.twin->ms)},
                    {"precision_note", r.twin->precision_note},
                    {"nonfinite_origin", r.twin->nonfinite_origin},
                    {"error", r.twin->error}};
  ojson times = ojson::object();
  for (const auto& [stage, ms] : r.time_ms) times[stage] = json_number(ms);
  cell["time_ms"] = std::move(times);
  cell["program_cached"] = r.program_cached;
  const auto interval = [](const TimingInterval& t) {
    return ojson{{"median", json_number(t.median)},
                 {"ci", {{"low", json_number(t.low)}, {"high", json_number(t.high)}, {"level", json_number(t.level)}}}};
  };
  cell["gpu_ms"] = {{"clock", r.gpu.clock},
                    {"warmup", r.gpu.warmup},
                    {"runs", r.gpu.runs},
                    {"device", interval(r.gpu.device)},
                    {"wall", interval(r.gpu.wall)}};
  cell["spirv_hash"] = {{"vertex", r.vertex_spirv_hash}, {"fragment", r.fragment_spirv_hash}};
  cell["scene_hash"] = r.scene_hash;
  cell["instructions"] = {{"vertex", r.vertex_instructions}, {"fragment", r.fragment_instructions}};
  cell["artefacts"] = {{"render_exr", a.render_exr},         {"render_png", a.render_png},
                       {"error_exr", a.error_exr},           {"error_png", a.error_png},
                       {"reference_png", a.reference_png},   {"stored_exr", a.stored_exr},
                       {"vertex_spirv", a.vertex_spirv},
                       {"fragment_spirv", a.fragment_spirv}, {"vertex_cross_glsl", a.vertex_cross_glsl},
                       {"fragment_cross_glsl", a.fragment_cross_glsl}};
  if (a.error_scale.top > 0) {   // only with an error map: what its colours stand for
    const ErrorMapScale& e = a.error_scale;
    cell["artefacts"]["error_scale"] = {{"top", json_number(e.top)}, {"peak", json_number(e.peak)}};
    if (e.peak_x >= 0) cell["artefacts"]["error_scale"]["peak_x"] = e.peak_x, cell["artefacts"]["error_scale"]["peak_y"] = e.peak_y;
  }
  if (!a.render_exr.empty()) cell["image"] = a.render_exr;   // schema 1 name, kept for old readers
  return cell;
}

// ---- reading -----------------------------------------------------------------------------

// A field with the wrong type or value; caught in parse_json and turned into an Error.
struct BadField {
  std::string pointer, message;
};

std::string child(const std::string& pointer, std::string_view key) { return pointer + "/" + std::string(key); }

const json* member(const json& object, std::string_view key) {
  auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

const json* object_at(const json& parent, std::string_view key, const std::string& pointer) {
  const json* v = member(parent, key);
  if (v && !v->is_object()) throw BadField{child(pointer, key), "expected an object, found " + std::string(v->type_name())};
  return v;
}

void read(const json& parent, std::string_view key, const std::string& pointer, std::string& out) {
  const json* v = member(parent, key);
  if (!v) return;
  if (!v->is_string()) throw BadField{child(pointer, key), "expected a string, found " + std::string(v->type_name())};
  out = v->get<std::string>();
}

double to_double(const json& v, const std::string& where) {
  if (v.is_number()) return v.get<double>();
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
  }
  throw BadField{where, "expected a number (or \"inf\", \"-inf\", \"nan\"), found " + v.dump()};
}

void read(const json& parent, std::string_view key, const std::string& pointer, double& out) {
  if (const json* v = member(parent, key)) out = to_double(*v, child(pointer, key));
}

void read(const json& parent, std::string_view key, const std::string& pointer, size_t& out) {
  const json* v = member(parent, key);
  if (!v) return;
  if (v->is_number_unsigned()) out = v->get<size_t>();
  else if (v->is_number_integer() && v->get<long long>() >= 0) out = size_t(v->get<long long>());
  else throw BadField{child(pointer, key), "expected a count (integer >= 0), found " + v->dump()};
}

void read(const json& parent, std::string_view key, const std::string& pointer, int& out) {
  size_t count = size_t(std::max(out, 0));
  read(parent, key, pointer, count);
  out = int(count);
}

void read(const json& parent, std::string_view key, const std::string& pointer, bool& out) {
  const json* v = member(parent, key);
  if (!v) return;
  if (!v->is_boolean()) throw BadField{child(pointer, key), "expected true or false, found " + v->dump()};
  out = v->get<bool>();
}

void read_required(const json& parent, std::string_view key, const std::string& pointer, std::string& out) {
  if (!member(parent, key)) throw BadField{child(pointer, key), "missing"};
  read(parent, key, pointer, out);
}

void read_counts(const json& parent, std::string_view key, const std::string& pointer, ValueCounts& v) {
  const json* o = object_at(parent, key, pointer);
  if (!o) return;
  const std::string p = child(pointer, key);
  read(*o, "nan", p, v.nan);
  read(*o, "pos_inf", p, v.pos_inf);
  read(*o, "neg_inf", p, v.neg_inf);
  read(*o, "negative", p, v.negative);
  read(*o, "above_one", p, v.above_one);
}

CellResult read_cell(const json& c, const std::string& p) {
  if (!c.is_object()) throw BadField{p, "expected a result object, found " + std::string(c.type_name())};
  CellResult r;
  read_required(c, "case", p, r.case_name);
  read_required(c, "variant", p, r.variant);
  read_required(c, "language", p, r.language);
  read_required(c, "backend", p, r.backend);
  read_required(c, "path", p, r.path);
  read_required(c, "shape", p, r.shape);
  std::string status;
  read_required(c, "status", p, status);
  const std::optional<CellStatus> parsed = parse_cell_status(status);
  if (!parsed)
    throw BadField{child(p, "status"), "expected \"pass\", \"fail\", \"error\" or \"skipped\", found \"" + status + "\""};
  r.status = *parsed;
  read(c, "message", p, r.message);
  read(c, "error_stage", p, r.error_stage);
  if (const json* a = object_at(c, "attribution", p)) {
    read(*a, "verdict", child(p, "attribution"), r.attribution);
    read(*a, "reason", child(p, "attribution"), r.attribution_reason);
  }
  if (const json* k = object_at(c, "known_failure", p)) {
    read(*k, "known", child(p, "known_failure"), r.known_failure);
    read(*k, "reason", child(p, "known_failure"), r.known_reason);
  }
  read(c, "reference_note", p, r.reference_note);
  if (const json* list = member(c, "warnings")) {   // absent in files from before it existed
    if (!list->is_array()) throw BadField{child(p, "warnings"), "expected an array"};
    for (size_t i = 0; i < list->size(); ++i) {
      if (!(*list)[i].is_string())
        throw BadField{child(child(p, "warnings"), std::to_string(i)), "expected a string"};
      r.warnings.push_back((*list)[i].get<std::string>());
    }
  }
  if (const json* s = object_at(c, "reference", p)) {
    const std::string sp = child(p, "reference");
    read(*s, "kind", sp, r.reference.kind);
    read(*s, "label", sp, r.reference.label);
    read(*s, "is_reference", sp, r.reference.is_reference);
    read(*s, "toolchain_note", sp, r.reference.toolchain_note);
  }
  if (const json* list = member(c, "explanations")) {
    if (!list->is_array()) throw BadField{child(p, "explanations"), "expected an array"};
    for (size_t i = 0; i < list->size(); ++i) {
      const std::string ep = child(child(p, "explanations"), std::to_string(i));
      const json& e = (*list)[i];
      if (!e.is_object()) throw BadField{ep, "expected an object"};
      Explanation x;
      read(e, "name", ep, x.name);
      read(e, "description", ep, x.description);
      read(e, "summary", ep, x.summary);
      read(e, "residual", ep, x.residual);
      read(e, "rmse", ep, x.rmse);
      read(e, "pixels", ep, x.pixels);
      read(e, "fits", ep, x.fits);
      r.explanations.push_back(std::move(x));
    }
  }
  if (const json* m = object_at(c, "metrics", p)) {
    const std::string mp = child(p, "metrics");
    CellMetrics& x = r.metrics;
    read(*m, "max_abs", mp, x.max_abs);
    read(*m, "rmse", mp, x.rmse);
    read(*m, "psnr", mp, x.psnr);
    read(*m, "bad_pixels", mp, x.bad_pixels);
    read(*m, "nonfinite", mp, x.nonfinite);
    read(*m, "nonfinite_mismatch", mp, x.nonfinite_mismatch);
    read(*m, "coverage_mismatch", mp, x.coverage_mismatch);
    read(*m, "silhouette_max_abs", mp, x.silhouette_max_abs);
    read(*m, "tolerance_share", mp, x.tolerance_share);
    if (const json* mp2 = object_at(*m, "min_passing", mp)) {
      read(*mp2, "interior", child(mp, "min_passing"), x.min_passing_interior);
      read(*mp2, "silhouette", child(mp, "min_passing"), x.min_passing_silhouette);
    }
    if (const json* cov = object_at(*m, "coverage", mp)) {
      const std::string cp = child(mp, "coverage");
      read(*cov, "interior_pixels", cp, x.interior_pixels);
      read(*cov, "silhouette_pixels", cp, x.silhouette_pixels);
      read(*cov, "covered_pixels", cp, x.covered_pixels);
      read(*cov, "reference_covered_pixels", cp, x.reference_covered_pixels);
      read(*cov, "expected_area", cp, x.expected_area);
    }
    if (const json* v = object_at(*m, "values", mp)) {
      read_counts(*v, "render", child(mp, "values"), x.render_values);
      read_counts(*v, "reference", child(mp, "values"), x.reference_values);
    }
  }
  if (const json* t = object_at(c, "tolerance", p)) {
    const std::string tp = child(p, "tolerance");
    read(*t, "interior", tp, r.interior_threshold);
    read(*t, "silhouette", tp, r.silhouette_threshold);
    read(*t, "interior_rel", tp, r.interior_threshold_rel);
    read(*t, "silhouette_rel", tp, r.silhouette_threshold_rel);
    read(*t, "reason", tp, r.tolerance_reason);
    if (const json* lut = object_at(*t, "lut", tp)) {
      read(*lut, "bound", child(tp, "lut"), r.lut_bound);
      read(*lut, "derivation", child(tp, "lut"), r.lut_derivation);
    }
    if (const json* texels = object_at(*t, "texels", tp)) {
      read(*texels, "bound", child(tp, "texels"), r.texel_bound);
      read(*texels, "derivation", child(tp, "texels"), r.texel_derivation);
    }
  }
  if (const json* s = object_at(c, "sh", p)) {   // SH cases only
    const std::string sp = child(p, "sh");
    CellResult::ShErrors e;
    read(*s, "summary", sp, e.summary);
    read(*s, "render_vs_exact", sp, e.render_vs_exact);
    read(*s, "rmse_vs_exact", sp, e.rmse_vs_exact);
    read(*s, "truncation", sp, e.truncation);
    read(*s, "bound", sp, e.bound);
    read(*s, "precompute_ms", sp, e.precompute_ms);
    read(*s, "bytes_per_vertex", sp, e.bytes_per_vertex);
    r.sh = e;
  }
  if (const json* d = object_at(c, "divergence", p)) {
    const std::string dp = child(p, "divergence");
    CellResult::Divergence x;
    if (d->contains("error")) {
      x.kind = "error";
      read(*d, "error", dp, x.error);
    } else {
      read(*d, "kind", dp, x.kind);
      read(*d, "against", dp, x.against);
      read(*d, "stage", dp, x.stage);
      read(*d, "file", dp, x.file);
      read(*d, "line", dp, x.line);
      read(*d, "source", dp, x.source);
      read(*d, "operation", dp, x.operation);
      read(*d, "value", dp, x.value);
      read(*d, "text", dp, x.text);
      read(*d, "pixels", dp, x.pixels);
      if (const json* list = member(*d, "operands"); list && list->is_array())
        for (size_t i = 0; i < list->size(); ++i) {
          const json& o = (*list)[i];
          const std::string op = child(child(dp, "operands"), std::to_string(i));
          if (!o.is_object()) throw BadField{op, "expected an object"};
          CellResult::Divergence::Operand operand;
          read(o, "name", op, operand.name);
          read(o, "matches", op, operand.matches);
          x.operands.push_back(std::move(operand));
        }
      for (const auto& [key, e] : {std::pair{"port_source", &x.port_source}, std::pair{"original_source", &x.original_source}})
        if (const json* o = object_at(*d, key, dp)) {
          const std::string op = child(dp, key);
          read(*o, "file", op, e->file);
          read(*o, "first", op, e->first);
          read(*o, "mark", op, e->mark);
          if (const json* lines = member(*o, "lines"); lines && lines->is_array())
            for (const json& l : *lines)
              if (l.is_string()) e->lines.push_back(l.get<std::string>());
        }
      if (const json* n = object_at(*d, "nearest", dp)) {
        const std::string np = child(dp, "nearest");
        read(*n, "file", np, x.nearest_file);
        read(*n, "line", np, x.nearest_line);
        read(*n, "value", np, x.nearest_value);
        read(*n, "relation", np, x.nearest_relation);
      }
    }
    r.divergence = std::move(x);
  }
  if (const json* t = object_at(c, "twin", p)) {
    const std::string tp = child(p, "twin");
    CellResult::TwinFigures f;
    read(*t, "precision", tp, f.precision);
    read(*t, "max_abs", tp, f.max_abs);
    read(*t, "rmse", tp, f.rmse);
    read(*t, "share", tp, f.share);
    if (const json* w = t->contains("worst_pixel") ? &(*t)["worst_pixel"] : nullptr; w && w->is_array() && w->size() == 2 &&
        (*w)[0].is_number_integer() && (*w)[1].is_number_integer()) {
      f.worst_x = (*w)[0].get<int>();
      f.worst_y = (*w)[1].get<int>();
    }
    read(*t, "reference_max_abs", tp, f.reference_max_abs);
    read(*t, "self_error", tp, f.self_error);
    read(*t, "ms", tp, f.ms);
    read(*t, "precision_note", tp, f.precision_note);
    read(*t, "nonfinite_origin", tp, f.nonfinite_origin);
    read(*t, "error", tp, f.error);
    r.twin = f;
  }
  if (const json* t = object_at(c, "time_ms", p))
    for (const auto& [stage, ms] : t->items()) r.time_ms[stage] = to_double(ms, child(child(p, "time_ms"), stage));
  read(c, "program_cached", p, r.program_cached);
  if (const json* g = object_at(c, "gpu_ms", p)) {
    const std::string gp = child(p, "gpu_ms");
    read(*g, "clock", gp, r.gpu.clock);
    read(*g, "warmup", gp, r.gpu.warmup);
    read(*g, "runs", gp, r.gpu.runs);
    for (auto [name, out] : {std::pair{"device", &r.gpu.device}, std::pair{"wall", &r.gpu.wall}})
      if (const json* t = object_at(*g, name, gp)) {
        const std::string tp = child(gp, name);
        read(*t, "median", tp, out->median);
        if (const json* ci = object_at(*t, "ci", tp)) {
          read(*ci, "low", child(tp, "ci"), out->low);
          read(*ci, "high", child(tp, "ci"), out->high);
          read(*ci, "level", child(tp, "ci"), out->level);
        }
      }
  }
  if (const json* n = object_at(c, "instructions", p)) {
    read(*n, "vertex", child(p, "instructions"), r.vertex_instructions);
    read(*n, "fragment", child(p, "instructions"), r.fragment_instructions);
  }
  read(c, "scene_hash", p, r.scene_hash);
  if (const json* h = object_at(c, "spirv_hash", p)) {
    read(*h, "vertex", child(p, "spirv_hash"), r.vertex_spirv_hash);
    read(*h, "fragment", child(p, "spirv_hash"), r.fragment_spirv_hash);
  }
  if (const json* a = object_at(c, "artefacts", p)) {
    const std::string ap = child(p, "artefacts");
    CellArtefacts& x = r.artefacts;
    read(*a, "render_exr", ap, x.render_exr);
    read(*a, "render_png", ap, x.render_png);
    read(*a, "error_exr", ap, x.error_exr);
    read(*a, "error_png", ap, x.error_png);
    read(*a, "reference_png", ap, x.reference_png);
    read(*a, "stored_exr", ap, x.stored_exr);
    read(*a, "vertex_spirv", ap, x.vertex_spirv);
    read(*a, "fragment_spirv", ap, x.fragment_spirv);
    read(*a, "vertex_cross_glsl", ap, x.vertex_cross_glsl);
    read(*a, "fragment_cross_glsl", ap, x.fragment_cross_glsl);
    if (const json* e = object_at(*a, "error_scale", ap)) {
      const std::string ep = child(ap, "error_scale");
      read(*e, "top", ep, x.error_scale.top);
      read(*e, "peak", ep, x.error_scale.peak);
      read(*e, "peak_x", ep, x.error_scale.peak_x);
      read(*e, "peak_y", ep, x.error_scale.peak_y);
    }
  }
  return r;
}

RunReport read_report(const json& j) {
  if (!j.is_object()) throw BadField{"", "expected a results object, found " + std::string(j.type_name())};
  const json* schema = member(j, "schema");
  if (!schema) throw BadField{"/schema", "missing: not a shaderbed results file"};
  if (!schema->is_number_integer())
    throw BadField{"/schema", "expected an integer schema version, found " + schema->dump()};
  if (const long long v = schema->get<long long>(); v != kResultsSchemaVersion)
    throw BadField{"/schema", fmt::format("schema version {} is not supported: this shaderbed reads version {}{}", v,
                                          kResultsSchemaVersion,
                                          v < kResultsSchemaVersion ? "; re-run the cells with this shaderbed"
                                                                    : "; use the shaderbed that wrote the file")};
  RunReport report;
  // "tools", as every other JSON shaderbed writes; "tool" in files written before.
  if (const json* t = object_at(j, member(j, "tools") ? "tools" : "tool", "")) {
    read(*t, "glslang", "/tool", report.tools.glslang);
    read(*t, "spirv_tools", "/tool", report.tools.spirv_tools);
    read(*t, "spirv_cross", "/tool", report.tools.spirv_cross);
    read(*t, "llvm", "/tool", report.tools.llvm);
    read(*t, "vulkan_device", "/tool", report.tools.vulkan_device);
    read(*t, "gl_platform", "/tool", report.tools.gl_platform);   // absent in files written before EGL
    if (const json* mesa = object_at(*t, "mesa", "/tool")) {
      read(*mesa, "vulkan", "/tool/mesa", report.tools.vulkan_driver);
      read(*mesa, "gl", "/tool/mesa", report.tools.gl_driver);
    }
  }
  read(j, "run_id", "", report.run_id);
  if (const json* cases = object_at(j, "cases", ""))
    for (const auto& [name, digest] : cases->items()) {
      if (!digest.is_string()) throw BadField{"/cases/" + name, "expected a string digest, found " + digest.dump()};
      report.case_digests[name] = digest.get<std::string>();
    }
  read(j, "shard", "", report.shard);
  if (const json* incomplete = object_at(j, "incomplete", "")) {
    Interruption& i = report.interruption.emplace();
    read(*incomplete, "signal", "/incomplete", i.signal);
    read(*incomplete, "reason", "/incomplete", i.reason);
  }
  read(j, "out_dir", "", report.out_dir);
  read(j, "keep_images", "", report.keep_images);
  read(j, "wall_ms", "", report.wall_ms);
  read(j, "workers", "", report.workers);
  if (const json* c = object_at(j, "cache", "")) {
    CacheUse& use = report.cache.emplace();
    if (const json* d = object_at(*c, "driver", "/cache")) {
      read(*d, "enabled", "/cache/driver", use.driver_cache);
      read(*d, "dir", "/cache/driver", use.driver_cache_dir);
    }
    if (const json* k = object_at(*c, "compile", "/cache")) {
      read(*k, "enabled", "/cache/compile", use.compile_cache);
      read(*k, "dir", "/cache/compile", use.compile_cache_dir);
      read(*k, "hits", "/cache/compile", use.compile_hits);
      read(*k, "misses", "/cache/compile", use.compile_misses);
      read(*k, "memory_hits", "/cache/compile", use.compile_memory_hits);
    }
  }
  const json* results = member(j, "results");
  if (!results) throw BadField{"/results", "missing"};
  if (!results->is_array()) throw BadField{"/results", "expected an array, found " + std::string(results->type_name())};
  report.results.reserve(results->size());
  for (size_t i = 0; i < results->size(); ++i) report.results.push_back(read_cell((*results)[i], "/results/" + std::to_string(i)));
  return report;
}

ojson report_json(const RunReport& report) {
  ojson j;
  j["schema"] = kResultsSchemaVersion;
  j["tools"] = json_tools(report.tools);
  j["run_id"] = report.run_id;
  j["cases"] = ojson::object();
  for (const auto& [name, digest] : report.case_digests) j["cases"][name] = digest;
  j["shard"] = report.shard;
  if (report.interruption)
    j["incomplete"] = {{"signal", report.interruption->signal}, {"reason", report.interruption->reason}};
  j["out_dir"] = report.out_dir;
  j["keep_images"] = report.keep_images;
  j["wall_ms"] = json_number(report.wall_ms);
  j["workers"] = report.workers;
  if (report.cache) {   // optional: merged reports have none
    const CacheUse& c = *report.cache;
    j["cache"] = {{"driver", {{"enabled", c.driver_cache}, {"dir", home_relative(c.driver_cache_dir)}}},
                  {"compile",
                   {{"enabled", c.compile_cache},
                    {"dir", home_relative(c.compile_cache_dir)},
                    {"hits", c.compile_hits},
                    {"misses", c.compile_misses},
                    {"memory_hits", c.compile_memory_hits}}}};
  }
  size_t known = 0;
  for (const CellResult& r : report.results) known += r.status == CellStatus::fail && r.known_failure;
  j["totals"] = {{"cells", report.results.size()},
                 {"pass", report.count(CellStatus::pass)},
                 {"fail", report.count(CellStatus::fail) - known},
                 {"known", known},
                 {"error", report.count(CellStatus::error)},
                 {"skipped", report.count(CellStatus::skipped)}};
  j["results"] = ojson::array();
  for (const CellResult& r : report.results) j["results"].push_back(cell_json(r));
  return j;
}

}  // namespace

std::string to_json(const RunReport& report) {
  // Compiler output can hold any bytes: invalid UTF-8 becomes U+FFFD instead of an exception.
  return report_json(report).dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string to_json_line(const RunReport& report) {
  return report_json(report).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

Result<void> write_json(const RunReport& report, const std::string& path) {
  return write_file_atomically(path, to_json(report) + '\n', "JSON report");
}

Result<RunReport> parse_json(std::string_view text, const std::string& file) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    // "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error ..."
    Error err{.message = e.what(), .file = file, .stage = ErrorStage::report};
    static const std::regex where(R"(^\[json\.exception\.[a-z_.0-9]+\] (parse error at line (\d+), column (\d+): )?(.*)$)");
    if (std::smatch m; std::regex_match(err.message, m, where)) {
      if (m[1].matched) {
        err.line = std::stoi(m[2]);
        err.column = std::stoi(m[3]);
      }
      err.message = "invalid JSON: " + m[4].str();
    }
    if (!err.line) err.message += fmt::format(" (at byte {})", e.byte);
    return std::unexpected(std::move(err));
  } catch (const json::out_of_range& e) {
    // out_of_range.406: a number beyond double's range ("1e999") is bad input too, not a crash.
    const std::string what = e.what();
    const size_t tag_end = what.find("] ");
    return std::unexpected(Error{.message = "invalid JSON: " + (tag_end == std::string::npos ? what : what.substr(tag_end + 2)),
                                 .file = file, .stage = ErrorStage::report});
  }
  try {
    return read_report(j);
  } catch (const BadField& b) {
    return std::unexpected(Error{.message = (b.pointer.empty() ? std::string("/") : b.pointer) + ": " + b.message,
                                 .file = file,
                                 .stage = ErrorStage::report});
  } catch (const json::exception& e) {
    // A field's type the readers above did not check: bad input too, never an abort.
    return std::unexpected(
        Error{.message = std::string("unexpected value: ") + e.what(), .file = file, .stage = ErrorStage::report});
  }
}

Result<RunReport> read_json(const std::string& path) {
  // Bounded and regular files only: `/dev/zero` or a FIFO named as results is one error,
  // not a read until memory runs out or a wait forever.
  Result<std::string> text = read_bounded_file(path, "results file", ErrorStage::report, kMaxResultsBytes);
  if (!text) return std::unexpected(text.error());
  return parse_json(*text, path);
}

}  // namespace shaderbed
