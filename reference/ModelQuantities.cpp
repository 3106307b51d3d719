#include "reference/ModelQuantities.h"

#include "reference/ObjectSpace.h"
#include "reference/PixelShading.h"
#include "reference/StableVector.h"
#include "reference/VisibleSurface.h"

namespace reference {
namespace {

// `turned` scaled to the length of `original`: a unit vector stays unit, an unnormalised
// one keeps its length; an identity world matrix gives the object-space vector exactly.
glm::dvec3 keep_length(const glm::dvec3& turned, const glm::dvec3& original) {
  if (turned == glm::dvec3(0.0) || original == glm::dvec3(0.0)) return turned;
  return turned * (stable::length(original) / stable::length(turned));
}

// Collects one pixel's quantities, each vector followed by its world-space version.
class Collector final : public QuantitySink {
 public:
  Collector(const glm::dmat4& world, std::vector<NamedQuantity>& quantities)
      : world_(world),
        linear_(world),
        normal_matrix_(glm::transpose(glm::inverse(glm::dmat3(world)))),
        quantities_(quantities) {}

  void scalar(std::string_view name, double value) override { quantities_.push_back({std::string(name), {value}}); }

  void vector(std::string_view name, const glm::dvec3& value, VectorKind kind) override {
    push(std::string(name), value);
    switch (kind) {
      case VectorKind::direction: return push(std::string(name) + " world", keep_length(linear_ * value, value));
      case VectorKind::normal: return push(std::string(name) + " world", keep_length(normal_matrix_ * value, value));
      case VectorKind::position: return push(std::string(name) + " world", glm::dvec3(world_ * glm::dvec4(value, 1.0)));
      case VectorKind::displacement: return push(std::string(name) + " world", linear_ * value);
      case VectorKind::colour: return;
    }
  }

 private:
  void push(std::string name, const glm::dvec3& value) {
    quantities_.push_back({std::move(name), {value.x, value.y, value.z}});
  }

  glm::dmat4 world_;
  glm::dmat3 linear_;
  glm::dmat3 normal_matrix_;
  std::vector<NamedQuantity>& quantities_;
};

}  // namespace

std::expected<std::vector<std::vector<NamedQuantity>>, std::string> model_quantities(
    const Scene& scene, const std::string& model_name, const Params& params,
    std::span<const std::pair<int, int>> pixels, const Perturbation& perturbation) {
  auto model = scene_model(scene, model_name, params);
  if (!model) return std::unexpected(model.error());
  auto visibility = rasterise_scene(scene);
  if (!visibility) return std::unexpected(visibility.error());
  for (const auto& [x, y] : pixels) {
    if (x < 0 || y < 0 || x >= scene.width || y >= scene.height)
      return std::unexpected("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                             std::to_string(scene.width) + "x" + std::to_string(scene.height) + " image");
  }

  const PointLighting lighting(to_object_space(scene.lights, scene.camera, scene.world), perturbation, model->light,
                               scene.light);
  std::vector<std::vector<NamedQuantity>> result(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) {
    const VisibleSample& sample = visibility->at(pixels[i].first, pixels[i].second);
    if (!sample.covered()) continue;
    const PixelInput input = pixel_input(scene.mesh, sample, lighting, perturbation);
    Collector sink(scene.world, result[i]);
    sink.vector("P", input.point.position, VectorKind::position);
    sink.vector("N interpolated", interpolate_surface(scene.mesh, sample).normal, VectorKind::normal);
    sink.vector("T", input.point.tangent, VectorKind::direction);
    sink.vector("eye_position", input.lighting.eye_position, VectorKind::position);
    sink.vector("light_position", input.lighting.light_position, VectorKind::position);
    sink.vector("light_vector", input.lighting.light_direction, VectorKind::direction);
    model->model->quantities(input.point, input.lighting, sink);
  }
  return result;
}

}  // namespace reference
