// The book's instruction counts (fxc "approximately N instruction slots", DX9 vs_1_1 /
// ps_2_0), from the book's §3.26 (docs/instruction-counts.md). Where the book gives a literal
// and a constant figure the case's shader decides: our pixel shaders take the parameter
// as a uniform, so they get the "as a constant" number; literal variants ("*_literal")
// get the other.
#include <tuple>

#include "stats/StatsReport.h"

namespace shaderbed::stats {
namespace {

struct BookRow {
  const char* case_name;
  const char* variant;
  const char* stage;
  int count;
};

constexpr BookRow kBook[] = {
    {"blinn_phong", "vertex", "vertex", 20},     // Blinn_Phong_VS
    {"phong", "vertex", "vertex", 22},           // Phong_VS
    {"blinn_phong", "pixel", "fragment", 19},    // Blinn_Phong_PS
    {"phong", "pixel", "fragment", 37},          // Phong_PS, specular power as a constant
    {"phong", "pixel_literal", "fragment", 21},  // Phong_PS, literal power
    {"phong", "pixel_uniform", "fragment", 37},
    {"oren_nayar", "pixel", "fragment", 70},     // arithmetic; > ps_2_0's 64
    {"oren_nayar", "pixel_lut", "fragment", 27}, // OrenNayar_PS, 2D LUT
    {"ward_iso", "pixel", "fragment", 51},       // Ward_Isotropic_PS, roughness as a constant
    {"ward_iso", "pixel_literal", "fragment", 46},
    {"ward_iso", "pixel_uniform", "fragment", 51},
    {"ward_iso", "pixel_lut", "fragment", 19},   // Ward_Isotropic_PS_Tex, 3D LUT
    {"ward_aniso", "pixel", "fragment", 43},     // Ward_Anisotropic_PS
    {"cook_torrance", "pixel", "fragment", 45},  // CookTorrance_PS, "about 45"
};

}  // namespace

std::optional<int> book_count(const std::string& case_name, const std::string& variant, const std::string& stage) {
  for (const BookRow& r : kBook)
    if (case_name == r.case_name && variant == r.variant && stage == r.stage) return r.count;
  return std::nullopt;
}

}  // namespace shaderbed::stats
