#include <gtest/gtest.h>

#include <filesystem>

#include "candela/content/asset_cache.h"

namespace candela::content {
namespace {

std::filesystem::path asset(const std::string& relative) {
    return std::filesystem::path(CANDELA_SHARED_ASSETS) / relative;
}

TEST(AssetCache, AMeshOrTextureUsedTwiceIsLoadedOnce) {
    AssetCache cache;
    Diagnostics diagnostics;
    auto a = cache.mesh(asset("models/BoxTextured/BoxTextured.glb"), 0, diagnostics);
    // A different spelling of the same file hits the same entry.
    auto b = cache.mesh(asset("models/Box/../BoxTextured/./BoxTextured.glb"), 0, diagnostics);
    ASSERT_TRUE(a);
    EXPECT_EQ(a.get(), b.get());
    auto srgb1 = cache.texture(asset("models/BoxTextured/BoxTextured.glb"), 0, ColorSpace::Srgb,
                               diagnostics);
    auto srgb2 = cache.texture(asset("models/BoxTextured/BoxTextured.glb"), 0, ColorSpace::Srgb,
                               diagnostics);
    auto linear = cache.texture(asset("models/BoxTextured/BoxTextured.glb"), 0, ColorSpace::Linear,
                                diagnostics);
    ASSERT_TRUE(srgb1 && linear);
    EXPECT_EQ(srgb1.get(), srgb2.get());
    EXPECT_NE(srgb1.get(), linear.get()) << "colour space is part of the key";
    EXPECT_EQ(srgb1->mips.size(), 9u) << "256 -> 1 is 9 levels";
    EXPECT_EQ(srgb1->colorSpace, ColorSpace::Srgb);
    const AssetCache::Stats stats = cache.stats();
    EXPECT_EQ(stats.modelLoads, 1u);
    EXPECT_EQ(stats.textureBuilds, 2u);
    EXPECT_GE(stats.hits, 3u);
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
}

TEST(AssetCache, MissingFilesAndIndicesAreReportedOnce) {
    AssetCache cache;
    Diagnostics diagnostics;
    EXPECT_FALSE(cache.mesh("/no/such/model.glb", 0, diagnostics));
    EXPECT_FALSE(cache.mesh("/no/such/model.glb", 0, diagnostics));
    EXPECT_EQ(diagnostics.count(Severity::Error), 1u) << diagnostics.toString();
    EXPECT_EQ(cache.stats().modelLoads, 1u);
    Diagnostics indexDiagnostics;
    EXPECT_FALSE(cache.mesh(asset("models/Box/Box.glb"), 5, indexDiagnostics));
    EXPECT_TRUE(indexDiagnostics.mentions("meshes[5]"));
}

TEST(AssetCache, EnvironmentsAreCachedToo) {
    AssetCache cache;
    Diagnostics diagnostics;
    auto a = cache.environment(asset("env/studio_small_03_1k.exr"), diagnostics);
    auto b = cache.environment(asset("env/studio_small_03_1k.exr"), diagnostics);
    ASSERT_TRUE(a);
    EXPECT_EQ(a.get(), b.get());
    EXPECT_EQ(cache.stats().environmentLoads, 1u);
}

}  // namespace
}  // namespace candela::content
