#include "reference/ModelRegistry.h"

#include <array>

#include "reference/models/Models.h"

namespace reference {
namespace {

struct RegisteredModel {
  std::string_view name;
  ModelOrError (*make)(const Params&);
};

// An explicit table rather than self-registering statics: this is a static library, and
// the linker drops object files nothing refers to, registrations included.
constexpr std::array registered_models{
    RegisteredModel{"ambient", make_ambient},
    RegisteredModel{"lambert", make_lambert},
    RegisteredModel{"phong", make_phong},
};

}  // namespace

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (const RegisteredModel& model : registered_models) names.emplace_back(model.name);
  return names;
}

ModelOrError make_model(std::string_view name, const Params& params) {
  for (const RegisteredModel& model : registered_models) {
    if (model.name == name) return model.make(params);
  }
  std::string known;
  for (const RegisteredModel& model : registered_models) known += (known.empty() ? "" : ", ") + std::string(model.name);
  return std::unexpected("unknown lighting model '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace reference
