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
#include "scene/CaseFile.h"
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

// A user's case (`hard --case path/to/case.toml`), judged against its own shader in double
// (the twin): the slices that break naive formulas whatever the shader computes. N.L and
// N.V through 0, L = V, L = -V, the light at the eye (and for a point light just above and on
// the surface), long normals, the model's sharpest lobe where it has one, each scalar
// parameter the shader binds at the two ends of its range, and degenerate tangents when the
// shader reads a tangent.
struct UserCaseTraits {
  bool point_light = false;     // the shader reads light_position (or the case's light is a point)
  bool reads_tangent = false;   // a vertex input is the tangent or binormal
};
std::vector<Scenario> user_scenarios(const Case& c, const UserCaseTraits& traits);

// Every scenario name any model can get, for --scenario checks and docs.
std::vector<std::string> scenario_names();

}  // namespace shaderbed::hard
