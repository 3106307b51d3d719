// The top-level keys that set up what is drawn: tessellation, light and ambient.
#include "scene/CaseSections.h"

namespace shaderbed::case_sections {

Result<void> read_tessellation(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  const toml::table& root = doc.root;
  if (auto t = root["tessellation"].value<std::string>()) {
    if (*t == "low") c.tessellation = Tessellation::low;
    else if (*t == "high") c.tessellation = Tessellation::high;
    else return std::unexpected(at(path, *root.get("tessellation"), "tessellation must be \"low\" or \"high\""));
  }
  return {};
}

Result<void> read_light(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  if (const toml::node* light = doc.root.get("light")) {
    const auto kind = light->value<std::string>();
    if (kind == "directional") c.light = CaseLight::directional;
    else if (kind == "point") c.light = CaseLight::point;
    else return std::unexpected(at(path, *light, "light must be \"directional\" or \"point\""));
  }
  return {};
}

Result<void> read_ambient(const CaseDocument& doc, Case& c) {
  const std::string& path = doc.path;
  if (const toml::node* ambient = doc.root.get("ambient")) {
    auto v = numbers(path, *ambient, "ambient");
    if (!v) return std::unexpected(v.error());
    if (v->size() != 3)
      return std::unexpected(at(path, *ambient, "ambient must be [r, g, b], not " + std::to_string(v->size()) +
                                                    " number" + (v->size() == 1 ? "" : "s")));
    c.ambient = glm::dvec3((*v)[0], (*v)[1], (*v)[2]);
  }
  return {};
}

}  // namespace shaderbed::case_sections
