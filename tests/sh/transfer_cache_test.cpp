// The transfer cache serves a stored result only for exactly the same key, and never a
// damaged file: whether a call computed is read from the report, not from timing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "TempDir.h"
#include "sh/TransferCache.h"
#include "TransferSceneOf.h"

namespace sh {
namespace {

using sh::test::make_scene;

// A small box-like object (an octahedron) over a floor: cheap, and with real shadows.
std::vector<TransferMesh> small_scene(double lift = 0.0) {
  TransferMesh object;
  object.albedo = glm::dvec3(0.9, 0.6, 0.3);
  const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::dvec3& a : axes) {
    object.positions.push_back(0.5 * a + glm::dvec3(0.0, 0.6 + lift, 0.0));
    object.normals.push_back(a);
  }
  object.indices = {0, 2, 4, 4, 2, 1, 1, 2, 5, 5, 2, 0, 0, 4, 3, 4, 1, 3, 1, 5, 3, 5, 0, 3};
  return {object, ground_plane(0.0, 2.0, 4, glm::dvec3(0.5))};
}

const TransferOptions base{.kind = TransferKind::interreflected, .bands = 3, .grid = 6, .seed = 2, .bounces = 1};

CachedTransfer lookup(const TransferScene& scene, const TransferOptions& options, const std::filesystem::path& dir) {
  auto report = cached_transfer_report(scene, options, dir);
  EXPECT_TRUE(report.has_value()) << (report ? "" : report.error());
  EXPECT_EQ(report->write_error, "");
  return std::move(*report);
}

bool same(const std::vector<VertexTransfer>& a, const std::vector<VertexTransfer>& b) {
  if (a.size() != b.size()) return false;
  for (size_t m = 0; m < a.size(); ++m)
    if (a[m].bands != b[m].bands || a[m].coefficients != b[m].coefficients) return false;
  return true;
}

TEST(TransferCache, SecondCallIsServedFromDiskAndEqualsTheComputation) {
  const shaderbed::test::TempDir dir("sh_cache");
  const TransferScene scene = make_scene(small_scene());
  const CachedTransfer first = lookup(scene, base, dir.path() / "nested");  // created on demand
  EXPECT_TRUE(first.computed);
  EXPECT_EQ(first.reason, "no cache file");
  EXPECT_TRUE(std::filesystem::exists(first.file));
  const CachedTransfer second = lookup(scene, base, dir.path() / "nested");
  EXPECT_FALSE(second.computed) << second.reason;
  EXPECT_TRUE(same(first.transfer, second.transfer));
  const auto direct = compute_transfer(scene, base);
  ASSERT_TRUE(direct);
  EXPECT_TRUE(same(*direct, second.transfer));
  // Only the final file is left behind: temporaries are renamed away.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path() / "nested")) ++files;
  EXPECT_EQ(files, 1);
}

TEST(TransferCache, AnyChangeOfKeyRecomputes) {
  const shaderbed::test::TempDir dir("sh_cache");
  const TransferScene scene = make_scene(small_scene());
  ASSERT_TRUE(lookup(scene, base, dir.path()).computed);

  std::vector<TransferMesh> moved = small_scene();
  moved[0].positions[2].y += 1e-9;  // one vertex, a little
  EXPECT_TRUE(lookup(make_scene(moved), base, dir.path()).computed);
  std::vector<TransferMesh> recoloured = small_scene();
  recoloured[1].albedo.g = 0.51;
  EXPECT_TRUE(lookup(make_scene(recoloured), base, dir.path()).computed);

  TransferOptions changed = base;
  changed.bands = 4;
  EXPECT_TRUE(lookup(scene, changed, dir.path()).computed);
  changed = base;
  changed.grid = 7;
  EXPECT_TRUE(lookup(scene, changed, dir.path()).computed);
  changed = base;
  changed.seed = 3;
  EXPECT_TRUE(lookup(scene, changed, dir.path()).computed);
  changed = base;
  changed.bounces = 2;
  EXPECT_TRUE(lookup(scene, changed, dir.path()).computed);
  changed = base;
  changed.kind = TransferKind::shadowed;
  EXPECT_TRUE(lookup(scene, changed, dir.path()).computed);
  // Bounces do not matter to the shadowed kind, so they share its file.
  changed.bounces = 5;
  EXPECT_FALSE(lookup(scene, changed, dir.path()).computed);

  // And the original is still there, untouched by the others.
  EXPECT_FALSE(lookup(scene, base, dir.path()).computed);
}

TEST(TransferCache, DamagedFilesAreRecomputedAndRepaired) {
  const shaderbed::test::TempDir dir("sh_cache");
  const TransferScene scene = make_scene(small_scene());
  const CachedTransfer first = lookup(scene, base, dir.path());
  const auto size = std::filesystem::file_size(first.file);

  // Truncated.
  std::filesystem::resize_file(first.file, size - 5);
  CachedTransfer again = lookup(scene, base, dir.path());
  EXPECT_TRUE(again.computed);
  EXPECT_NE(again.reason.find("payload"), std::string::npos) << again.reason;
  EXPECT_TRUE(same(first.transfer, again.transfer));
  EXPECT_FALSE(lookup(scene, base, dir.path()).computed);  // rewritten whole
  std::filesystem::resize_file(first.file, 10);
  EXPECT_TRUE(lookup(scene, base, dir.path()).computed);

  // One flipped byte: in the payload (the checksum catches it), in the header (the key).
  const auto flip = [&](std::streamoff at) {
    std::fstream file(first.file, std::ios::in | std::ios::out | std::ios::binary);
    file.seekg(at);
    char c = 0;
    file.read(&c, 1);
    file.seekp(at);
    c = static_cast<char>(c ^ 0x10);
    file.write(&c, 1);
  };
  flip(static_cast<std::streamoff>(size) - 3);
  again = lookup(scene, base, dir.path());
  EXPECT_TRUE(again.computed);
  EXPECT_NE(again.reason.find("checksum"), std::string::npos) << again.reason;
  EXPECT_TRUE(same(first.transfer, again.transfer));
  flip(12);
  again = lookup(scene, base, dir.path());
  EXPECT_TRUE(again.computed);
  EXPECT_NE(again.reason.find("another key"), std::string::npos) << again.reason;

  // Empty file.
  std::ofstream(first.file, std::ios::trunc).close();
  again = lookup(scene, base, dir.path());
  EXPECT_TRUE(again.computed);
  EXPECT_NE(again.reason.find("truncated"), std::string::npos) << again.reason;
  EXPECT_FALSE(lookup(scene, base, dir.path()).computed);
}

TEST(TransferCache, ConvenienceFormAndErrors) {
  const shaderbed::test::TempDir dir("sh_cache");
  const TransferScene scene = make_scene(small_scene());
  const auto transfer = cached_transfer(scene, base, dir.path());
  ASSERT_TRUE(transfer) << transfer.error();
  EXPECT_EQ(transfer->size(), 2u);
  TransferOptions bad = base;
  bad.bands = 0;
  EXPECT_FALSE(cached_transfer(scene, bad, dir.path()).has_value());
  // An unwritable cache (a file where the folder should be) still gives the transfer.
  const std::string blocker = dir.write("blocker", "x");
  const auto report = cached_transfer_report(scene, base, std::filesystem::path(blocker) / "sub");
  ASSERT_TRUE(report) << report.error();
  EXPECT_TRUE(report->computed);
  EXPECT_NE(report->write_error, "");
  EXPECT_TRUE(same(*transfer, report->transfer));
}

}  // namespace
}  // namespace sh
