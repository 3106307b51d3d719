#pragma once
// The registry of reference kinds (run/CellReference.h), in the order they are asked: the
// first kind that judges a case prepares its groups' references.
#include <memory>
#include <string>
#include <vector>

#include "run/CellReference.h"
#include "run/StoredImages.h"

namespace shaderbed {

class ReferenceKinds {
 public:
  // `stored`: the stored runs the run loaded (the viewer loads none).
  explicit ReferenceKinds(const StoredReferences& stored);
  // What the group's draws take from the kinds (CellReference::draw_inputs): the first
  // kind's that adds something, or its error.
  Result<const DrawAdditions*> draw_inputs(const GroupScene& group);
  std::unique_ptr<CellReference> prepare(const GroupScene& group, GroupDrawer& drawer);

 private:
  std::vector<std::unique_ptr<ReferenceKind>> kinds_;
};

// What the kinds add to a case once it is read: the model's default parameters (a library
// model's, an SH model's) and, when the case states no [tolerance], the library case's
// tolerances for its model. An error when the model has no library case to inherit from.
Result<void> complete_case(Case& c);
// The model names the kinds evaluate (the library's and SH's), for a case's `model`.
bool is_reference_model(const std::string& model);
std::vector<std::string> reference_model_names();

// The kinds, one file each.
std::unique_ptr<ReferenceKind> stored_reference_kind(const StoredReferences& stored);
std::unique_ptr<ReferenceKind> sh_reference_kind();
std::unique_ptr<ReferenceKind> model_reference_kind();
std::unique_ptr<ReferenceKind> original_reference_kind();

}  // namespace shaderbed
