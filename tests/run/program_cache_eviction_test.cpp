// The worker's caches are bounded (run/LruCache.h): a case with thousands of variants
// keeps the programs it used last, not every one it ever compiled.
#include <string>

#include <gtest/gtest.h>

#include "SourceTree.h"
#include "run/LruCache.h"
#include "run/ProgramCache.h"
#include "scene/CaseFile.h"

namespace {

using shaderbed::LruCache;

TEST(LruCache, ForgetsTheLeastRecentlyUsedPastItsEntryBudget) {
  LruCache<int> cache(2, 1000);
  cache.put("a", 1, 10);
  cache.put("b", 2, 10);
  ASSERT_NE(cache.find("a"), nullptr);   // a is now the most recent: b goes next
  cache.put("c", 3, 10);
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.evictions(), 1u);
  EXPECT_EQ(cache.find("b"), nullptr);
  ASSERT_NE(cache.find("a"), nullptr);
  EXPECT_EQ(*cache.find("c"), 3);
  EXPECT_EQ(cache.bytes(), 20u);
}

TEST(LruCache, ForgetsPastItsByteBudgetButKeepsTheNewestEntry) {
  LruCache<std::string> cache(100, 50);
  cache.put("a", "x", 30);
  cache.put("b", "y", 30);   // 60 > 50: a goes
  EXPECT_EQ(cache.find("a"), nullptr);
  EXPECT_EQ(cache.bytes(), 30u);
  const std::string& big = cache.put("c", "z", 500);   // alone over budget, yet kept
  EXPECT_EQ(big, "z");
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.bytes(), 500u);
  cache.put("c", "w", 5);   // replacing counts the new size only
  EXPECT_EQ(cache.bytes(), 5u);
  EXPECT_EQ(cache.size(), 1u);
}

// Real compiles of the library's Lambert case: six programs through a cache of two.
TEST(ProgramCache, KeepsAtMostItsBudgetOfPrograms) {
  auto c = shaderbed::load_case((shaderbed::test::kSource / "shaders" / "cases" / "lambert.toml").string());
  ASSERT_TRUE(c) << c.error().to_string();
  shaderbed::ProgramCache programs({.opengl = false, .max_programs = 2});
  size_t compiled = 0;
  for (const shaderbed::Variant& v : c->variants)
    for (const auto& [language, files] : v.shaders) {
      const shaderbed::CachedProgram& p = programs.get(*c, v, language);
      EXPECT_TRUE(p.program) << p.program.error().to_string();
      ++compiled;
      EXPECT_LE(programs.size(), 2u);
      EXPECT_GT(programs.bytes(), 0u);
    }
  ASSERT_GE(compiled, 4u);
  EXPECT_EQ(programs.evictions(), compiled - 2);
  // The first program was evicted: asking again compiles it again (and evicts another).
  const shaderbed::Variant& first = c->variants.front();
  EXPECT_TRUE(programs.get(*c, first, first.shaders.begin()->first).program);
  EXPECT_EQ(programs.evictions(), compiled - 1);
}

}  // namespace
