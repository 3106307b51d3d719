#include "run/ReferenceKinds.h"

#include <algorithm>
#include <filesystem>

#include "prt/ShCase.h"
#include "reference/ModelRegistry.h"
#include "reference/Reference.h"
#include "run/Runner.h"

namespace shaderbed {
namespace fs = std::filesystem;

ReferenceKinds::ReferenceKinds(const StoredReferences& stored) {
  // Stored images judge whatever the case names (--against); SH before the library models.
  kinds_.push_back(stored_reference_kind(stored));
  kinds_.push_back(sh_reference_kind());
  kinds_.push_back(model_reference_kind());
  kinds_.push_back(original_reference_kind());
}

Result<const DrawAdditions*> ReferenceKinds::draw_inputs(const GroupScene& group) {
  for (const auto& kind : kinds_)
    if (auto inputs = kind->draw_inputs(group); !inputs || *inputs) return inputs;
  return nullptr;
}

std::unique_ptr<CellReference> ReferenceKinds::prepare(const GroupScene& group, GroupDrawer& drawer) {
  for (const auto& kind : kinds_)
    if (kind->judges(*group.group.c, group.settings)) return kind->prepare(group, drawer);
  return kinds_.back()->prepare(group, drawer);   // unreachable: the original's kind takes every differential case
}

Result<void> complete_case(Case& c) {
  apply_sh_defaults(c);
  if (!reference::find_model(c.model)) return {};
  // A user writes only what differs from the model: its other parameters are the defaults.
  if (auto defaults = reference::default_params(c.model))
    for (auto& [name, value] : *defaults) c.params.try_emplace(name, value);
  if (!c.tolerance_from_model) return {};
  // ...and its tolerances are the library case's, derived for the model's whole parameter
  // range (docs/tolerances.md).
  const std::string library_case = (fs::path(default_cases_dir()) / (c.model + ".toml")).string();
  auto library = load_case(library_case);
  if (!library)
    return std::unexpected(Error{.message = "the case states no [tolerance] and the library's case for model '" +
                                            c.model + "' cannot give one: " + library.error().to_string(),
                                 .file = c.path, .line = c.model_line, .stage = ErrorStage::case_file});
  const auto inherited = [&](Tolerance t) {
    t.reason = "model " + c.model + "'s tolerance (" + library_case + "): " + t.reason;
    return t;
  };
  c.interior = inherited(library->interior);
  c.silhouette = inherited(library->silhouette);
  if (library->lut) c.lut = inherited(*library->lut);
  for (const Variant& v : c.variants)
    if (!v.lut.empty() && !c.lut)
      return std::unexpected(Error{.message = "variant '" + v.name + "' uses a LUT and model " + c.model +
                                              " has no LUT tolerance: state [tolerance]",
                                   .file = c.path, .line = c.model_line, .stage = ErrorStage::case_file});
  return {};
}

bool is_reference_model(const std::string& model) { return reference::find_model(model) || is_sh_model(model); }

std::vector<std::string> reference_model_names() {
  std::vector<std::string> names = reference::model_names();
  std::ranges::copy(sh_model_names(), std::back_inserter(names));
  return names;
}

}  // namespace shaderbed
