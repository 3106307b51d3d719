#include "run/ReferenceKinds.h"

#include <algorithm>

#include "prt/ShCase.h"
#include "reference/ModelRegistry.h"

namespace shaderbed {

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

void complete_case(Case& c) { apply_sh_defaults(c); }

bool is_reference_model(const std::string& model) { return reference::find_model(model) || is_sh_model(model); }

std::vector<std::string> reference_model_names() {
  std::vector<std::string> names = reference::model_names();
  std::ranges::copy(sh_model_names(), std::back_inserter(names));
  return names;
}

}  // namespace shaderbed
