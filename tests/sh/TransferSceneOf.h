#pragma once
// The transfer tests' scenes: built from meshes, a failure to build is the test's failure.
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "sh/TransferScene.h"

namespace sh::test {

inline TransferScene make_scene(std::vector<TransferMesh> meshes) {
  auto scene = TransferScene::create(std::move(meshes));
  EXPECT_TRUE(scene.has_value()) << (scene ? "" : scene.error());
  return std::move(*scene);
}

}  // namespace sh::test
