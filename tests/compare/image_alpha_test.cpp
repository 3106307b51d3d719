// Issue 30: alpha is the file's own. OpenImageIO premultiplied RGBA8 PNG texels into RGB on
// reading (alpha 0 read as black, alpha 128 as RGB x 0.5), but shaders keep masks,
// roughness or heights in alpha and must see the stored values, as a texture upload gives them.
#include <cstdint>
#include <filesystem>

#include <gtest/gtest.h>

#include "TempDir.h"
#include "imageio/ImageIoModule.h"

namespace shaderbed {
namespace {

TEST(ImageAlpha, RgbaPngTexelsReadBackAsStoredWhateverTheirAlpha) {
  test::TempDir dir("alpha");
  const std::string path = (dir.path() / "mask.png").string();
  // Three texels: alpha 0, 128 and 255 over the same colour.
  const uint8_t texels[] = {200, 100, 50, 0, 200, 100, 50, 128, 200, 100, 50, 255};
  ASSERT_TRUE(write_image_file(path, 3, 1, 4, PixelType::uint8, texels));
  for (bool levels : {false, true}) {
    std::vector<float> values;
    if (levels) {
      auto read = read_image_levels(path, false);
      ASSERT_TRUE(read) << read.error().to_string();
      EXPECT_TRUE(read->eight_bit);
      values = read->levels.at(0).values;
    } else {
      auto read = read_image_file(path);
      ASSERT_TRUE(read) << read.error().to_string();
      values = read->values;
    }
    ASSERT_EQ(values.size(), 12u);
    // (OpenImageIO converts by n * (1/255): within an ulp of n / 255.)
    for (size_t i = 0; i < 12; ++i) EXPECT_NEAR(values[i], texels[i] / 255.0, 1e-7) << "value " << i;
  }
}

}  // namespace
}  // namespace shaderbed
