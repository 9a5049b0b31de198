// The scene perturbations on a real lit scene rendered by `candela run`: moving the
// light 5 cm, changing roughness by 0.05 and swapping the shading model must each fail the
// golden comparison; re-rendering the unchanged scene must pass it. Each runs on the scene as
// glTF and as an engine scene file. A new perturbation is one test: copy the baseline
// LitScene, change a field, expect a failure.
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>

#include "captures.h"
#include "lit_scene_file.h"
#include "lit_scene_gltf.h"

using namespace candela::golden;
using namespace candela::golden::test;
namespace fs = std::filesystem;

namespace {

enum class SceneFormat { Gltf, EngineSceneFile };

const char* formatLabel(SceneFormat format) {
    return format == SceneFormat::Gltf ? "glTF" : "scene file";
}

// Names the parameter in test output and ctest names instead of its bytes.
void PrintTo(SceneFormat format, std::ostream* out) {
    *out << (format == SceneFormat::Gltf ? "gltf" : "scene-file");
}

class ScenePerturbation : public testing::TestWithParam<SceneFormat> {
protected:
    void SetUp() override {
        dir_ = testDirectory();
        std::optional<Capture> baseline = render(LitScene{}, "baseline");
        ASSERT_TRUE(baseline);
        baseline_ = *baseline;
        ASSERT_EQ(baseline_.hdr.nonFiniteTexels, 0u);
    }

    void TearDown() override { removeIfPassed(dir_); }

    fs::path writeScene(const LitScene& scene, const std::string& name) {
        if (GetParam() == SceneFormat::EngineSceneFile) {
            std::string error;
            fs::path path = writeLitSceneFile(scene, dir_, name, error);
            EXPECT_TRUE(error.empty()) << error;
            return path;
        }
        const fs::path path = dir_ / (name + ".gltf");
        std::ofstream(path) << litSceneGltf(scene);
        return path;
    }

    std::optional<Capture> render(const LitScene& scene, const std::string& name) {
        return renderAndLoad(writeScene(scene, name).string(), "256x256", dir_, name);
    }

    // Renders the perturbed scene, prints the metrics and returns the comparison.
    CaptureComparison compareWithBaseline(const LitScene& scene, const std::string& what) {
        std::optional<Capture> changed = render(scene, "changed");
        EXPECT_TRUE(changed);
        if (!changed) return {};
        CaptureComparison c = compareCaptures(*changed, baseline_);
        report((what + " (" + formatLabel(GetParam()) + ")").c_str(), c);
        return c;
    }

    fs::path dir_;
    Capture baseline_;
};

}  // namespace

TEST_P(ScenePerturbation, UnchangedSceneRenderedAgainPasses) {
    const CaptureComparison c = compareWithBaseline(LitScene{}, "lit scene rendered again");
    EXPECT_TRUE(c.passed());
    EXPECT_EQ(c.hdr.difference.maxErrorInTolerances, 0.0);
}

TEST_P(ScenePerturbation, TheSceneIsLitNotBlack) {
    // A perturbation test on a black frame would prove nothing.
    double sum = 0;
    for (float v : baseline_.hdr.image.rgb) {
        sum += v;
    }
    EXPECT_GT(sum / double(baseline_.hdr.image.rgb.size()), 100.0);  // cd/m^2
}

TEST_P(ScenePerturbation, LightMovedFiveCentimetresFails) {
    LitScene scene;
    scene.lightPosition[0] += 0.05f;
    const CaptureComparison c = compareWithBaseline(scene, "light moved 5 cm along +x");
    EXPECT_FALSE(c.hdr.passed());
}

TEST_P(ScenePerturbation, RoughnessChangedByFiveHundredthsFails) {
    LitScene scene;
    scene.sphereRoughness += 0.05f;
    const CaptureComparison c = compareWithBaseline(scene, "sphere roughness 0.40 -> 0.45");
    EXPECT_FALSE(c.hdr.passed());
}

TEST_P(ScenePerturbation, ShadingModelSwappedFails) {
    LitScene scene;
    scene.sphereShadingModel = "legacy";  // same albedo, specular 0.04: only the model differs
    const CaptureComparison c = compareWithBaseline(scene, "sphere defaultLit -> legacy");
    EXPECT_FALSE(c.hdr.passed());
}

std::string formatName(const testing::TestParamInfo<SceneFormat>& param) {
    return param.param == SceneFormat::Gltf ? "Gltf" : "SceneFile";
}

INSTANTIATE_TEST_SUITE_P(Formats, ScenePerturbation,
                         testing::Values(SceneFormat::Gltf, SceneFormat::EngineSceneFile),
                         formatName);
