#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <limits>

#include "candela/content/component_validation.h"
#include "candela/content/scene_file.h"
#include "test_paths.h"

namespace candela::content {
namespace {

// Values chosen so a decimal round trip through too few digits would change them.
SceneDocument exampleScene() {
    SceneDocument scene;
    SceneEntity& root = scene.entities.emplace_back();
    root.name = "root";
    root.transform.translation = {0.1f, 1.0f / 3.0f, -2.7182817f};
    root.transform.rotation = {0.0f, 0.38268343f, 0.0f, 0.9238795f};
    root.transform.scale = {1e-7f, 3.4e38f, 1.17549435e-38f};
    root.sky = Sky{"env/studio_small_03_1k.exr", 0.75f};
    root.gameDataJson = R"({"level":3,"spawn":{"x":1.5},"tags":["a","b"]})";  // canonical form

    SceneEntity& helmet = scene.entities.emplace_back();
    helmet.name = "helmet \"quoted\" ünïcode";
    helmet.parent = 0;
    helmet.mesh = MeshReference{"models/DamagedHelmet/DamagedHelmet.glb", 0};
    MaterialOverride override;
    override.primitive = 0;
    override.material.name = "red";
    override.material.baseColorFactor = {0.9f, 0.1f, 0.1f, 1.0f};
    override.material.shadingModel = ShadingModel::Subsurface;
    override.material.alphaMode = AlphaMode::Mask;
    override.material.normalTexture.texture = 4;
    override.material.normalTexture.transform.rotation = 0.1f;
    helmet.materialOverrides.push_back(override);

    SceneEntity& lamp = scene.entities.emplace_back();
    lamp.name = "lamp";
    lamp.parent = 1;
    Light light;
    light.type = LightType::Spot;
    light.lumens = 1234.5678f;
    light.sourceLength = 0.3f;
    light.color = {1.0f, 0.9f, 0.8f};
    lamp.light = light;

    SceneEntity& eye = scene.entities.emplace_back();
    eye.name = "camera";
    Camera camera;
    camera.exposureMode = ExposureMode::Manual;
    camera.manualEv100 = 12.25f;
    camera.projection = Projection::Orthographic;
    eye.camera = camera;
    return scene;
}

template <std::size_t N>
bool bitEqual(const std::array<float, N>& a, const std::array<float, N>& b) {
    return std::memcmp(a.data(), b.data(), sizeof(float) * N) == 0;
}

// Component-by-component comparison, floats compared bit for bit.
void expectIdentical(const SceneDocument& a, const SceneDocument& b) {
    ASSERT_EQ(a.entities.size(), b.entities.size());
    for (std::size_t i = 0; i < a.entities.size(); ++i) {
        const SceneEntity& x = a.entities[i];
        const SceneEntity& y = b.entities[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.parent, y.parent);
        EXPECT_TRUE(bitEqual(x.transform.translation, y.transform.translation)) << i;
        EXPECT_TRUE(bitEqual(x.transform.rotation, y.transform.rotation)) << i;
        EXPECT_TRUE(bitEqual(x.transform.scale, y.transform.scale)) << i;
        EXPECT_EQ(x.mesh, y.mesh);
        ASSERT_EQ(x.materialOverrides.size(), y.materialOverrides.size());
        for (std::size_t m = 0; m < x.materialOverrides.size(); ++m) {
            const Material& p = x.materialOverrides[m].material;
            const Material& q = y.materialOverrides[m].material;
            EXPECT_EQ(p.name, q.name);
            EXPECT_TRUE(bitEqual(p.baseColorFactor, q.baseColorFactor));
            EXPECT_EQ(p.shadingModel, q.shadingModel);
            EXPECT_EQ(p.alphaMode, q.alphaMode);
            EXPECT_EQ(p.normalTexture.texture, q.normalTexture.texture);
            EXPECT_EQ(p.normalTexture.transform.rotation, q.normalTexture.transform.rotation);
            EXPECT_EQ(p.specular, q.specular);
        }
        ASSERT_EQ(x.light.has_value(), y.light.has_value());
        if (x.light) {
            const Light& l = *x.light;
            const Light& k = *y.light;
            EXPECT_EQ(l.type, k.type);
            EXPECT_TRUE(bitEqual(l.color, k.color));
            EXPECT_TRUE(bitEqual(std::array{l.lumens, l.lux, l.attenuationRadius, l.sourceRadius,
                                            l.sourceLength, l.innerConeAngle, l.outerConeAngle},
                                 std::array{k.lumens, k.lux, k.attenuationRadius, k.sourceRadius,
                                            k.sourceLength, k.innerConeAngle, k.outerConeAngle}));
        }
        ASSERT_EQ(x.camera.has_value(), y.camera.has_value());
        if (x.camera) {
            const Camera& c = *x.camera;
            const Camera& d = *y.camera;
            EXPECT_EQ(c.projection, d.projection);
            EXPECT_EQ(c.exposureMode, d.exposureMode);
            EXPECT_TRUE(bitEqual(std::array{c.verticalFov, c.nearPlane, c.farPlane,
                                            c.orthographicHalfHeight, c.aperture, c.shutterSeconds,
                                            c.iso, c.manualEv100, c.exposureCompensation},
                                 std::array{d.verticalFov, d.nearPlane, d.farPlane,
                                            d.orthographicHalfHeight, d.aperture, d.shutterSeconds,
                                            d.iso, d.manualEv100, d.exposureCompensation}));
        }
        ASSERT_EQ(x.sky.has_value(), y.sky.has_value());
        if (x.sky) {
            EXPECT_EQ(x.sky->exrPath, y.sky->exrPath);
            EXPECT_EQ(x.sky->intensity, y.sky->intensity);
        }
        EXPECT_EQ(x.gameDataJson, y.gameDataJson);
    }
}

TEST(SceneFile, SaveLoadSaveRoundTripsBitExactly) {
    const auto path = testing::tempPath("level.scene.json");
    const SceneDocument original = exampleScene();
    ASSERT_EQ(saveSceneFile(path, original), "");
    Diagnostics diagnostics;
    auto loaded = loadSceneFile(path, diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    expectIdentical(original, *loaded);

    // Saving what was loaded gives the same bytes: nothing drifts across generations.
    std::string error;
    EXPECT_EQ(sceneToJson(*loaded, error), sceneToJson(original, error));
}

// Issue 21: material overrides keep the anisotropy and clear-coat fields through save and load;
// a material without them writes none of their keys (older files re-save byte for byte).
TEST(SceneFile, MaterialExtensionsRoundTripAndAreOnlyWrittenWhenUsed) {
    SceneDocument scene = exampleScene();
    std::string error;
    const std::string plain = sceneToJson(scene, error);
    EXPECT_EQ(plain.find("anisotropy"), std::string::npos);
    EXPECT_EQ(plain.find("clearcoat"), std::string::npos);

    Material& m = scene.entities[1].materialOverrides[0].material;
    m.anisotropyStrength = 0.75f;
    m.anisotropyRotation = 0.3f;
    m.anisotropyTexture.texture = 2;
    m.clearcoatFactor = 0.9f;
    m.clearcoatRoughnessFactor = 0.05f;
    m.clearcoatNormalTexture.texture = 3;
    m.clearcoatNormalScale = 0.5f;
    const auto path = testing::tempPath("coated.scene.json");
    ASSERT_EQ(saveSceneFile(path, scene), "");
    Diagnostics diagnostics;
    auto loaded = loadSceneFile(path, diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    const Material& r = loaded->entities[1].materialOverrides[0].material;
    EXPECT_EQ(r.anisotropyStrength, 0.75f);
    EXPECT_EQ(r.anisotropyRotation, 0.3f);
    EXPECT_EQ(r.anisotropyTexture.texture, 2);
    EXPECT_EQ(r.clearcoatFactor, 0.9f);
    EXPECT_EQ(r.clearcoatRoughnessFactor, 0.05f);
    EXPECT_EQ(r.clearcoatNormalTexture.texture, 3);
    EXPECT_EQ(r.clearcoatNormalScale, 0.5f);
    EXPECT_EQ(sceneToJson(*loaded, error), sceneToJson(scene, error));
}

// Issue 21: the layer library and a material's layers (each a library layer, changed or not)
// and mask survive save and load bit for bit; scenes without layers write neither.
TEST(SceneFile, MaterialLayersRoundTripAndAreOnlyWrittenWhenUsed) {
    SceneDocument scene = exampleScene();
    std::string error;
    const std::string plain = sceneToJson(scene, error);
    EXPECT_EQ(plain.find("layer"), std::string::npos);

    MaterialLayer paint;
    paint.name = "painted_metal";
    paint.baseColorFactor = {0.1f, 0.3f, 0.8f, 1.0f};
    paint.metallicFactor = 1.0f;
    paint.roughnessFactor = 0.3f;
    MaterialLayer rust;
    rust.name = "rust";
    rust.roughnessFactor = 0.9f;
    rust.baseColorTexture.texture = 1;
    rust.normalTexture.texture = 2;
    rust.normalScale = 0.7f;
    rust.uvScale = {8.0f, 6.5f};
    scene.materialLayers = {paint, rust};
    Material& m = scene.entities[1].materialOverrides[0].material;
    m.layering.layers = {paint, rust};
    m.layering.layers[1].roughnessFactor = 0.8f;  // this material's rust is a little smoother
    m.layering.maskTexture.texture = 3;
    m.layering.maskTexture.transform.scale = {2.0f, 2.0f};
    const auto path = testing::tempPath("layered.scene.json");
    ASSERT_EQ(saveSceneFile(path, scene), "");
    Diagnostics diagnostics;
    auto loaded = loadSceneFile(path, diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    ASSERT_EQ(loaded->materialLayers.size(), 2u);
    EXPECT_EQ(loaded->materialLayers[1].name, "rust");
    EXPECT_EQ(loaded->materialLayers[1].roughnessFactor, 0.9f);
    EXPECT_EQ(loaded->materialLayers[1].uvScale[1], 6.5f);
    const MaterialLayering& r = loaded->entities[1].materialOverrides[0].material.layering;
    ASSERT_EQ(r.layers.size(), 2u);
    EXPECT_EQ(r.layers[0].name, "painted_metal");
    EXPECT_EQ(r.layers[0].baseColorFactor[2], 0.8f);
    EXPECT_EQ(r.layers[1].roughnessFactor, 0.8f);
    EXPECT_EQ(r.layers[1].normalTexture.texture, 2);
    EXPECT_EQ(r.layers[1].uvScale[0], 8.0f);
    EXPECT_EQ(r.maskSource, LayerMaskSource::Texture);
    EXPECT_EQ(r.maskTexture.texture, 3);
    EXPECT_EQ(r.maskTexture.transform.scale[0], 2.0f);
    EXPECT_EQ(sceneToJson(*loaded, error), sceneToJson(scene, error));
}

// Unknown layer names, too many layers and a texture mask without a texture are errors naming
// the file, the JSON pointer and the material; only that material override is dropped.
TEST(SceneFile, BadMaterialLayersAreNamedAndDropOnlyThatMaterial) {
    const std::string text = R"({
      "format": "candela.scene", "version": 1,
      "materialLayers": [{"name": "paint", "metallicFactor": 1}, {"name": "rust"},
                         {"name": "grime", "uvScale": [0, 1]}],
      "entities": [
        {"name": "a", "mesh": {"gltf": "x.glb"}, "materialOverrides": [{"primitive": 0,
          "material": {"name": "typo", "layers": [{"layer": "paint"}, {"layer": "russt"}],
                       "layerMask": {"source": "vertexColor"}}}]},
        {"name": "b", "mesh": {"gltf": "x.glb"}, "materialOverrides": [{"primitive": 0,
          "material": {"name": "five", "layers": [{"layer": "paint"}, {"layer": "rust"},
            {"layer": "rust"}, {"layer": "rust"}, {"layer": "rust"}]}}]},
        {"name": "c", "mesh": {"gltf": "x.glb"}, "materialOverrides": [{"primitive": 0,
          "material": {"name": "unmasked", "layers": [{"layer": "paint"}, {"layer": "rust"}]}}]},
        {"name": "d", "mesh": {"gltf": "x.glb"}, "materialOverrides": [{"primitive": 0,
          "material": {"name": "fine", "layers": [{"layer": "paint"}, {"layer": "rust"}],
                       "layerMask": {"texture": {"texture": 0}}}}]}
      ]})";
    Diagnostics d;
    auto parsed = parseSceneJson(std::as_bytes(std::span(text)), "l.json", d);
    ASSERT_TRUE(parsed) << d.toString();
    EXPECT_TRUE(d.mentions("l.json: /materialLayers/2/uvScale: error")) << d.toString();
    EXPECT_EQ(parsed->materialLayers.size(), 2u);
    EXPECT_TRUE(
        d.mentions("l.json: /entities/0/materialOverrides/0/material/layers/1/layer: "
                   "error: material 'typo': unknown layer 'russt' (the scene's "
                   "\"materialLayers\" library has: paint, rust)"))
        << d.toString();
    EXPECT_TRUE(
        d.mentions("/entities/1/materialOverrides/0/material/layers: error: material "
                   "'five' has 5 layers; at most 4"))
        << d.toString();
    EXPECT_TRUE(
        d.mentions("/entities/2/materialOverrides/0/material/layerMask/texture: error: "
                   "material 'unmasked' blends 1 layer(s) over its base by a texture "
                   "mask but names no mask texture"))
        << d.toString();
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(parsed->entities[size_t(i)].materialOverrides.empty()) << i;
    ASSERT_EQ(parsed->entities[3].materialOverrides.size(), 1u);
    EXPECT_EQ(parsed->entities[3].materialOverrides[0].material.layering.layers.size(), 2u);
    EXPECT_EQ(parsed->entities[3].mesh->gltfPath, "x.glb");  // the entity itself stays
}

// Issue 25: a material override's cavity survives save and load, is written only when not 1,
// and a value outside [0, 1] is clamped with a warning naming the file, pointer and material.
TEST(SceneFile, CavityRoundTripsOnlyWhenSetAndOutOfRangeIsClampedWithAWarning) {
    SceneDocument scene = exampleScene();
    std::string error;
    EXPECT_EQ(sceneToJson(scene, error).find("cavity"), std::string::npos);
    scene.entities[1].materialOverrides[0].material.cavity = 0.375f;
    const auto path = testing::tempPath("cavity.scene.json");
    ASSERT_EQ(saveSceneFile(path, scene), "");
    Diagnostics diagnostics;
    auto loaded = loadSceneFile(path, diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_EQ(loaded->entities[1].materialOverrides[0].material.cavity, 0.375f);
    EXPECT_EQ(sceneToJson(*loaded, error), sceneToJson(scene, error));

    const std::string text = R"({
      "format": "candela.scene", "version": 1,
      "entities": [
        {"name": "pitted", "mesh": {"gltf": "x.glb"}, "materialOverrides": [{"primitive": 0,
          "material": {"name": "stone", "cavity": -0.5}}]}
      ]})";
    Diagnostics bad;
    auto parsed = parseSceneJson(std::as_bytes(std::span(text)), "c.json", bad);
    ASSERT_TRUE(parsed) << bad.toString();
    ASSERT_EQ(parsed->entities[0].materialOverrides.size(), 1u);
    EXPECT_EQ(parsed->entities[0].materialOverrides[0].material.cavity, 0.0f);
    EXPECT_TRUE(
        bad.mentions("c.json: /entities/0/materialOverrides/0/material/cavity: warning: "
                     "cavity of material 'stone'"))
        << bad.toString();
}

// Issue 26: the top-level "brdf" survives save and load; a misspelt value is an error naming
// the file and /brdf, and the scene still loads with the engine's default.
TEST(SceneFile, BrdfSettingRoundTripsAndABadValueIsNamed) {
    SceneDocument scene = exampleScene();
    scene.settings.brdf = BrdfModel::Ue4;
    std::string error;
    const std::string text = sceneToJson(scene, error);
    ASSERT_EQ(error, "");
    EXPECT_NE(text.find("\"brdf\": \"ue4\""), std::string::npos) << text;
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "ue4.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_EQ(loaded->settings.brdf, BrdfModel::Ue4);
    EXPECT_FALSE(exampleScene().settings.brdf.has_value());

    const std::string bad =
        R"({"format": "candela.scene", "version": 1, "brdf": "phong", "entities": []})";
    Diagnostics badDiagnostics;
    auto fallback =
        parseSceneJson(std::as_bytes(std::span(bad)), "phong.scene.json", badDiagnostics);
    ASSERT_TRUE(fallback);
    EXPECT_FALSE(fallback->settings.brdf.has_value());
    EXPECT_TRUE(badDiagnostics.hasErrors());
    EXPECT_TRUE(badDiagnostics.mentions("phong.scene.json")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/brdf")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("energy-conserving")) << badDiagnostics.toString();
}

// Issue 24: the top-level "aa", "msaa" and "bloom" survive save and load, as do "ssr" (issue
// 18), "scattering" (16) and "volumetrics" (17); bad values are named.
TEST(SceneFile, AntiAliasingAndBloomSettingsRoundTripAndBadValuesAreNamed) {
    SceneDocument scene = exampleScene();
    scene.settings.aa = AntiAliasing::Fxaa;
    scene.settings.msaaSamples = 4u;
    scene.settings.bloomStrength = 0.0f;  // the scene turns bloom off
    scene.settings.exposure = FrameExposure::Auto;
    scene.settings.exposureCompensation = -0.5f;
    scene.settings.ssr = SsrMode::Hiz;  // issue 18
    scene.settings.scattering = ScatteringMode::BruteForce;
    scene.settings.volumetrics = VolumetricsMode::Froxels;
    scene.settings.volumeProxies = true;
    std::string error;
    const std::string text = sceneToJson(scene, error);
    ASSERT_EQ(error, "");
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "aa.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_EQ(loaded->settings.aa, AntiAliasing::Fxaa);
    EXPECT_EQ(loaded->settings.msaaSamples, 4u);
    EXPECT_EQ(loaded->settings.bloomStrength, 0.0f);
    EXPECT_EQ(loaded->settings.exposure, FrameExposure::Auto);
    EXPECT_EQ(loaded->settings.exposureCompensation, -0.5f);
    EXPECT_EQ(loaded->settings.ssr, SsrMode::Hiz);
    EXPECT_EQ(loaded->settings.scattering, ScatteringMode::BruteForce);
    EXPECT_EQ(loaded->settings.volumetrics, VolumetricsMode::Froxels);
    EXPECT_EQ(loaded->settings.volumeProxies, true);
    EXPECT_NE(text.find("\"scattering\": \"brute-force\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"volume_proxies\": \"on\""), std::string::npos) << text;
    // Either spelling reads: JSON's booleans and the command line's words.
    for (const auto& [value, proxies] :
         {std::pair{"false", false}, std::pair{"\"on\"", true}, std::pair{"\"off\"", false}}) {
        const std::string spelt = std::string(R"({"format": "candela.scene", "version": 1, )") +
                                  R"("volume_proxies": )" + value + R"(, "entities": []})";
        Diagnostics spelling;
        auto read = parseSceneJson(std::as_bytes(std::span(spelt)), "p.scene.json", spelling);
        ASSERT_TRUE(read) << spelling.toString();
        EXPECT_TRUE(spelling.messages.empty()) << spelling.toString();
        EXPECT_EQ(read->settings.volumeProxies, proxies) << value;
    }

    const std::string bad = R"({"format": "candela.scene", "version": 1, "aa": "msaa8",
                               "msaa": 3, "bloom": 3, "ssr": "raymarch",
                               "scattering": "on", "volumetrics": 2,
                               "volume_proxies": "yes", "entities": []})";
    Diagnostics badDiagnostics;
    auto fallback = parseSceneJson(std::as_bytes(std::span(bad)), "bad.scene.json", badDiagnostics);
    ASSERT_TRUE(fallback);
    EXPECT_FALSE(fallback->settings.aa.has_value());
    EXPECT_FALSE(fallback->settings.msaaSamples.has_value());
    EXPECT_FALSE(fallback->settings.bloomStrength.has_value());
    EXPECT_TRUE(badDiagnostics.mentions("bad.scene.json")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/aa")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/msaa")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/bloom")) << badDiagnostics.toString();
    EXPECT_FALSE(fallback->settings.ssr.has_value());
    EXPECT_TRUE(badDiagnostics.mentions("/ssr")) << badDiagnostics.toString();
    EXPECT_FALSE(fallback->settings.scattering.has_value());
    EXPECT_FALSE(fallback->settings.volumetrics.has_value());
    EXPECT_TRUE(badDiagnostics.mentions("/scattering")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("brute-force")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/volumetrics")) << badDiagnostics.toString();
    EXPECT_FALSE(fallback->settings.volumeProxies.has_value());
    EXPECT_TRUE(badDiagnostics.mentions("/volume_proxies")) << badDiagnostics.toString();
}

// Issue 41: the top-level "quality" survives save and load; a bad value is named with the
// levels.
TEST(SceneFile, QualityRoundTripsAndBadValuesAreNamed) {
    SceneDocument scene = exampleScene();
    scene.quality = QualityLevel::Low;
    std::string error;
    const std::string text = sceneToJson(scene, error);
    ASSERT_EQ(error, "");
    EXPECT_NE(text.find("\"quality\": \"low\""), std::string::npos) << text;
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "q.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_EQ(loaded->quality, QualityLevel::Low);

    const std::string bad =
        R"({"format": "candela.scene", "version": 1, "quality": "epic", "entities": []})";
    Diagnostics badDiagnostics;
    auto fallback = parseSceneJson(std::as_bytes(std::span(bad)), "bad.scene.json", badDiagnostics);
    ASSERT_TRUE(fallback);
    EXPECT_FALSE(fallback->quality.has_value());
    EXPECT_TRUE(badDiagnostics.mentions("/quality")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("ultra")) << badDiagnostics.toString();
}

// Issue 44: "exposure_compensation" takes the range --exposure-compensation takes; +-3e38 was
// accepted. A value outside it is named and the scene loads without it.
TEST(SceneFile, ExposureCompensationOutsideSixteenEvIsNamed) {
    for (const char* value : {"3e38", "-3e38", "16.5"}) {
        const std::string bad = std::string(R"({"format": "candela.scene", "version": 1, )") +
                                R"("exposure_compensation": )" + value + R"(, "entities": []})";
        Diagnostics diagnostics;
        auto scene = parseSceneJson(std::as_bytes(std::span(bad)), "e.scene.json", diagnostics);
        ASSERT_TRUE(scene) << value;
        EXPECT_FALSE(scene->settings.exposureCompensation.has_value()) << value;
        EXPECT_TRUE(
            diagnostics.mentions("/exposure_compensation: error: expected EV from -16 to 16"))
            << diagnostics.toString();
    }
    const std::string fine =
        R"({"format": "candela.scene", "version": 1, "exposure_compensation": -16, "entities": []})";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(fine)), "e.scene.json", diagnostics);
    ASSERT_TRUE(scene);
    EXPECT_EQ(scene->settings.exposureCompensation, -16.0f);
}

// Issue 44: unknown keys were ignored without a word. Each is a warning naming its JSON
// pointer and, when one is near, the known key meant; the scene loads as before. A written
// scene reads back without one, and "gameData" is the game's to check.
TEST(SceneFile, UnknownKeysAreNamedWithTheClosestKnownKey) {
    const std::string text = R"({"format": "candela.scene", "version": 1, "qualty": "low",
      "entities": [
        {"name": "a", "transform": {"translaton": [1, 2, 3]}, "script": {"file": "a.lua"},
         "light": {"type": "point", "lumen": 5}, "gameData": {"anything": 1}}]})";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(text)), "k.scene.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.toString();
    ASSERT_EQ(scene->entities.size(), 1u);
    EXPECT_TRUE(scene->entities[0].light.has_value());
    EXPECT_EQ(scene->entities[0].transform.translation, (std::array<float, 3>{0, 0, 0}));
    for (const char* expected :
         {"/qualty: warning: unknown key 'qualty', ignored (did you mean 'quality'?)",
          "/entities/0/transform/translaton: warning: unknown key 'translaton', ignored (did "
          "you mean 'translation'?)",
          "/entities/0/light/lumen: warning: unknown key 'lumen', ignored (did you mean "
          "'lumens'?)",
          "/entities/0/script: warning: unknown key 'script', ignored"}) {
        EXPECT_TRUE(diagnostics.mentions(expected)) << expected << "\n" << diagnostics.toString();
    }
    EXPECT_FALSE(diagnostics.mentions("anything")) << diagnostics.toString();

    std::string error;
    const std::string written = sceneToJson(exampleScene(), error);
    ASSERT_EQ(error, "");
    Diagnostics clean;
    ASSERT_TRUE(parseSceneJson(std::as_bytes(std::span(written)), "w.scene.json", clean));
    EXPECT_FALSE(clean.mentions("unknown key")) << clean.toString();
}

// Issue 44: material overrides in scene files skipped the range checks glTF's importer applies
// (anisotropyStrength 3e38 or -5, clearcoatFactor 3e38 were taken). Factors on [0, 1] are
// clamped with a warning naming the field.
TEST(SceneFile, MaterialFactorsOutsideZeroToOneAreClampedWithAWarning) {
    const std::string text = R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "m", "mesh": {"builtin": "box", "material": {"name": "odd",
          "anisotropyStrength": 3e38, "clearcoatFactor": 3e38, "roughnessFactor": -5,
          "metallicFactor": 0.5}}}]})";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(text)), "m.scene.json", diagnostics);
    ASSERT_TRUE(scene) << diagnostics.toString();
    ASSERT_EQ(scene->entities[0].materialOverrides.size(), 1u) << diagnostics.toString();
    const Material& m = scene->entities[0].materialOverrides[0].material;
    EXPECT_EQ(m.anisotropyStrength, 1.0f);
    EXPECT_EQ(m.clearcoatFactor, 1.0f);
    EXPECT_EQ(m.roughnessFactor, 0.0f);
    EXPECT_EQ(m.metallicFactor, 0.5f);
    for (const char* field : {"anisotropyStrength", "clearcoatFactor", "roughnessFactor"}) {
        EXPECT_TRUE(diagnostics.mentions(std::string("/entities/0/mesh/material/") + field +
                                         ": warning: " + field + " of material 'odd'"))
            << field << "\n"
            << diagnostics.toString();
    }
    EXPECT_FALSE(diagnostics.mentions("metallicFactor")) << diagnostics.toString();
}

// Issue 44: a quaternion whose length overflows is not called a zero quaternion.
TEST(SceneFile, OverflowingQuaternionIsNamedAsSuch) {
    const std::string text = R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "huge", "transform": {"rotation": [3e38, 0, 0, 3e38]}}]})";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(text)), "r.scene.json", diagnostics);
    ASSERT_TRUE(scene);
    EXPECT_TRUE(
        diagnostics.mentions("/entities/0/transform/rotation: error: its length is not a "
                             "finite number"))
        << diagnostics.toString();
    EXPECT_FALSE(diagnostics.mentions("zero quaternion")) << diagnostics.toString();
    EXPECT_EQ(scene->entities[0].transform.rotation, (std::array<float, 4>{0, 0, 0, 1}));
}

// Sky occlusion: the top-level "sky_occlusion" survives save and load; a bad value is named
// and the scene loads with the engine's default.
TEST(SceneFile, SkyOcclusionSettingRoundTripsAndBadValuesAreNamed) {
    SceneDocument scene = exampleScene();
    scene.settings.skyOcclusion = SkyOcclusionMode::Reference;
    std::string error;
    const std::string text = sceneToJson(scene, error);
    ASSERT_EQ(error, "");
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "sky.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_EQ(loaded->settings.skyOcclusion, SkyOcclusionMode::Reference);

    const std::string bad = R"({"format": "candela.scene", "version": 1,
                               "sky_occlusion": "always", "entities": []})";
    Diagnostics badDiagnostics;
    auto fallback = parseSceneJson(std::as_bytes(std::span(bad)), "bad.scene.json", badDiagnostics);
    ASSERT_TRUE(fallback);
    EXPECT_FALSE(fallback->settings.skyOcclusion.has_value());
    EXPECT_TRUE(badDiagnostics.mentions("bad.scene.json")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/sky_occlusion")) << badDiagnostics.toString();
}

// Issue 25: the top-level "ambient_occlusion" (mode, radius, intensity) survives save and
// load; bad values are errors naming the file and the field, and the scene still loads with
// the defaults for them.
TEST(SceneFile, AmbientOcclusionSettingRoundTripsAndBadValuesAreNamed) {
    SceneDocument scene = exampleScene();
    scene.settings.ao = AoMode::Reference;
    scene.ambientOcclusion = SceneAmbientOcclusion{2.5f, 0.75f};
    std::string error;
    const std::string text = sceneToJson(scene, error);
    ASSERT_EQ(error, "");
    EXPECT_NE(text.find("\"ambient_occlusion\""), std::string::npos) << text;
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "ao.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_EQ(loaded->ambientOcclusion, scene.ambientOcclusion);
    EXPECT_EQ(loaded->settings.ao, AoMode::Reference);
    EXPECT_FALSE(exampleScene().ambientOcclusion.has_value());

    const std::string bad = R"({"format": "candela.scene", "version": 1, "entities": [],
        "ambient_occlusion": {"mode": "ssao", "radius": -1, "intensity": 2}})";
    Diagnostics badDiagnostics;
    auto fallback =
        parseSceneJson(std::as_bytes(std::span(bad)), "bad_ao.scene.json", badDiagnostics);
    ASSERT_TRUE(fallback);
    ASSERT_TRUE(fallback->ambientOcclusion.has_value());
    EXPECT_FALSE(fallback->settings.ao.has_value());
    EXPECT_EQ(fallback->ambientOcclusion->radius, SceneAmbientOcclusion{}.radius);
    EXPECT_EQ(fallback->ambientOcclusion->intensity, SceneAmbientOcclusion{}.intensity);
    EXPECT_TRUE(badDiagnostics.mentions("bad_ao.scene.json")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/ambient_occlusion/mode")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("gtao")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/ambient_occlusion/radius")) << badDiagnostics.toString();
    EXPECT_TRUE(badDiagnostics.mentions("/ambient_occlusion/intensity"))
        << badDiagnostics.toString();
}

TEST(SceneFile, RefusesToSaveNonFiniteValuesAndKeepsTheOldFile) {
    const auto path = testing::tempPath("level.scene.json");
    ASSERT_EQ(saveSceneFile(path, exampleScene()), "");
    SceneDocument bad = exampleScene();
    bad.entities[2].light->lumens = std::numeric_limits<float>::infinity();
    const std::string error = saveSceneFile(path, bad);
    EXPECT_NE(error.find("/entities/2/light/lumens"), std::string::npos) << error;
    Diagnostics diagnostics;
    auto loaded = loadSceneFile(path, diagnostics);
    ASSERT_TRUE(loaded);
    expectIdentical(exampleScene(), *loaded);
}

TEST(SceneFile, KilledSaveLeavesAPreviousCompleteFile) {
    const auto path = testing::tempPath("killed.scene.json");
    SceneDocument big = exampleScene();
    for (int i = 0; i < 20000; ++i)
        big.entities.push_back(big.entities[2]);  // ~ several MB
    ASSERT_EQ(saveSceneFile(path, exampleScene()), "");
    for (int attempt = 0; attempt < 5; ++attempt) {
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            for (;;)
                (void)saveSceneFile(path, (attempt % 2) ? big : exampleScene());
        }
        usleep(static_cast<useconds_t>(20000 + 15000 * attempt));
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        Diagnostics diagnostics;
        auto loaded = loadSceneFile(path, diagnostics);
        ASSERT_TRUE(loaded) << "attempt " << attempt << ": " << diagnostics.toString();
        EXPECT_FALSE(diagnostics.hasErrors());
        EXPECT_TRUE(loaded->entities.size() == 4 || loaded->entities.size() == big.entities.size());
    }
}

TEST(SceneFile, AssetPathsResolveAgainstTheSceneFile) {
    EXPECT_EQ(resolveScenePath("/levels/one/level.json", "models/a.glb"),
              std::filesystem::path("/levels/one/models/a.glb"));
    EXPECT_EQ(resolveScenePath("/levels/one/level.json", "/abs/b.glb"),
              std::filesystem::path("/abs/b.glb"));
}

TEST(SceneFile, BadJsonNamesFileAndPosition) {
    const std::string text = "{\n  \"format\": \"candela.scene\",\n  \"version\": 1,\n  oops\n}";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(text)), "broken.scene.json", diagnostics);
    EXPECT_FALSE(scene);
    EXPECT_TRUE(diagnostics.mentions("broken.scene.json")) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.mentions("line 4")) << diagnostics.toString();
}

TEST(SceneFile, InvalidUtf8NamesAreASaveErrorNotAnException) {
    SceneDocument scene = exampleScene();
    scene.entities[0].name = "bad \xff\xfe utf-8";
    EXPECT_NE(saveSceneFile(testing::tempPath("utf8.json"), scene), "");
}

TEST(SceneFile, HugeNumbersAreAnErrorNotAnException) {
    const std::string text = R"({"format": "candela.scene", "version": 1e999, "entities": []})";
    Diagnostics diagnostics;
    EXPECT_FALSE(parseSceneJson(std::as_bytes(std::span(text)), "huge.json", diagnostics));
    EXPECT_TRUE(diagnostics.mentions("huge.json"));
}

TEST(SceneFile, StructuralErrorsNameTheJsonPointerAndDropOnlyThatComponent) {
    const std::string text = R"({
      "format": "candela.scene", "version": 1,
      "entities": [
        {"name": "a", "light": {"type": "laser", "lumens": 10}, "camera": {"iso": 200}},
        {"name": "b", "parent": 7, "transform": {"scale": [1, 2]}},
        {"name": "c", "parent": 3},
        {"name": "d", "parent": 2},
        {"name": "e", "mesh": {"gltf": "x.glb", "mesh": -1}}
      ]})";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(text)), "s.json", diagnostics);
    ASSERT_TRUE(scene);
    ASSERT_EQ(scene->entities.size(), 5u);
    EXPECT_FALSE(scene->entities[0].light) << "bad light dropped";
    ASSERT_TRUE(scene->entities[0].camera) << "good camera kept";
    EXPECT_EQ(scene->entities[0].camera->iso, 200.0f);
    EXPECT_TRUE(diagnostics.mentions("s.json: /entities/0/light/type: error: 'laser'"))
        << diagnostics.toString();
    EXPECT_TRUE(diagnostics.mentions("/entities/1/parent"));
    EXPECT_TRUE(diagnostics.mentions("/entities/1/transform/scale"));
    EXPECT_TRUE(diagnostics.mentions("cycle"));
    EXPECT_TRUE(scene->entities[2].parent == kNoIndex || scene->entities[3].parent == kNoIndex);
    EXPECT_FALSE(scene->entities[4].mesh);
    EXPECT_TRUE(diagnostics.mentions("/entities/4/mesh/mesh"));
}

TEST(SceneFile, VersionFormatAndNestingAreChecked) {
    for (const std::string& text : std::vector<std::string>{
             R"({"format": "candela.scene", "version": 99, "entities": []})",
             R"({"format": "other", "version": 1, "entities": []})",
             R"({"format": "candela.scene", "entities": []})", R"([])",
             std::string(
                 R"({"format": "candela.scene", "version": 1, "entities": [{"gameData": )") +
                 std::string(5000, '[') + std::string(5000, ']') + "}]}"}) {
        Diagnostics diagnostics;
        EXPECT_FALSE(parseSceneJson(std::as_bytes(std::span(text)), "v.json", diagnostics))
            << text.substr(0, 80);
        EXPECT_TRUE(diagnostics.hasErrors());
    }
    Diagnostics missing;
    EXPECT_FALSE(loadSceneFile("/no/such/scene.json", missing));
    EXPECT_TRUE(missing.mentions("/no/such/scene.json"));
}

// Issue 22: values that used to give a blank, flipped or NaN frame without a word are errors
// naming the file and the element (the component is dropped), and physically absurd but
// finite magnitudes are clamped with a warning.
TEST(SceneFile, OutOfDomainValuesAreErrorsNamingTheElement) {
    const std::string text = R"({
      "format": "candela.scene", "version": 1,
      "entities": [
        {"name": "fov0", "camera": {"verticalFov": 0}},
        {"name": "fovPi", "camera": {"verticalFov": 3.14159274}},
        {"name": "fov2Pi", "camera": {"verticalFov": 6.2831855}},
        {"name": "fovNeg", "camera": {"verticalFov": -1}},
        {"name": "nearFar", "camera": {"nearPlane": 10, "farPlane": 1}},
        {"name": "zeroQuat", "transform": {"rotation": [0, 0, 0, 0]}},
        {"name": "darkSky", "sky": {"exr": "sky.exr", "intensity": -5}},
        {"name": "noSky", "sky": {"exr": ""}},
        {"name": "cones", "light": {"type": "spot", "innerConeAngle": 0.8, "outerConeAngle": 0.4}},
        {"name": "negative", "light": {"lumens": -1, "attenuationRadius": 0, "sourceRadius": -2}},
        {"name": "fine", "camera": {"verticalFov": 0.5}, "light": {"type": "spot"}}
      ]})";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(text)), "s.json", diagnostics);
    ASSERT_TRUE(scene);
    ASSERT_EQ(scene->entities.size(), 11u);
    for (int i = 0; i < 5; ++i) {
        EXPECT_FALSE(scene->entities[i].camera) << scene->entities[i].name;
    }
    const std::string expected[] = {
        "s.json: /entities/0/camera/verticalFov: error: must be between 0 and pi",
        "s.json: /entities/1/camera/verticalFov: error",
        "s.json: /entities/2/camera/verticalFov: error",
        "s.json: /entities/3/camera/verticalFov: error",
        "s.json: /entities/4/camera/farPlane: error: must be beyond nearPlane",
        "s.json: /entities/5/transform/rotation: error: a zero quaternion",
        "s.json: /entities/6/sky/intensity: error: must not be negative",
        "s.json: /entities/7/sky/exr: error",
        "s.json: /entities/8/light/innerConeAngle: error: the inner cone (0.8) is wider",
        "s.json: /entities/9/light/lumens: error",
        "s.json: /entities/9/light/attenuationRadius: error",
        "s.json: /entities/9/light/sourceRadius: error"};
    for (const std::string& message : expected) {
        EXPECT_TRUE(diagnostics.mentions(message)) << message << "\n" << diagnostics.toString();
    }
    EXPECT_EQ(scene->entities[5].transform.rotation, (std::array<float, 4>{0, 0, 0, 1}));
    EXPECT_FALSE(scene->entities[6].sky);
    EXPECT_FALSE(scene->entities[7].sky);
    EXPECT_FALSE(scene->entities[8].light);
    EXPECT_FALSE(scene->entities[9].light);
    EXPECT_TRUE(scene->entities[10].camera);
    EXPECT_TRUE(scene->entities[10].light);
    EXPECT_FALSE(diagnostics.mentions("/entities/10/"));
}

TEST(SceneFile, AbsurdMagnitudesAreClampedWithAWarning) {
    const std::string text = R"({
      "format": "candela.scene", "version": 1,
      "entities": [
        {"name": "bright", "light": {"color": [3e38, 1, 1], "lumens": 3e38}},
        {"name": "sun", "light": {"type": "directional", "lux": 3e38}},
        {"name": "sky", "sky": {"exr": "sky.exr", "intensity": 3e38}},
        {"name": "glow", "mesh": {"gltf": "x.glb"}, "materialOverrides": [{"primitive": 0,
          "material": {"emissiveFactor": [3e38, 3e38, 3e38], "emissiveStrength": 3e38}}]}
      ]})";
    Diagnostics diagnostics;
    auto scene = parseSceneJson(std::as_bytes(std::span(text)), "s.json", diagnostics);
    ASSERT_TRUE(scene);
    ASSERT_TRUE(scene->entities[0].light);
    EXPECT_EQ(scene->entities[0].light->lumens, kMaxLumens);
    EXPECT_EQ(scene->entities[0].light->color[0], kMaxLightColorChannel);
    ASSERT_TRUE(scene->entities[1].light);
    EXPECT_EQ(scene->entities[1].light->lux, kMaxLux);
    ASSERT_TRUE(scene->entities[2].sky);
    EXPECT_EQ(scene->entities[2].sky->intensity, kMaxSkyIntensity);
    ASSERT_EQ(scene->entities[3].materialOverrides.size(), 1u);
    const Material& m = scene->entities[3].materialOverrides[0].material;
    EXPECT_LE(double(m.emissiveFactor[0]) * double(m.emissiveStrength),
              double(kMaxEmissiveLuminance) * 1.0001);
    for (const char* message :
         {"s.json: /entities/0/light/lumens: warning: 3e+38 lm is beyond the limit of 1e+12 lm",
          "s.json: /entities/0/light/color: warning", "s.json: /entities/1/light/lux: warning",
          "s.json: /entities/2/sky/intensity: warning",
          "s.json: /entities/3/materialOverrides/0/material/emissiveStrength: warning"}) {
        EXPECT_TRUE(diagnostics.mentions(message)) << message << "\n" << diagnostics.toString();
    }
}

}  // namespace
}  // namespace candela::content
