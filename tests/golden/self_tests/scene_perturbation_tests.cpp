// The scene perturbations on a real lit scene rendered by `candela run`: moving the
// light 5 cm, changing roughness by 0.05 and swapping the shading model must each fail the
// golden comparison; re-rendering the unchanged scene must pass it. New perturbations are one
// test each: copy the baseline LitScene, change a field, expect a failure.
#include <gtest/gtest.h>

#include <fstream>

#include "captures.h"
#include "lit_scene_gltf.h"

using namespace candela::golden;
using namespace candela::golden::test;
namespace fs = std::filesystem;

namespace {

class ScenePerturbation : public testing::Test {
protected:
    void SetUp() override {
        dir_ = testDirectory();
        std::optional<Capture> baseline = render(LitScene{}, "baseline");
        ASSERT_TRUE(baseline);
        baseline_ = *baseline;
        ASSERT_EQ(baseline_.hdr.nonFiniteTexels, 0u);
    }

    std::optional<Capture> render(const LitScene& scene, const std::string& name) {
        const fs::path gltf = dir_ / (name + ".gltf");
        std::ofstream(gltf) << litSceneGltf(scene);
        return renderAndLoad(gltf.string(), "256x256", dir_, name);
    }

    // Renders the perturbed scene, prints the metrics and returns the comparison.
    CaptureComparison compareWithBaseline(const LitScene& scene, const char* what) {
        std::optional<Capture> changed = render(scene, "changed");
        EXPECT_TRUE(changed);
        if (!changed) return {};
        CaptureComparison c = compareCaptures(*changed, baseline_);
        report(what, c);
        return c;
    }

    void TearDown() override { removeIfPassed(dir_); }

    fs::path dir_;
    Capture baseline_;
};

}  // namespace

TEST_F(ScenePerturbation, UnchangedSceneRenderedAgainPasses) {
    const CaptureComparison c = compareWithBaseline(LitScene{}, "lit scene rendered again");
    EXPECT_TRUE(c.passed());
    EXPECT_EQ(c.hdr.difference.maxErrorInTolerances, 0.0);
}

TEST_F(ScenePerturbation, TheSceneIsLitNotBlack) {
    // A perturbation test on a black frame would prove nothing.
    double sum = 0;
    for (float v : baseline_.hdr.image.rgb)
        sum += v;
    EXPECT_GT(sum / double(baseline_.hdr.image.rgb.size()), 100.0);  // cd/m^2
}

TEST_F(ScenePerturbation, LightMovedFiveCentimetresFails) {
    LitScene scene;
    scene.lightPosition[0] += 0.05f;
    const CaptureComparison c = compareWithBaseline(scene, "light moved 5 cm along +x");
    EXPECT_FALSE(c.hdr.passed());
}

TEST_F(ScenePerturbation, RoughnessChangedByFiveHundredthsFails) {
    LitScene scene;
    scene.sphereRoughness += 0.05f;
    const CaptureComparison c = compareWithBaseline(scene, "sphere roughness 0.40 -> 0.45");
    EXPECT_FALSE(c.hdr.passed());
}

TEST_F(ScenePerturbation, ShadingModelSwappedFails) {
    LitScene scene;
    scene.sphereShadingModel = "legacy";  // same albedo, specular 0.04: only the model differs
    const CaptureComparison c = compareWithBaseline(scene, "sphere defaultLit -> legacy");
    EXPECT_FALSE(c.hdr.passed());
}
