// Every shape carries a vertex colour, (0.5 + 0.5 n, 1) from its normal, in the tightly
// packed vertex the backends upload.
#include <cstddef>

#include <gtest/gtest.h>

#include "scene/Primitives.h"

namespace shaderbed {
namespace {

TEST(VertexColour, TheStreamFollowsTheOthersWithoutPadding) {
  EXPECT_EQ(offsetof(Vertex, color), 44u);
  EXPECT_EQ(sizeof(Vertex), 72u);   // then the binormal, after the colour
  EXPECT_EQ(Vertex{}.color, glm::vec4(1, 1, 1, 1)) << "meshes that paint nothing are white";
}

TEST(VertexColour, EveryShapeIsPaintedFromItsNormals) {
  for (const std::string& name : shape_names())
    for (Tessellation t : {Tessellation::low, Tessellation::high}) {
      const auto mesh = make_shape(name, t);
      ASSERT_TRUE(mesh) << name;
      for (const Vertex& v : mesh->vertices) {
        ASSERT_EQ(v.color, glm::vec4(0.5f + 0.5f * v.normal, 1.0f)) << name;
        ASSERT_GE(v.color.r, 0.0f);
        ASSERT_LE(v.color.r, 1.0f);
      }
    }
}

}  // namespace
}  // namespace shaderbed
