// Tolerances that scale (docs/tolerances.md): the library's own shaders pass across each
// model's parameter range, not only at the defaults the tolerances were first measured
// at, and a LUT variant passes at every table size from 8 to 1024 with a bound derived
// for the shape it draws. Small images, the shapes that show each lobe, no timed repeats.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ShellCommand.h"
namespace {

struct Point {
  const char* case_name;
  const char* params;   // --param arguments
  const char* variants;
};

class ToleranceSweep : public testing::TestWithParam<Point> {};

TEST_P(ToleranceSweep, CorrectShadersPass) {
  const Point& p = GetParam();
  const auto [status, out] = shaderbed::test::run_shell(
      std::string(SHADERBED_BINARY) + " run --case " + p.case_name + " --variant " + p.variants + " " + p.params +
      " --shape sphere,torus --size 48 --repeat 0 --quiet");
  EXPECT_EQ(status, 0) << p.case_name << " " << p.params << ":\n" << out;
}

// The points that failed with the absolute tolerances of before (cook_torrance's sharp
// tall lobe, oren_nayar's 1024 LUT) and each model's extremes.
INSTANTIATE_TEST_SUITE_P(
    Library, ToleranceSweep,
    testing::Values(Point{"cook_torrance", "--param gaussian_c=25 --param slope_m=0.2", "vertex,pixel,pixel_robust"},
                    Point{"cook_torrance", "--param gaussian_c=25 --param slope_m=0.05", "vertex,pixel,pixel_robust"},
                    Point{"cook_torrance", "--param slope_m=1", "vertex,pixel,pixel_robust"},
                    Point{"phong", "--param power=1", "vertex,pixel"},
                    Point{"phong", "--param power=256", "vertex,pixel"},
                    Point{"blinn_phong", "--param power=256", "vertex,pixel"},
                    Point{"schlick", "--param power=256", "vertex,pixel"},
                    Point{"minnaert", "--param minnaert_power=4", "vertex,pixel"},
                    Point{"oren_nayar", "--param roughness_sq=0.01", "vertex,pixel,pixel_lut"},
                    Point{"oren_nayar", "--param roughness_sq=4", "vertex,pixel,pixel_lut"},
                    Point{"oren_nayar", "--param lut_size=8", "pixel_lut"},
                    Point{"oren_nayar", "--param lut_size=1024", "pixel_lut"},
                    Point{"ward_iso", "--param roughness=0.05", "vertex,pixel,pixel_lut,pixel_robust"},
                    Point{"ward_iso", "--param lut_size=8", "pixel_lut"},
                    Point{"ward_iso", "--param lut_size=128", "pixel_lut"},
                    Point{"ward_aniso", "--param roughness_xy=0.05,0.05", "vertex,pixel"},
                    Point{"spot", "--param falloff=4", "vertex,pixel,pixel_robust"},
                    Point{"warn", "--param warn_exponent=63", "vertex,pixel,pixel_lut,pixel_robust"},
                    Point{"warn", "--param lut_size=8", "pixel_lut"},
                    Point{"warn", "--param lut_size=1024", "pixel_lut"}),
    [](const testing::TestParamInfo<Point>& info) { return std::string(info.param.case_name) + "_" + std::to_string(info.index); });

}  // namespace
