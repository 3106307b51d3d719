// Image instructions: handles, sampling with implicit or explicit LOD, fetches and queries,
// all answered by TextureSampling from the texels the draw binds. A handle is an index
// into BoundResources::resources; OpSampledImage pairs an image with a separate sampler
// state as image + 65536 * (sampler + 1).
#include <spirv/unified1/spirv.hpp11>

#include <algorithm>
#include <cmath>
#include <optional>

#include "twin/Executor.h"

namespace twin {

namespace {

using spv::Op;

constexpr uint32_t sampler_shift = 65536;

// An integer operand (texel coordinate, level) as int: a 64-bit integer's slot can be far
// beyond int, whose conversion would be undefined.
int as_int(double x) { return x == x ? int(std::clamp(x, -1e9, 1e9)) : 0; }

}  // namespace

template <typename Real>
TwinResult<void> BasicExecutor<Real>::execute_image(uint32_t index, const Lanes& lanes) {
  const Instruction& in = m_.instructions[index];
  const auto ops = m_.operands_of(in);
  const Op op = Op(in.op);
  const uint32_t L = lanes_;
  Real* d = dst(in.result);
  const Src handle = src(ops[0]);

  struct Bound {
    const TextureImage* image = nullptr;
    SamplerState sampler;
  };
  // The sampler state's filtering and addressing; sRGB decoding belongs to the image's format.
  auto bound = [&](uint16_t l) -> Bound {
    const auto h = uint32_t(handle.at(0, l));
    const uint32_t image = h % sampler_shift, sampler = h / sampler_shift;
    if (image >= resources_.resources.size() || (sampler && sampler - 1 >= resources_.resources.size())) return {};
    Bound b{.image = resources_.resources[image].image,
            .sampler = sampler ? resources_.resources[sampler - 1].sampler : resources_.resources[image].sampler};
    b.sampler.srgb = resources_.resources[image].sampler.srgb;
    return b;
  };

  switch (op) {
    case Op::OpSampledImage: {
      const Src sampler = src(ops[1]);
      for (uint16_t l : lanes) d[l] = double(uint32_t(handle.at(0, l)) % sampler_shift) +
                                      sampler_shift * (double(uint32_t(sampler.at(0, l)) % sampler_shift) + 1);
      return {};
    }
    case Op::OpImage:
      for (uint16_t l : lanes) d[l] = double(uint32_t(handle.at(0, l)) % sampler_shift);
      return {};
    default: break;
  }

  // The image type: how many coordinates it takes.
  uint32_t image_type = m_.type_of[ops[0]];
  if (m_.types[image_type].kind == Type::Kind::sampled_image) image_type = m_.types[image_type].element;
  const Type& it = m_.types[image_type];
  if (it.arrayed) return std::unexpected(error(in, "the twin does not sample arrayed images"));
  const auto dim = spv::Dim(it.dim);
  const uint32_t dimensions = dim == spv::Dim::Dim1D || dim == spv::Dim::Buffer ? 1
                              : dim == spv::Dim::Dim3D || dim == spv::Dim::Cube ? 3
                                                                               : 2;
  // Src::at does not check its slot: never read more components than an operand has (a
  // Buffer image's coordinate is a scalar).
  auto components = [&](uint32_t id, uint32_t wanted) { return std::min(wanted, slots_of(id)); };

  auto missing = [&]() { return std::unexpected(error(in, "a texture instruction reads a binding with no texture")); };

  switch (op) {
    case Op::OpImageSampleImplicitLod: case Op::OpImageSampleExplicitLod: case Op::OpImageSampleProjImplicitLod:
    case Op::OpImageSampleProjExplicitLod: case Op::OpImageQueryLod: {
      const bool projective = op == Op::OpImageSampleProjImplicitLod || op == Op::OpImageSampleProjExplicitLod;
      const bool implicit = op == Op::OpImageSampleImplicitLod || op == Op::OpImageSampleProjImplicitLod ||
                            op == Op::OpImageQueryLod;
      const Src coordinate = src(ops[1]);
      // The projective divisor is the component after the coordinates.
      const uint32_t coordinates =
          std::min(dimensions, projective ? std::max(slots_of(ops[1]), 1u) - 1 : slots_of(ops[1]));
      const uint32_t mask = ops.size() > 2 ? ops[2] : 0;
      size_t next = 3;
      std::optional<Src> bias, lod, grad_x, grad_y;
      uint32_t grad_components = 0;
      if (mask & uint32_t(spv::ImageOperandsMask::Bias)) bias = src(ops[next++]);
      if (mask & uint32_t(spv::ImageOperandsMask::Lod)) lod = src(ops[next++]);
      if (mask & uint32_t(spv::ImageOperandsMask::Grad)) {
        grad_components = std::min(components(ops[next], coordinates), slots_of(ops[next + 1]));
        grad_x = src(ops[next++]);
        grad_y = src(ops[next++]);
      }
      if (mask & ~uint32_t(spv::ImageOperandsMask::Bias | spv::ImageOperandsMask::Lod | spv::ImageOperandsMask::Grad))
        return std::unexpected(error(in, "the twin does not support texel offsets or other image operands"));
      auto coordinate_at = [&](uint16_t lane) {
        std::array<double, 3> c{0, 0, 0};
        // Sampling works in double: the texels are floats.
        const Real q = projective ? coordinate.at(coordinates, lane) : Real(1);
        for (uint32_t k = 0; k < coordinates; ++k)
          c[k] = double(projective ? rounded(index, coordinate.at(k, lane) / q) : coordinate.at(k, lane));
        return c;
      };
      for (uint16_t l : lanes) {
        const Bound b = bound(l);
        if (!b.image) return missing();
        double lambda = 0;
        if (grad_x) {
          CoordinateDerivatives g;
          for (uint32_t k = 0; k < grad_components; ++k) {
            g.dx[k] = double(grad_x->at(k, l));
            g.dy[k] = double(grad_y->at(k, l));
          }
          lambda = implicit_lod(*b.image, coordinate_at(l), g);
        } else if (lod) {
          lambda = double(lod->at(0, l));
        } else if (implicit && quads_) {
          // One level of detail per quad, from its first row and column (llvmpipe's default).
          const uint16_t q = uint16_t(l & ~3u);
          const auto c0 = coordinate_at(q), cx = coordinate_at(uint16_t(q + 1)), cy = coordinate_at(uint16_t(q + 2));
          CoordinateDerivatives g;
          for (uint32_t k = 0; k < coordinates; ++k) {
            g.dx[k] = cx[k] - c0[k];
            g.dy[k] = cy[k] - c0[k];
          }
          lambda = implicit_lod(*b.image, c0, g);
        }
        if (bias) lambda += double(bias->at(0, l));
        if (op == Op::OpImageQueryLod) {
          const double levels = level_count(*b.image);
          const double clamped = b.sampler.mip_filter == MipFilter::none ? 0.0 : std::clamp(lambda, 0.0, levels - 1);
          d[l] = rounded(index, clamped);
          d[L + l] = rounded(index, lambda);
          continue;
        }
        const std::array<double, 4> texel = sample(*b.image, b.sampler, coordinate_at(l), lambda);
        const uint32_t n = slots_of(in.result);
        for (uint32_t s = 0; s < n && s < 4; ++s) d[s * L + l] = rounded(index, texel[s]);
      }
      return {};
    }
    case Op::OpImageFetch: {
      const Src coordinate = src(ops[1]);
      const uint32_t coordinates = components(ops[1], dimensions);
      const uint32_t mask = ops.size() > 2 ? ops[2] : 0;
      std::optional<Src> lod;
      if (mask & uint32_t(spv::ImageOperandsMask::Lod)) lod = src(ops[3]);
      for (uint16_t l : lanes) {
        const Bound b = bound(l);
        if (!b.image) return missing();
        std::array<int, 3> texel{0, 0, 0};
        for (uint32_t k = 0; k < coordinates; ++k) texel[k] = as_int(double(coordinate.at(k, l)));
        const auto value = fetch(*b.image, b.sampler.srgb, texel, lod ? as_int(double(lod->at(0, l))) : 0);
        const uint32_t n = slots_of(in.result);
        for (uint32_t s = 0; s < n && s < 4; ++s) d[s * L + l] = rounded(index, value[s]);
      }
      return {};
    }
    case Op::OpImageQuerySize: case Op::OpImageQuerySizeLod: {
      const std::optional<Src> lod = op == Op::OpImageQuerySizeLod ? std::optional<Src>(src(ops[1])) : std::nullopt;
      const uint32_t n = slots_of(in.result);
      for (uint16_t l : lanes) {
        const Bound b = bound(l);
        if (!b.image) return missing();
        const auto size = level_size(*b.image, lod ? as_int(double(lod->at(0, l))) : 0);
        for (uint32_t s = 0; s < n && s < 3; ++s) d[s * L + l] = size[s];
      }
      return {};
    }
    case Op::OpImageQueryLevels:
      for (uint16_t l : lanes) {
        const Bound b = bound(l);
        if (!b.image) return missing();
        d[l] = level_count(*b.image);
      }
      return {};
    default: return std::unexpected(error(in, "the twin does not support " + opcode_name(in.op)));
  }
}

template TwinResult<void> BasicExecutor<double>::execute_image(uint32_t, const Lanes&);
template TwinResult<void> BasicExecutor<WideReal>::execute_image(uint32_t, const Lanes&);

}  // namespace twin
