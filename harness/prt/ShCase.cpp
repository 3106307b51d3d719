#include "prt/ShCase.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "prt/ShLight.h"
#include "prt/ShSpecular.h"
#include "sh/Basis.h"
#include "sh/Cpca.h"
#include "sh/Lights.h"
#include "sh/Rotation.h"
#include "sh/Sampling.h"
#include "sh/Transfer.h"
#include "sh/TransferCache.h"

namespace shaderbed {
namespace {

using Params = std::map<std::string, std::vector<double>>;

// float4 constants the SH_VS layout gives the clusters: c5..c255 of D3D9's 256.
constexpr int kClusterRegisters = 251;

double param(const Case& c, const std::string& name) { return c.params.at(name).at(0); }

glm::dvec3 colour_param(const Case& c, const std::string& name) {
  const std::vector<double>& v = c.params.at(name);
  return v.size() >= 3 ? glm::dvec3(v[0], v[1], v[2]) : glm::dvec3(v.at(0));
}

Result<void> check_int(const Case& c, const std::string& name, int lo, int hi) {
  const double v = param(c, name);
  if (v != std::floor(v) || v < lo || v > hi)
    return std::unexpected(Error{.message = fmt::format("{} = {} must be a whole number in {}..{}", name, v, lo, hi),
                                 .file = c.path, .stage = ErrorStage::sh});
  return {};
}

// Vertices by their position's exact float bits, then the nearest normal: the reference
// shades each vertex at the position the mesh holds (converted exactly to double), with
// the normal possibly renormalised in double, and a cube corner holds three vertices.
struct PositionHash {
  size_t operator()(const glm::vec3& p) const {
    size_t h = 1469598103934665603ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(&p);
    for (size_t i = 0; i < sizeof p; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
    return h;
  }
};

// The reference "model" of a per-vertex SH case: the colour computed on the CPU for each
// vertex (truncated SH in double, or the exact integral), Gouraud-interpolated by the
// reference rasteriser as the GPU interpolates the vertex shader's output.
class VertexRadiance final : public reference::LightingModel {
 public:
  VertexRadiance(const Mesh& mesh, std::vector<glm::dvec3> colours) : colours_(std::move(colours)) {
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
      index_.emplace(mesh.vertices[v].position, std::make_pair(glm::dvec3(mesh.vertices[v].normal), v));
  }
  glm::dvec3 shade(const reference::SurfacePoint& point, const reference::ObjectSpaceLighting&) const override {
    const glm::vec3 p(point.position);
    // Shaded between vertices (a per-pixel reference was asked of a per-vertex technique):
    // NaN, which fails every comparison, rather than a made-up colour.
    if (glm::dvec3(p) != point.position) return glm::dvec3(std::nan(""));
    const auto [first, last] = index_.equal_range(p);
    const glm::dvec3* best = nullptr;
    double best_dot = -2;
    for (auto it = first; it != last; ++it)
      if (const double d = glm::dot(it->second.first, point.normal); d > best_dot) {
        best_dot = d;
        best = &colours_[it->second.second];
      }
    return best ? *best : glm::dvec3(std::nan(""));
  }

 private:
  std::vector<glm::dvec3> colours_;
  std::unordered_multimap<glm::vec3, std::pair<glm::dvec3, size_t>, PositionHash> index_;
};

// sh_irradiance's references, per pixel from the interpolated normal: the band-limited
// irradiance in double, or the exact integral.
class NormalRadiance final : public reference::LightingModel {
 public:
  explicit NormalRadiance(std::function<glm::dvec3(const glm::dvec3&)> of_normal) : of_normal_(std::move(of_normal)) {}
  glm::dvec3 shade(const reference::SurfacePoint& point, const reference::ObjectSpaceLighting&) const override {
    return of_normal_(point.normal);
  }

 private:
  std::function<glm::dvec3(const glm::dvec3&)> of_normal_;
};

// sh_specular's references, per pixel: a diffuse reference of the interpolated normal (as
// NormalRadiance) plus the specular lobe evaluated exactly at the reflection vector
// R = 2(N·V)N - V of that normal and the interpolated position, V toward the eye: where
// the GPU looks the lobe's cube map up.
class SpecularRadiance final : public reference::LightingModel {
 public:
  SpecularRadiance(std::function<glm::dvec3(const glm::dvec3&)> diffuse, SpecularLobe lobe)
      : diffuse_(std::move(diffuse)), lobe_(lobe) {}
  glm::dvec3 shade(const reference::SurfacePoint& point, const reference::ObjectSpaceLighting& lighting) const override {
    const glm::dvec3 n = glm::normalize(point.normal);
    const glm::dvec3 v = glm::normalize(lighting.eye_position - point.position);
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    return diffuse_(n) + glm::dvec3(lobe_(glm::normalize(r)));
  }

 private:
  std::function<glm::dvec3(const glm::dvec3&)> diffuse_;
  SpecularLobe lobe_;
};

sh::TransferMesh transfer_mesh(const Mesh& mesh, const glm::dvec3& albedo) {
  sh::TransferMesh t;
  t.positions.reserve(mesh.vertices.size());
  t.normals.reserve(mesh.vertices.size());
  for (const Vertex& v : mesh.vertices) {
    t.positions.emplace_back(v.position);
    t.normals.emplace_back(v.normal);
  }
  t.indices = mesh.indices;
  t.albedo = albedo;
  return t;
}

// Appends one colour channel's coefficients as 4-float streams named <prefix><k>.
void add_channel_streams(ExtraStreams& extra, const std::string& prefix, size_t count) {
  for (size_t k = 0; k < (count + 3) / 4; ++k) extra.names.push_back(prefix + std::to_string(k));
}

std::vector<double> padded(std::vector<double> v) {
  v.resize((v.size() + 3) / 4 * 4, 0.0);
  return v;
}

// The light coefficients as the shaders read them: per channel, padded to whole vec4s.
void add_light_uniforms(NamedValues& values, std::span<const glm::dvec3> light) {
  std::vector<double> channel[3];
  for (const glm::dvec3& c : light)
    for (int k = 0; k < 3; ++k) channel[k].push_back(c[k]);
  const char* names[3] = {"sh_light_r", "sh_light_g", "sh_light_b"};
  for (int k = 0; k < 3; ++k) values[names[k]] = padded(channel[k]);
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

const std::vector<std::string>& sh_model_names() {
  static const std::vector<std::string> names{"sh", "sh_cpca", "sh_irradiance", "sh_specular"};
  return names;
}

bool is_sh_model(std::string_view model) {
  return std::ranges::find(sh_model_names(), model) != sh_model_names().end();
}

std::map<std::string, std::vector<double>> sh_default_params(std::string_view model) {
  // Bands 4 (16 coefficients, 12 vec4 inputs for RGB: within GL's 16 attributes with the
  // position), 20² jittered rays per vertex, the light tilted 35° toward the eye.
  Params p{{"bands", {4}}, {"grid", {20}}, {"seed", {1}}, {"bounces", {1}}, {"rotation", {35}},
           {"cone_radius", {0.6}}, {"albedo", {1.0, 0.85, 0.7}}};
  if (model == "sh_cpca") {
    p["clusters"] = {4};
    p["pca_vectors"] = {8};
  }
  if (model == "sh_irradiance" || model == "sh_specular") {
    p.erase("grid");
    p.erase("seed");
    p.erase("bounces");
    p["bands"] = {3};
  }
  if (model == "sh_specular") {
    // The specular view k max(0, R·s)^p: a highlight about 12° wide at half height, half
    // as bright as a facing albedo-1 point under the light, 64² texels per cube face.
    p["specular_power"] = {32};
    p["specular_scale"] = {0.5};
    p["cube_size"] = {64};
  }
  return p;
}

void apply_sh_defaults(Case& c) {
  if (!is_sh_model(c.model)) return;
  for (auto& [name, value] : sh_default_params(c.model)) c.params.try_emplace(name, value);
}

bool is_sh_approximation_parameter(std::string_view name) {
  return name == "bands" || name == "grid" || name == "seed" || name == "bounces" || name == "clusters" ||
         name == "pca_vectors" || name == "cube_size";
}

sh::TransferKind sh_transfer_kind(std::string_view name) {
  return name == "unshadowed" ? sh::TransferKind::unshadowed
         : name == "interreflected" ? sh::TransferKind::interreflected
                                    : sh::TransferKind::shadowed;
}

std::expected<sh::TransferScene, std::string> sh_transfer_scene(const Mesh& shape, const glm::dvec3& albedo, bool ground) {
  std::vector<sh::TransferMesh> meshes{transfer_mesh(shape, albedo)};
  if (ground) {
    double lowest = 0, extent = 0;
    for (const Vertex& v : shape.vertices) {
      lowest = std::min(lowest, double(v.position.y));
      extent = std::max(extent, double(glm::length(v.position)));
    }
    meshes.push_back(sh::ground_plane(lowest - 0.01 * extent, 4 * extent, 16, glm::dvec3(0.8)));
  }
  return sh::TransferScene::create(std::move(meshes));
}

Result<ShPrepared> prepare_sh(const Case& c, const Mesh& shape, const SceneSetup& scene,
                              const std::filesystem::path& cache_dir) {
  const auto t0 = std::chrono::steady_clock::now();
  const ShSetup setup = c.sh.value_or(ShSetup{});
  auto fail_sh = [&](std::string message) {
    return std::unexpected(Error{.message = std::move(message), .file = c.path, .line = setup.line, .stage = ErrorStage::sh});
  };
  if (auto ok = check_int(c, "bands", 1, 8); !ok) return std::unexpected(ok.error());
  const int bands = int(param(c, "bands"));
  const glm::dvec3 albedo = colour_param(c, "albedo");

  // The light, turned by `rotation` degrees about the scene's z axis (toward the eye):
  // projected once in its own frame and then rotated in SH (what D3DXSHRotate does), so a
  // wrong rotation shows against the exact reference, which turns the light itself.
  const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(param(c, "rotation")), glm::dvec3(0, 0, 1)));
  auto made = make_sh_light(setup, c, scene, turn);
  if (!made) return std::unexpected(made.error());
  const ShLight& light = **made;

  ShPrepared out;
  out.mesh = shape;
  std::vector<glm::dvec3> coefficients = light.coefficients(bands);

  if (c.model == "sh_irradiance" || c.model == "sh_specular") {
    if (bands != 3)
      return fail_sh(c.model + " evaluates the 9-coefficient (3-band) irradiance: bands must be 3");
    // E(n) = Σ A_l L_lm y_lm(n) (Ramamoorthi and Hanrahan), times albedo/π: the shader
    // evaluates the 9 basis polynomials of its normal and sums.
    const std::vector<double> a = sh::band_limited_irradiance_weights(bands);
    std::vector<glm::dvec3> irradiance(coefficients.size());
    for (int l = 0; l < bands; ++l)
      for (int m = -l; m <= l; ++m) irradiance[sh::index(l, m)] = coefficients[sh::index(l, m)] * a[l] * albedo / M_PI;
    std::vector<double> packed;
    for (const glm::dvec3& v : irradiance) packed.insert(packed.end(), {v.r, v.g, v.b, 0.0});
    out.uniforms["sh_irradiance"] = packed;
    auto truncated = [irradiance, bands](const glm::dvec3& n) {
      std::vector<double> y(size_t(bands * bands));
      sh::basis_all(bands, sh::to_sh_frame(glm::normalize(n)), y);
      glm::dvec3 e(0.0);
      for (size_t i = 0; i < y.size(); ++i) e += irradiance[i] * y[i];
      return e;
    };
    auto exact = light.exact_unshadowed(albedo);
    out.summary = fmt::format("{} light, 3 bands (9 coefficients), irradiance per pixel", setup.light);
    if (c.model == "sh_irradiance") {
      out.truncated = std::make_shared<NormalRadiance>(std::move(truncated));
      out.exact = std::make_shared<NormalRadiance>(std::move(exact));
      out.precompute_ms = ms_since(t0);
      return out;
    }
    // sh_specular (book Ch. 9.7): plus the specular view of the light, k max(0, ω·s)^p
    // with s the light's direction turned by `rotation`, as a cube map the shader looks
    // up at R (prt/ShSpecular.h). Both references add the lobe exactly at R: the texture's
    // filtering is the render's only difference beyond fp32 (the case's tolerance).
    if (auto ok = check_int(c, "cube_size", 2, 4096); !ok) return std::unexpected(ok.error());
    SpecularLobe lobe{.power = param(c, "specular_power"), .scale = param(c, "specular_scale")};
    if (!(lobe.power >= 1 && lobe.power <= 4096) || !(lobe.scale >= 0 && lobe.scale <= 1e6))
      return fail_sh(fmt::format("specular_power = {} must be in 1..4096 and specular_scale = {} at least 0",
                                 lobe.power, lobe.scale));
    if (setup.light == "sky") lobe.axis = turn * sh::from_sh_frame(sh::SkyLight{}.sun_direction);
    else if (setup.light == "directional" || setup.light == "cone") lobe.axis = turn * scene.lights.direction;
    else return fail_sh("sh_specular's highlight is the light's direction: light = \"sky\", \"directional\" or \"cone\"");
    lobe.axis = glm::normalize(lobe.axis);
    const int cube_size = int(param(c, "cube_size"));
    out.textures["sh_specular"] = std::make_shared<const Texture>(specular_cube(lobe, cube_size));
    const CubeFilterBound filter = cube_filter_bound(lobe, cube_size);
    out.truncated = std::make_shared<SpecularRadiance>(std::move(truncated), lobe);
    out.exact = std::make_shared<SpecularRadiance>(std::move(exact), lobe);
    out.summary += fmt::format(", plus {} max(0, R.s)^{} from a cube map at R (filter bound {:.3g}: {})", lobe.scale,
                               lobe.power, filter.max_abs, filter.derivation);
    out.precompute_ms = ms_since(t0);
    return out;
  }

  // sh and sh_cpca: the per-vertex transfer of the shape (on the ground plane, if asked).
  for (const char* name : {"grid", "seed", "bounces"})
    if (auto ok = check_int(c, name, name == std::string("bounces") ? 0 : 1, name == std::string("grid") ? 1000 : 1 << 30);
        !ok)
      return std::unexpected(ok.error());
  auto transfer_scene = sh_transfer_scene(shape, albedo, setup.ground);
  if (!transfer_scene) return fail_sh(transfer_scene.error());
  sh::TransferOptions options;
  options.kind = sh_transfer_kind(setup.transfer);
  options.bands = bands;
  options.grid = int(param(c, "grid"));
  options.seed = uint64_t(param(c, "seed"));
  options.bounces = options.kind == sh::TransferKind::interreflected ? int(param(c, "bounces")) : 0;
  sh::CachedTransfer cached;
  if (cache_dir.empty()) {
    auto computed = sh::compute_transfer(*transfer_scene, options);
    if (!computed) return fail_sh(computed.error());
    cached = {.transfer = std::move(*computed), .computed = true};
  } else {
    auto read = sh::cached_transfer_report(*transfer_scene, options, cache_dir);
    if (!read) return fail_sh(read.error());
    cached = std::move(*read);
  }
  const sh::VertexTransfer& transfer = cached.transfer.front();
  const size_t n = size_t(bands * bands);
  const size_t vertex_count = shape.vertices.size();

  std::vector<glm::dvec3> truncated(vertex_count);
  if (c.model == "sh") {
    // Two ways to the GPU, one per variant. Up to 4 bands, 16 coefficients per channel as
    // 12 vec4 vertex inputs (`sh_r0`..`sh_b3`, zero beyond `bands`; GL guarantees 16
    // attributes). Any band count up to 8, a data texture `sh_transfer` (one row per
    // vertex: R, G, B blocks of vec4s) read at the vertex's `sh_index`.
    constexpr size_t per_channel = 16, texture_channel = 64;
    if (bands <= 4)
      for (const char* channel : {"sh_r", "sh_g", "sh_b"}) add_channel_streams(out.mesh.extra, channel, per_channel);
    out.mesh.extra.names.push_back("sh_index");
    const size_t stride = out.mesh.extra.stride_floats();
    out.mesh.extra.values.assign(vertex_count * stride, 0.0f);
    const size_t texels_per_channel = (n + 3) / 4;
    Texture data;
    data.name = "sh_transfer";
    data.width = uint32_t(3 * texels_per_channel);
    data.height = uint32_t(vertex_count);
    data.format = TexelFormat::rgba32_float;
    data.texels.assign(size_t(data.width) * data.height * 4, 0.0f);
    for (size_t v = 0; v < vertex_count; ++v) {
      const auto t = transfer.vertex(v);
      for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
          if (bands <= 4) out.mesh.extra.values[v * stride + k * per_channel + i] = float(t[i][k]);
          data.texels[(v * data.width + k * texels_per_channel) * 4 + i] = float(t[i][k]);
        }
      out.mesh.extra.values[v * stride + stride - 4] = float(v);
      truncated[v] = sh::shade(transfer, v, coefficients);
    }
    out.textures["sh_transfer"] = std::make_shared<const Texture>(std::move(data));
    // (width, height, vec4s per channel): where the shader finds a vertex's coefficients.
    out.uniforms["sh_transfer_layout"] = {float(3 * texels_per_channel), float(vertex_count), float(texels_per_channel), 0};
    // 64 per channel, zero past `bands`: the texture variant's arrays take them all, the
    // vertex-input variant's 16-coefficient arrays the first 16.
    std::vector<glm::dvec3> light(coefficients);
    light.resize(texture_channel, glm::dvec3(0.0));
    add_light_uniforms(out.uniforms, light);
    out.bytes_per_vertex = 3 * n * sizeof(float);
  } else {
    if (auto ok = check_int(c, "clusters", 1, 4096); !ok) return std::unexpected(ok.error());
    if (auto ok = check_int(c, "pca_vectors", 4, 24); !ok) return std::unexpected(ok.error());
    const int pca_vectors = int(param(c, "pca_vectors"));
    if (pca_vectors % 4 != 0)
      return fail_sh(fmt::format("pca_vectors = {} must be a multiple of 4 (float4 weights, as SH_VS)", pca_vectors));
    const int clusters = int(param(c, "clusters"));
    // The constants live where the book's SH_VS has them: float4 registers c5..c255 of
    // the 256 a D3D9 vertex shader has (c0-c3 the transform, c4 the layout), in the
    // shaders' $Global block (docs/sh.md). A 64 KiB uniform buffer would hold
    // max_clusters_for_constant_bytes(P, 65536) clusters; the book's 200 x 24 fits neither.
    const int registers = sh::cluster_registers(pca_vectors);
    if (clusters * registers + 6 > kClusterRegisters)
      return fail_sh(fmt::format("{} clusters of {} PCA vectors need {} float4 constants; the SH_VS layout has {} "
                                 "(c5..c255, as D3D9): at most {} clusters",
                                 clusters, pca_vectors, clusters * registers, kClusterRegisters,
                                 (kClusterRegisters - 6) / registers));
    auto compressed = sh::cpca(sh::cpca_input(transfer), int(3 * n),
                               sh::CpcaOptions{.clusters = clusters, .pca_vectors = pca_vectors});
    if (!compressed) return fail_sh(compressed.error());
    auto constants = sh::cluster_light_constants(*compressed, coefficients);
    if (!constants) return fail_sh(constants.error());
    std::vector<double> registers_f(constants->begin(), constants->end());
    registers_f.resize(size_t(kClusterRegisters) * 4, 0.0);
    out.uniforms["sh_cluster_constants"] = std::move(registers_f);
    // The shader's loop reads six float4 weights (the book's 24); how many registers each
    // colour's block has is the layout it needs to find G and B.
    out.uniforms["sh_pca_layout"] = {double(registers / 3), 0.0, 0.0, 0.0};
    out.mesh.extra.names.push_back("sh_cluster");
    add_channel_streams(out.mesh.extra, "sh_weights", 24);
    const size_t stride = out.mesh.extra.stride_floats();
    out.mesh.extra.values.assign(vertex_count * stride, 0.0f);
    for (size_t v = 0; v < vertex_count; ++v) {
      // The book's ClusterID: the cluster's first float4 register in the constant array.
      out.mesh.extra.values[v * stride] = float(compressed->cluster_of_vertex[v] * registers);
      for (int j = 0; j < pca_vectors; ++j)
        out.mesh.extra.values[v * stride + 4 + size_t(j)] = float(compressed->weights[v * size_t(pca_vectors) + size_t(j)]);
      truncated[v] = sh::shade_from_constants(*compressed, *constants, v);
    }
    out.bytes_per_vertex = (1 + size_t(pca_vectors)) * sizeof(float);
  }
  out.truncated = std::make_shared<VertexRadiance>(shape, std::move(truncated));

  // The exact integral at every vertex, with the same visibility (not defined here for
  // the inter-reflected transfer: its bounces are the approximation itself).
  if (options.kind != sh::TransferKind::interreflected) {
    const bool shadowed = options.kind == sh::TransferKind::shadowed;
    std::vector<glm::dvec3> exact(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v)
      exact[v] = light.exact_at(*transfer_scene, glm::dvec3(shape.vertices[v].position),
                                 glm::normalize(glm::dvec3(shape.vertices[v].normal)), albedo, shadowed);
    out.exact = std::make_shared<VertexRadiance>(shape, std::move(exact));
  }
  out.summary = fmt::format("{} light, {} bands, {} transfer, {}² rays per vertex{}{}", setup.light, bands,
                            setup.transfer, options.grid, setup.ground ? ", on a ground plane" : "",
                            cached.computed ? "" : " (transfer from the cache)");
  out.precompute_ms = ms_since(t0);
  return out;
}

}  // namespace shaderbed
