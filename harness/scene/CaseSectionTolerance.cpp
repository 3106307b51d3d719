// [tolerance]: the interior, silhouette, LUT and approximation thresholds, each with its
// reason. A differential case that states none gets differential_*_tolerance() (CaseFile.cpp);
// a model case that states none, its model's library case's (run/ReferenceKinds.h).
#include "scene/CaseSections.h"

#include <cmath>

#include "scene/TomlKeys.h"

namespace shaderbed::case_sections {
namespace {

Result<Tolerance> tolerance(const std::string& path, const toml::table& t, const std::string& key) {
  const toml::node* node = t.get(key);
  if (!node) return std::unexpected(at(path, t, "[tolerance] needs '" + key + "' = { max_abs = ..., reason = \"...\" }"));
  const toml::table* tt = node->as_table();
  if (!tt) return std::unexpected(at(path, *node, "tolerance '" + key + "' must be a table"));
  if (auto ok = check_keys(path, *tt, {"max_abs", "max_rel", "reason"}, "tolerance '" + key + "'"); !ok)
    return std::unexpected(ok.error());
  auto max_abs = (*tt)["max_abs"].value<double>();
  const double max_rel = (*tt)["max_rel"].value_or(0.0);
  auto reason = (*tt)["reason"].value<std::string>();
  if (!max_abs) return std::unexpected(at(path, *node, "tolerance '" + key + "' needs max_abs"));
  // A NaN threshold would pass every cell (no comparison with NaN fails).
  if (!std::isfinite(*max_abs) || *max_abs < 0)
    return std::unexpected(at(path, *node, "tolerance '" + key + "': max_abs must be a finite number >= 0"));
  if (tt->get("max_rel") && (!tt->get("max_rel")->is_number() || !std::isfinite(max_rel) || max_rel < 0))
    return std::unexpected(at(path, *tt->get("max_rel"), "tolerance '" + key + "': max_rel must be a finite number >= 0"));
  // Thresholds are explained, not tuned: a number without a reason is refused.
  if (!reason || reason->empty())
    return std::unexpected(at(path, *node, "tolerance '" + key + "' needs a reason saying why this threshold"));
  return Tolerance{*max_abs, *reason, max_rel};
}

}  // namespace

Result<void> read_tolerance(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  const toml::table& root = doc.root;
  const toml::table* tol = root["tolerance"].as_table();
  // A differential case may leave its tolerances to the documented fp32 bound.
  if (!tol && c.differential()) {
    c.interior = differential_interior_tolerance();
    c.silhouette = differential_silhouette_tolerance();
    return {};
  }
  // A model case may leave them to the model's (run/ReferenceKinds.h complete_case).
  if (!tol) {
    c.tolerance_from_model = true;
    return {};
  }
  if (auto ok = check_keys(path, *tol, {"interior", "silhouette", "lut", "approximation"}, "[tolerance]"); !ok)
    return std::unexpected(ok.error());
  auto interior = tolerance(path, *tol, "interior");
  if (!interior) return std::unexpected(interior.error());
  auto silhouette = tolerance(path, *tol, "silhouette");
  if (!silhouette) return std::unexpected(silhouette.error());
  c.interior = *interior;
  c.silhouette = *silhouette;
  if (const toml::node* lut = tol->get("lut")) {
    const toml::table* lt = lut->as_table();
    auto reason = lt ? (*lt)["reason"].value<std::string>() : std::nullopt;
    if (!reason || reason->empty())
      return std::unexpected(at(path, *lut, "tolerance 'lut' needs a reason saying how the threshold follows from the LUT"));
    if (auto ok = check_keys(path, *lt, {"max_abs", "reason"}, "tolerance 'lut'"); !ok) return std::unexpected(ok.error());
    const double max_abs = (*lt)["max_abs"].value_or(-1.0);   // absent: derived from the LUT
    if (lt->get("max_abs") && (!std::isfinite(max_abs) || max_abs < 0))
      return std::unexpected(at(path, *lut, "tolerance 'lut': max_abs must be a finite number >= 0 (or left out)"));
    c.lut = Tolerance{max_abs, *reason};
  }
  if (tol->get("approximation")) {
    auto approximation = tolerance(path, *tol, "approximation");
    if (!approximation) return std::unexpected(approximation.error());
    c.approximation = *approximation;
  }
  for (const Variant& v : c.variants)
    if (!v.lut.empty() && !c.lut)
      return std::unexpected(at(path, *tol, "variant '" + v.name + "' uses a LUT: [tolerance] needs 'lut' with a reason"));
  return {};
}

}  // namespace shaderbed::case_sections
