#pragma once
// The hard-case suite: which configurations each model is driven into, and why. A
// scenario is either a parameter-space slice (Slice.h) or a mesh scene (a shape and a
// camera aimed at its hard part) rendered and compared the normal way.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hard/Slice.h"
#include "pipeline/Mesh.h"
#include "scene/Scene.h"

namespace shaderbed::hard {

struct MeshScene {
  Mesh mesh;
  SceneSetup scene;   // width/height set by the runner
};

struct Scenario {
  std::string name;
  std::string probes;                                   // one line: what it exercises
  std::optional<SliceSpec> slice;                       // a slice ...
  std::optional<MeshScene> mesh;                        // ... or a mesh scene
  std::map<std::string, std::vector<double>> params;    // overrides of the case's parameters
};

// The scenarios that apply to a reference model, in a fixed order (model names as in
// shaders/cases/*.toml `model`). `size` is the image size for mesh scenes.
std::vector<Scenario> scenarios_for(const std::string& model, int size);

// Every scenario name any model can get, for --scenario checks and docs.
std::vector<std::string> scenario_names();

}  // namespace shaderbed::hard
