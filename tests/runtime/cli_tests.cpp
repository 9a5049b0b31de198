// The candela executable as a user runs it: good runs, determinism, and bad arguments that
// must give a clear message and a non-zero exit, never a crash.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include "candela/audio/wav_encoding.h"
#include "candela/content/atomic_file_write.h"
#include "candela/content/exr_image.h"
#include "candela/content/render_setting_table.h"
#include "full_filesystem.h"
#include "image_files.h"
#include "run_command.h"

namespace {

using candela::testing::runCommand;
using candela::testing::RunResult;

// `environment`: variable assignments for the shell to put before the command.
RunResult runCandela(const std::string& args, const std::string& environment = "") {
    return runCommand(environment + std::string(CANDELA_EXECUTABLE) + " " + args);
}

std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// tests/scenes/spot_light.scene.json (a box floor under a spot, entity 2 the camera) with its
// box found in the shared assets, for tests that change one value of it.
nlohmann::json spotLightScene() {
    nlohmann::json scene = nlohmann::json::parse(readBytes(
        std::filesystem::path(CANDELA_SOURCE_DIR) / "tests/scenes/spot_light.scene.json"));
    scene["entities"][0]["mesh"]["gltf"] =
        std::string(CANDELA_SHARED_ASSETS) + "/models/Box/Box.glb";
    return scene;
}

// One folder per test: ctest runs the tests in parallel processes, and several write files of
// the same names (default.json, flag.exr, ...), which raced in one shared folder.
std::filesystem::path tempDir() {
    const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
    auto dir = std::filesystem::path(testing::TempDir()) / "candela_cli" /
               (test ? std::string(test->name()) : std::string("shared"));
    std::filesystem::create_directories(dir);
    return dir;
}

// A headless `run` of `sceneAndFlags` capturing dir/NAME.exr and writing dir/NAME.json: the
// capture (empty when it could not be read) and the stats.
struct CapturedRun {
    std::optional<candela::content::ExrImage> capture;
    nlohmann::json stats;
};
CapturedRun captureRun(const std::filesystem::path& dir, const std::string& name,
                       const std::string& sceneAndFlags) {
    const std::string exr = (dir / (name + ".exr")).string();
    RunResult r = runCandela("run " + sceneAndFlags + " --headless --capture " + exr + " --stats " +
                             (dir / (name + ".json")).string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    candela::content::Diagnostics diagnostics;
    CapturedRun out{candela::content::readExrImage(exr, diagnostics), {}};
    EXPECT_TRUE(out.capture.has_value()) << name;
    if (r.exitCode == 0) out.stats = nlohmann::json::parse(readBytes(dir / (name + ".json")));
    return out;
}

// Sums of Rec. 709 luminance over two same-sized images: |image - reference|, the reference's
// and the image's (relative L1 error: difference / reference; total light: image / reference).
struct LuminanceSums {
    double difference = 0.0, reference = 0.0, image = 0.0;
};
LuminanceSums luminanceSums(const candela::content::FloatImage& image,
                            const candela::content::FloatImage& reference) {
    LuminanceSums sums;
    for (uint32_t y = 0; y < reference.height; ++y) {
        for (uint32_t x = 0; x < reference.width; ++x) {
            const float* a = reference.texel(x, y);
            const float* b = image.texel(x, y);
            const double la = 0.2126 * a[0] + 0.7152 * a[1] + 0.0722 * a[2];
            const double lb = 0.2126 * b[0] + 0.7152 * b[1] + 0.0722 * b[2];
            sums.difference += std::abs(lb - la);
            sums.reference += la;
            sums.image += lb;
        }
    }
    return sums;
}

const std::string kTriangle = "run builtin:triangle --headless --size 64x48 ";
// For demo runs that test something else (the camera path, the overlay, light culling): the
// demo's reflections and fog are the slowest pipelines to build on lavapipe (about half of a
// demo run's 30 s under the sanitizers), and its atmosphere's five passes (sky tables redone
// each frame while the day cycles) added a third to a 3-frame run's 10 s (lavapipe, no
// sanitizers); DemoRendersHeadlessWithEveryFeature keeps them.
const std::string kDemoWithoutCostlyPasses = "--ssr off --volumetrics off --atmosphere off ";

}  // namespace

TEST(Cli, HeadlessRunWritesCaptureAndStats) {
    auto dir = tempDir();
    RunResult r = runCandela(kTriangle + "--frames 2 --capture " + (dir / "a.exr").string() +
                             " --stats " + (dir / "a.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "a.exr"));
    nlohmann::json stats = nlohmann::json::parse(readBytes(dir / "a.json"));
    EXPECT_EQ(stats["frames"], 2);
    EXPECT_EQ(stats["width"], 64);
    EXPECT_EQ(stats["height"], 48);
    EXPECT_FALSE(stats["device"].get<std::string>().empty());
    EXPECT_GT(stats["frame_ms_median"].get<double>(), 0.0);
    EXPECT_EQ(stats["validation_messages"], 0);
    EXPECT_TRUE(stats["features"].is_array());
    EXPECT_FALSE(stats["features"].empty());
}

// --stats "settings": every render setting's value for the run under its stats name, a flag's
// choice over the preset's (here --quality low, whose SSR is off and bloom 0).
TEST(Cli, StatsReportEveryRenderSettingAndTheQualityItCameFrom) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/spot_light.scene.json";
    RunResult r = runCandela("run " + scene +
                             " --headless --size 32x32 --frames 1 --quality low --ssr reference "
                             "--render-scale 0.75 --stats " +
                             (dir / "s.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json stats = nlohmann::json::parse(readBytes(dir / "s.json"));
    EXPECT_EQ(stats["quality"], "low");
    EXPECT_EQ(stats["quality_source"], "flag");
    const nlohmann::json& settings = stats["settings"];
    candela::content::forEachRenderSetting([&](const auto& row) {
        EXPECT_TRUE(settings.contains(std::string(row.statsName))) << row.statsName;
    });
    EXPECT_EQ(settings["ssr"], "reference");
    EXPECT_EQ(settings["render_scale"], 0.75);
    EXPECT_EQ(settings["bloom"], 0);
    EXPECT_EQ(settings["area_lights"], "representative");
}

// Passes build their pipelines when a frame first uses them: the triangle's frame has no
// G-buffer or lighting, so its run compiles neither; a lit scene's run compiles its own.
TEST(Cli, StatsCountPipelinesAndOnlyLitFramesBuildTheLightingOnes) {
    auto dir = tempDir();
    RunResult triangle = runCandela(kTriangle + "--frames 1 --stats " + (dir / "t.json").string());
    ASSERT_EQ(triangle.exitCode, 0) << triangle.output;
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/spot_light.scene.json";
    RunResult lit = runCandela("run " + scene + " --headless --size 32x32 --frames 1 --stats " +
                               (dir / "l.json").string());
    ASSERT_EQ(lit.exitCode, 0) << lit.output;
    const nlohmann::json t = nlohmann::json::parse(readBytes(dir / "t.json"))["pipelines"];
    const nlohmann::json l = nlohmann::json::parse(readBytes(dir / "l.json"))["pipelines"];
    ASSERT_TRUE(t.is_object() && l.is_object());
    EXPECT_GT(t["created"].get<int>(), 0);
    EXPECT_GE(t["create_ms"].get<double>(), 0.0);
    // The G-buffer and the lighting variant of the scene, at least; compiled once each.
    EXPECT_GE(l["created"].get<int>(), t["created"].get<int>() + 2);
    EXPECT_LE(l["created"].get<int>(), t["created"].get<int>() + 8);
    EXPECT_GT(l["create_ms"].get<double>(), t["create_ms"].get<double>());
}

// --stats-work last: the frames before the last run the lighting variant without counters
// (one more pipeline: the counting one, built for the last frame), and the static scene's
// counts are those of a run that counts every frame. Antialiasing is off: TAA's jitter moves
// pixels in and out of the spot's cone, so its frames' counts differ and "every" keeps the largest.
TEST(Cli, StatsWorkLastCountsTheLastFrameOnly) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/spot_light.scene.json";
    const std::string run =
        "run " + scene + " --headless --size 32x32 --frames 3 --aa off --stats ";
    RunResult every = runCandela(run + (dir / "every.json").string());
    ASSERT_EQ(every.exitCode, 0) << every.output;
    RunResult last = runCandela(run + (dir / "last.json").string() + " --stats-work last");
    ASSERT_EQ(last.exitCode, 0) << last.output;
    const nlohmann::json e = nlohmann::json::parse(readBytes(dir / "every.json"));
    const nlohmann::json l = nlohmann::json::parse(readBytes(dir / "last.json"));
    EXPECT_GT(e["light_evaluations"].get<uint64_t>(), 0u);
    EXPECT_EQ(l["light_evaluations"], e["light_evaluations"]);
    EXPECT_EQ(l["work"], e["work"]);
    EXPECT_GT(l["work"]["light_evaluations_plain"].get<uint64_t>() +
                  l["work"]["light_evaluations_shadowed"].get<uint64_t>(),
              0u);
    EXPECT_EQ(l["pipelines"]["created"].get<int>(), e["pipelines"]["created"].get<int>() + 1);

    RunResult bad = runCandela(kTriangle + "--stats-work some");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("--stats-work needs every or last, got 'some'"), std::string::npos)
        << bad.output;
}

// --render-scale renders the scene at a fraction of the output and upscales the radiance: the
// captures keep the output's size, the stats say the render size, and the image stays close to
// the full-size one (a spot light's smooth falloff on a floor, no antialiasing or bloom).
TEST(Cli, RenderScaleRendersSmallerAndUpscalesToTheOutput) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/spot_light.scene.json";
    auto render = [&](const std::string& name, const std::string& scale) {
        return captureRun(dir, name,
                          scene +
                              " --size 96x64 --frames 2 --quality ultra --aa off --bloom 0 "
                              "--render-scale " +
                              scale);
    };
    const CapturedRun full = render("full", "1");
    const CapturedRun half = render("half", "0.5");
    ASSERT_TRUE(full.capture && half.capture);
    const nlohmann::json& f = full.stats;
    const nlohmann::json& h = half.stats;
    EXPECT_EQ(f["render_width"], 96);
    EXPECT_EQ(f["render_height"], 64);
    EXPECT_EQ(h["render_width"], 48);
    EXPECT_EQ(h["render_height"], 32);
    EXPECT_EQ(h["width"], 96);
    const auto has = [](const nlohmann::json& j, const char* feature) {
        const auto& list = j["features"];
        return std::find(list.begin(), list.end(), feature) != list.end();
    };
    EXPECT_FALSE(has(f, "upscale"));
    EXPECT_TRUE(has(h, "upscale"));
    ASSERT_EQ(half.capture->image.width, 96u);
    ASSERT_EQ(half.capture->image.height, 64u);
    // The luminance difference against the full-size frame relative to its total light (an
    // L1 error that dark pixels at the cone's edge cannot blow up), and the total within 5%.
    const LuminanceSums sums = luminanceSums(half.capture->image, full.capture->image);
    ASSERT_GT(sums.reference, 0.0);
    const double error = sums.difference / sums.reference;
    std::printf("render scale 0.5: relative L1 luminance error %.4f, total light ratio %.4f\n",
                error, sums.image / sums.reference);
    EXPECT_GT(error, 0.0) << "the half-size frame is the full-size one: nothing was scaled";
    EXPECT_LT(error, 0.1);
    EXPECT_NEAR(sums.image / sums.reference, 1.0, 0.05);

    RunResult bad = runCandela(kTriangle + "--render-scale 0.1");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("--render-scale needs a fraction of the output's size from 0.25 to "
                              "1, got '0.1'"),
              std::string::npos)
        << bad.output;
}

// --lod-error: a grid of 10,600-triangle spheres drawn at their levels of detail draws a
// fraction of the triangles, in shadow maps too, and stays close to the full meshes' image;
// --culling off records every draw and changes no pixel.
TEST(Cli, LevelsOfDetailAndCullingFlags) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/sphere_grid_point.scene.json";
    auto render = [&](const std::string& name, const std::string& flags) {
        return captureRun(dir, name,
                          scene + " --size 96x96 --quality ultra --aa off --bloom 0 " + flags);
    };
    const CapturedRun full = render("full", "--lod-error 0");
    const CapturedRun coarse = render("coarse", "--lod-error 1");
    const CapturedRun unculled = render("unculled", "--lod-error 0 --culling off");
    ASSERT_TRUE(full.capture && coarse.capture && unculled.capture);
    const uint64_t fullTriangles = full.stats["work"]["triangles"].get<uint64_t>();
    const uint64_t coarseTriangles = coarse.stats["work"]["triangles"].get<uint64_t>();
    EXPECT_GT(fullTriangles, 100000u);
    EXPECT_LT(coarseTriangles * 4, fullTriangles);
    EXPECT_LE(coarse.stats["work"]["shadow_triangles"].get<uint64_t>(),
              full.stats["work"]["shadow_triangles"].get<uint64_t>());
    EXPECT_EQ(unculled.stats["draws_culled"], 0);
    EXPECT_TRUE(full.capture->image.rgba == unculled.capture->image.rgba)
        << "culling changed a pixel";
    const LuminanceSums sums = luminanceSums(coarse.capture->image, full.capture->image);
    ASSERT_GT(sums.reference, 0.0);
    std::printf("levels of detail at 1 pixel: %llu of %llu triangles, relative L1 error %.4f\n",
                (unsigned long long)coarseTriangles, (unsigned long long)fullTriangles,
                sums.difference / sums.reference);
    EXPECT_LT(sums.difference / sums.reference, 0.02);

    RunResult bad = runCandela(kTriangle + "--lod-error 9");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("--lod-error needs pixels from 0 (full meshes) to 8, got '9'"),
              std::string::npos)
        << bad.output;
    bad = runCandela(kTriangle + "--culling maybe");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("--culling needs on or off, got 'maybe'"), std::string::npos)
        << bad.output;
}

TEST(Cli, CapturesAreIdenticalRunAfterRun) {
    auto dir = tempDir();
    for (const char* ext : {".exr", ".png"}) {
        auto first = dir / (std::string("first") + ext);
        auto second = dir / (std::string("second") + ext);
        ASSERT_EQ(runCandela(kTriangle + "--frames 3 --capture " + first.string()).exitCode, 0);
        ASSERT_EQ(runCandela(kTriangle + "--frames 3 --capture " + second.string()).exitCode, 0);
        std::string a = readBytes(first);
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, readBytes(second)) << ext;
    }
}

TEST(Cli, OneRunCanCaptureBothExrAndPng) {
    auto dir = tempDir();
    RunResult r = runCandela(kTriangle + "--capture " + (dir / "both.exr").string() +
                             " --capture " + (dir / "both.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(std::filesystem::file_size(dir / "both.exr"), 0u);
    EXPECT_GT(std::filesystem::file_size(dir / "both.png"), 0u);
}

// Every sample model loads from ../shared/assets and renders with no NaN/Inf and no
// validation message, lit by the viewing defaults (camera framing it, sun and fill).
TEST(Cli, SampleModelsRender) {
    auto dir = tempDir();
    for (const char* model : {"Box", "BoxTextured", "DamagedHelmet", "MetalRoughSpheresNoTextures",
                              "TextureSettingsTest", "AlphaBlendModeTest"}) {
        std::string path =
            std::string(CANDELA_SHARED_ASSETS) + "/models/" + model + "/" + model + ".glb";
        auto exr = dir / (std::string(model) + ".exr");
        RunResult r =
            runCandela("run " + path + " --headless --size 96x96 --capture " + exr.string());
        ASSERT_EQ(r.exitCode, 0) << model << ": " << r.output;
        candela::content::Diagnostics diagnostics;
        auto image = candela::content::readExrImage(exr, diagnostics);
        ASSERT_TRUE(image.has_value()) << model;
        EXPECT_EQ(image->replacedNonFiniteTexels, 0u) << model;
        // Something was drawn: not every pixel equals the background.
        const float* first = image->image.texel(0, 0);
        bool varied = false;
        for (uint32_t y = 0; y < image->image.height && !varied; ++y) {
            for (uint32_t x = 0; x < image->image.width && !varied; ++x) {
                varied = image->image.texel(x, y)[0] != first[0];
            }
        }
        EXPECT_TRUE(varied) << model << " rendered as a flat image";
    }
}

TEST(Cli, DemoRendersHeadlessWithEveryFeature) {
    auto dir = tempDir();
    RunResult r = runCandela("demo --headless --size 160x90 --frames 2 --stats " +
                             (dir / "demo.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json stats = nlohmann::json::parse(readBytes(dir / "demo.json"));
    auto features = stats["features"].get<std::vector<std::string>>();
    for (const char* expected :
         {"shading_subsurface", "shading_legacy_diffuse_specular", "lights_sphere", "lights_tube",
          "material_anisotropy", "material_clear_coat", "atmosphere", "sky_occlusion"}) {
        EXPECT_NE(std::find(features.begin(), features.end(), expected), features.end())
            << expected;
    }
}

// The demo's headless camera follows its path by frame index: two runs write the same bytes
// for every frame, and the frames along the path differ from each other.
TEST(Cli, DemoCameraPathIsDeterministic) {
    auto dir = tempDir();
    const std::string args = "demo --headless --size 96x54 --frames 3 --step 4 " +
                             kDemoWithoutCostlyPasses + "--capture-each ";
    RunResult a = runCandela(args + (dir / "path_a").string());
    ASSERT_EQ(a.exitCode, 0) << a.output;
    RunResult b = runCandela(args + (dir / "path_b").string() + " --summary " +
                             (dir / "path_b" / "summary.md").string());
    ASSERT_EQ(b.exitCode, 0) << b.output;
    std::vector<std::string> frames;
    for (const char* name : {"frame_00.png", "frame_01.png", "frame_02.png"}) {
        std::string bytes = readBytes(dir / "path_a" / name);
        ASSERT_FALSE(bytes.empty()) << name;
        EXPECT_EQ(bytes, readBytes(dir / "path_b" / name)) << name;
        frames.push_back(bytes);
    }
    EXPECT_NE(frames[0], frames[1]);
    EXPECT_NE(frames[1], frames[2]);
    std::string summary = readBytes(dir / "path_b" / "summary.md");
    EXPECT_NE(summary.find("| 2 | 8.00 |"), std::string::npos) << summary;
    EXPECT_NE(summary.find("culling efficiency"), std::string::npos) << summary;
}

TEST(Cli, DemoHasHundredsOfLightsAndCullsThem) {
    auto dir = tempDir();
    RunResult r = runCandela("demo --headless --size 96x54 " + kDemoWithoutCostlyPasses +
                             "--stats " + (dir / "d.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json stats = nlohmann::json::parse(readBytes(dir / "d.json"));
    EXPECT_GE(stats["lights"].get<int>(), 256);
    EXPECT_GT(stats["clusters_occupied"].get<int>(), 0);
    EXPECT_LT(stats["clusters_occupied"].get<int>(), stats["clusters"].get<int>());
    double efficiency = stats["culling_efficiency"].get<double>();
    EXPECT_GT(efficiency, 0.0);
    EXPECT_LE(efficiency, 1.0);
}

// The stats overlay (ImGui) draws in the top-left corner only: with --overlay the frame
// changes there and nowhere else (the window shows it by default; headless needs --overlay),
// and it is a pass of the frame graph. The triangle scene: the overlay is the same layer over
// any scene, and the demo's pipelines took most of this test's time.
TEST(Cli, OverlayDrawsOnlyItsCorner) {
    auto dir = tempDir();
    const std::string args = "run builtin:triangle --headless --size 640x360 --frames 2 --capture ";
    RunResult plain = runCandela(args + (dir / "plain.png").string());
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    RunResult overlay = runCandela(args + (dir / "overlay.png").string() + " --overlay" +
                                   " --frame-graph " + (dir / "overlay.dot").string());
    ASSERT_EQ(overlay.exitCode, 0) << overlay.output;
    // The overlay is a FrameLayer: a pass of the frame graph of its own, after tonemapping.
    std::ifstream dotFile(dir / "overlay.dot");
    const std::string dot((std::istreambuf_iterator<char>(dotFile)),
                          std::istreambuf_iterator<char>());
    EXPECT_NE(dot.find("stats_overlay"), std::string::npos) << dot;
    std::string error;
    auto a = candela::golden::readLdrPng(dir / "plain.png", error);
    ASSERT_TRUE(a) << error;
    auto b = candela::golden::readLdrPng(dir / "overlay.png", error);
    ASSERT_TRUE(b) << error;
    ASSERT_EQ(a->rgb.size(), b->rgb.size());
    size_t changedInCorner = 0, changedElsewhere = 0;
    for (uint32_t y = 0; y < a->height; ++y) {
        for (uint32_t x = 0; x < a->width; ++x) {
            size_t i = (size_t(y) * a->width + x) * 3;
            bool changed = a->rgb[i] != b->rgb[i] || a->rgb[i + 1] != b->rgb[i + 1] ||
                           a->rgb[i + 2] != b->rgb[i + 2];
            bool corner = x < 400 && y < 140;
            (corner ? changedInCorner : changedElsewhere) += changed;
        }
    }
    EXPECT_GT(changedInCorner, 1000u);  // text and panel edges (the panel over black stays black)
    EXPECT_EQ(changedElsewhere, 0u);
}

TEST(Cli, BadInputScriptIsRejectedWithFileAndLine) {
    auto script = tempDir() / "bad.input";
    std::ofstream(script) << "0 down W\n5 press W\n";
    RunResult r = runCandela(kTriangle + "--input " + script.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(script.string() + ":2: unknown action 'press'"), std::string::npos)
        << r.output;
    r = runCandela(kTriangle + "--input " + (tempDir() / "missing.input").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("cannot open input script"), std::string::npos) << r.output;
}

TEST(Cli, BadStepAndCaptureEachAreRejected) {
    RunResult r = runCandela(kTriangle + "--step 0");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--step needs seconds"), std::string::npos) << r.output;
    r = runCandela(kTriangle + "--step nan");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    r = runCandela("run builtin:triangle --size 64x48 --capture-each " + tempDir().string());
    // Headless without a display still needs a frame count to know how many files to write.
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--capture-each needs --frames"), std::string::npos) << r.output;
}

// Light lists built in compute shaders are the CPU's lists, in the same order: the same bytes.
TEST(Cli, DeviceLightAssignmentGivesTheSameImage) {
    auto dir = tempDir();
    // "auto" chooses one of the two (ApplicationOptions.LightAssignFlagChoosesTheDevice parses
    // it); the demo's hundreds of lights fill the clusters at any size.
    for (const char* device : {"cpu", "gpu"}) {
        RunResult r =
            runCandela("demo --headless --size 96x54 --frames 2 " + kDemoWithoutCostlyPasses +
                       "--light-assign " + device + " --capture " +
                       (dir / (std::string("assign_") + device + ".exr")).string());
        ASSERT_EQ(r.exitCode, 0) << device << ": " << r.output;
    }
    std::string cpu = readBytes(dir / "assign_cpu.exr");
    EXPECT_FALSE(cpu.empty());
    EXPECT_EQ(cpu, readBytes(dir / "assign_gpu.exr"));
    RunResult bad = runCandela(kTriangle + "--light-assign tpu");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("--light-assign needs auto, cpu or gpu, got 'tpu'"),
              std::string::npos)
        << bad.output;
}

// --stats names every pass the frame graph ran with its time and describes the graph;
// --frame-graph writes it as Graphviz. On lavapipe (a CPU device) auto assigns on the CPU.
TEST(Cli, StatsAndGraphvizDescribeTheFrameGraph) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/alpha_blend_mode.scene.json";
    RunResult r = runCandela("run " + scene + " --headless --size 64x64 --frames 3 --stats " +
                             (dir / "graph.json").string() + " --frame-graph " +
                             (dir / "graph.dot").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json json = nlohmann::json::parse(readBytes(dir / "graph.json"));
    for (const char* pass :
         {"gbuffer", "depth_range", "depth_occupancy", "light_assignment_cpu", "lighting",
          "transparent_occupancy", "forward_transparent", "tonemap"}) {
        ASSERT_TRUE(json["passes"].contains(pass)) << pass << ": " << json["passes"].dump();
        EXPECT_GE(json["passes"][pass].get<double>(), 0.0) << pass;
    }
    // Nothing animates: no skinning pass, no cost (issue 20).
    EXPECT_FALSE(json["passes"].contains("skinning"));
    EXPECT_EQ(json["deformed_draws"].get<int>(), 0);
    EXPECT_EQ(json["skinning_ms"].get<double>(), 0.0);
    const nlohmann::json& graph = json["frame_graph"];
    EXPECT_EQ(graph["passes"].get<int>(), int(json["passes"].size()));
    EXPECT_EQ(graph["culled_passes"].get<int>(), 0);
    EXPECT_GT(graph["barriers"].get<int>(), 0);
    EXPECT_GT(graph["transient_bytes"].get<uint64_t>(), 0u);
    EXPECT_LE(graph["transient_bytes"].get<uint64_t>(),
              graph["transient_bytes_unaliased"].get<uint64_t>());
    // Frame 1 renders the sun's shadow maps; frames 2 and 3 keep them (no shadow pass) and
    // reuse the graph frame 2 compiled.
    EXPECT_EQ(graph["compiled_frames"].get<int>(), 2);
    const std::string dot = readBytes(dir / "graph.dot");
    EXPECT_EQ(dot.rfind("digraph frame {", 0), 0u) << dot.substr(0, 80);
    EXPECT_NE(dot.find("gbuffer.depth"), std::string::npos);
    EXPECT_NE(dot.find("forward_transparent"), std::string::npos);
}

// The engine scene files in tests/scenes load (glTF references, lights, camera, material
// overrides) and render clean; the overrides switch on their shading models.
TEST(Cli, EngineSceneFilesRender) {
    auto dir = tempDir();
    for (const char* name : {"sphere_grid_point", "sphere_grid_sphere_light",
                             "sphere_grid_tube_light", "shading_models", "spot_light"}) {
        std::string scene =
            std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/" + name + ".scene.json";
        auto stats = dir / (std::string(name) + ".json");
        RunResult r =
            runCandela("run " + scene + " --headless --size 64x64 --stats " + stats.string());
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.output;
        nlohmann::json json = nlohmann::json::parse(readBytes(stats));
        EXPECT_GT(json["lights"].get<int>(), 0) << name;
        if (std::string(name) == "shading_models") {
            auto features = json["features"].get<std::vector<std::string>>();
            for (const char* f : {"shading_subsurface", "shading_legacy_diffuse_specular"}) {
                EXPECT_NE(std::find(features.begin(), features.end(), f), features.end()) << f;
            }
        }
    }
}

TEST(Cli, SceneFileOfUnknownTypeIsRejected) {
    auto path = tempDir() / "scene.txt";
    std::ofstream(path) << "not a scene";
    RunResult r = runCandela("run " + path.string() + " --headless");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("scene.txt"), std::string::npos) << r.output;
}

TEST(Cli, GarbageGltfGivesAClearErrorNotACrash) {
    auto path = tempDir() / "garbage.glb";
    std::ofstream(path, std::ios::binary) << "glTF\x02\x00\x00\x00garbage";
    RunResult r = runCandela("run " + path.string() + " --headless --size 32x32");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("garbage.glb"), std::string::npos) << r.output;
}

TEST(Cli, ZeroSizeIsRejected) {
    RunResult r = runCandela("run builtin:triangle --headless --size 0x0");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
}

TEST(Cli, MalformedSizeIsRejected) {
    for (const char* size : {"abc", "64", "64x", "x64", "-5x10", "99999x10"}) {
        RunResult r = runCandela(std::string("run builtin:triangle --headless --size ") + size);
        EXPECT_EQ(r.exitCode, 2) << size;
        EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
    }
}

TEST(Cli, UnwritableCapturePathIsRejectedBeforeRendering) {
    RunResult r = runCandela(kTriangle + "--capture /nonexistent-candela-dir/out.png");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("/nonexistent-candela-dir/out.png"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST(Cli, CaptureIntoADirectoryIsRejected) {
    auto dir = tempDir() / "is_a_dir.png";
    std::filesystem::create_directories(dir);
    RunResult r = runCandela(kTriangle + "--capture " + dir.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("is a directory"), std::string::npos) << r.output;
}

TEST(Cli, UnknownCaptureFormatIsRejected) {
    RunResult r = runCandela(kTriangle + "--capture out.bmp");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find(".exr or .png"), std::string::npos) << r.output;
}

// --animation picks the clip by name or index; headless time advances by --step, so the same
// clip at the same time renders the same image and another clip or time another one. An
// unknown clip is rejected naming the file and listing the clips.
TEST(Cli, AnimationFlagChoosesTheClipAndStepAdvancesIt) {
    auto dir = tempDir();
    const std::string fox = std::string(CANDELA_SHARED_ASSETS) + "/models/Fox/Fox.glb";
    auto render = [&](const std::string& name, const std::string& flags) {
        const auto path = dir / (name + ".png");
        // --aa off: TAA's jitter and history would make the image depend on the frame count.
        RunResult r = runCandela("run " + fox + " --headless --size 64x64 --aa off --capture " +
                                 path.string() + " " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readBytes(path);
    };
    const auto statsPath = dir / "walk.json";
    const std::string walkByName =
        render("walk", "--animation Walk --frames 3 --step 0.25 --stats " + statsPath.string());
    // Issue 20: the Fox's one skinned draw is deformed by the skinning compute pass.
    const nlohmann::json stats = nlohmann::json::parse(readBytes(statsPath));
    EXPECT_EQ(stats["deformed_draws"].get<int>(), 1) << stats.dump();
    EXPECT_GT(stats["skinning_ms"].get<double>(), 0.0);
    EXPECT_TRUE(stats["passes"].contains("skinning")) << stats["passes"].dump();
    EXPECT_EQ(stats["validation_messages"].get<int>(), 0);
    const std::string walkByIndex = render("walk1", "--animation 1 --frames 2 --step 0.5");
    const std::string run = render("run", "--animation Run --frames 3 --step 0.25");
    const std::string walkLater = render("walk2", "--animation Walk --frames 3 --step 0.3");
    EXPECT_FALSE(walkByName.empty());
    EXPECT_EQ(walkByName, walkByIndex) << "Walk at 0.5 s, by name or by index";
    EXPECT_NE(walkByName, run);
    EXPECT_NE(walkByName, walkLater);
    RunResult bad = runCandela("run " + fox + " --headless --size 64x64 --animation Fly");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("Fox.glb: no animation 'Fly' (available: 0 'Survey', 1 'Walk', "
                              "2 'Run')"),
              std::string::npos)
        << bad.output;
}

TEST(Cli, MissingSceneIsRejected) {
    RunResult r = runCandela("run /no/such/scene.gltf --headless");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("/no/such/scene.gltf"), std::string::npos) << r.output;
}

TEST(Cli, NoSceneAndUnknownOptionsAreRejected) {
    EXPECT_EQ(runCandela("run --headless").exitCode, 2);
    EXPECT_EQ(runCandela("run builtin:triangle --bogus").exitCode, 2);
    EXPECT_EQ(runCandela("run builtin:nothing --headless").exitCode, 2);
    EXPECT_EQ(runCandela("explode").exitCode, 2);
    EXPECT_EQ(runCandela("run builtin:triangle --frames 0").exitCode, 2);
    EXPECT_EQ(runCandela("run builtin:triangle --frames").exitCode, 2);
    EXPECT_EQ(runCandela("run --help").exitCode, 0);
}

// Image-based lighting from the command line (issue 6): a scene's sky, --env overriding it,
// the disk cache across runs, the three modes, and bad sky files.
TEST(Cli, SkyLightsTheSceneAndIsCachedAcrossRuns) {
    auto dir = tempDir() / "sky";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string cache = "CANDELA_CACHE_DIR=" + (dir / "cache").string() + " ";
    const std::string scene = std::string(CANDELA_SOURCE_DIR) +
                              "/tests/scenes/ibl_spheres_garden.scene.json --headless "
                              "--size 64x64 ";
    // Every run uses a private cache folder; the variable prefixes the command in the shell.
    auto run = [&](const std::string& name, const std::string& extra) {
        RunResult r =
            runCandela("run " + scene + extra + " --stats " + (dir / (name + ".json")).string() +
                           " --capture " + (dir / (name + ".exr")).string(),
                       cache);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(readBytes(dir / (name + ".json")));
    };
    nlohmann::json first = run("first", "");
    nlohmann::json second = run("second", "");
    ASSERT_TRUE(first.contains("environment"));
    EXPECT_FALSE(first["environment"]["from_cache"].get<bool>());
    EXPECT_TRUE(second["environment"]["from_cache"].get<bool>());
    EXPECT_EQ(second["environment"]["precompute_ms"].get<double>(), 0.0);
    // The environment BRDF LUT is cached in the same folder: built once, then read.
    EXPECT_EQ(first["brdf_lut"]["source"].get<std::string>(), "built");
    EXPECT_EQ(second["brdf_lut"]["source"].get<std::string>(), "disk_cache");
    // The cache holds exactly what the device computed: the same image either way.
    EXPECT_EQ(readBytes(dir / "first.exr"), readBytes(dir / "second.exr"));

    nlohmann::json mobile = run("mobile", "--ibl mobile");
    auto features = mobile["features"].get<std::vector<std::string>>();
    EXPECT_NE(std::find(features.begin(), features.end(), "ibl_mobile"), features.end());
    EXPECT_NE(readBytes(dir / "mobile.exr"), readBytes(dir / "first.exr"));

    // --env replaces the scene's sky; the image changes.
    run("studio", "--env " + std::string(CANDELA_SHARED_ASSETS) + "/env/studio_small_03_1k.exr");
    EXPECT_NE(readBytes(dir / "studio.exr"), readBytes(dir / "first.exr"));
}

// A cache folder that cannot be created (a file stands in its way) costs warnings, never the
// render: the same image as with a working cache.
TEST(Cli, UnwritableCacheFolderStillRendersTheSameImage) {
    auto dir = tempDir() / "unwritable_cache";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "blocker") << "x";
    const std::string scene = std::string("run ") + CANDELA_SOURCE_DIR +
                              "/tests/scenes/spot_light.scene.json --headless --size 32x32 "
                              "--frames 1 --capture ";
    RunResult blocked =
        runCandela(scene + (dir / "blocked.exr").string(),
                   "CANDELA_CACHE_DIR=" + (dir / "blocker" / "cache").string() + " ");
    EXPECT_EQ(blocked.exitCode, 0) << blocked.output;
    EXPECT_NE(blocked.output.find("BRDF LUT cache not written"), std::string::npos)
        << blocked.output;
    RunResult cached = runCandela(scene + (dir / "cached.exr").string(),
                                  "CANDELA_CACHE_DIR=" + (dir / "cache").string() + " ");
    EXPECT_EQ(cached.exitCode, 0) << cached.output;
    EXPECT_EQ(readBytes(dir / "blocked.exr"), readBytes(dir / "cached.exr"));
}

TEST(Cli, BadSkyFileGivesAClearErrorAndTheNeutralSky) {
    auto dir = tempDir();
    auto bad = dir / "bad_sky.exr";
    std::ofstream(bad) << "not an exr";
    RunResult r =
        runCandela(std::string("run ") + CANDELA_SOURCE_DIR +
                       "/tests/scenes/ibl_spheres_garden.scene.json --headless --size 32x32 "
                       "--env " +
                       bad.string() + " --stats " + (dir / "bad_sky.json").string(),
                   "CANDELA_CACHE_DIR=" + (dir / "bad_sky_cache").string() + " ");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(bad.string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("neutral uniform sky"), std::string::npos) << r.output;
    nlohmann::json stats = nlohmann::json::parse(readBytes(dir / "bad_sky.json"));
    EXPECT_TRUE(stats["environment"]["fallback"].get<bool>());
}

// Issue 26: --brdf picks the BRDF (stats `features`), a scene file's "brdf" does when the
// flag is absent, the flag wins over it, and the two BRDFs give different images.
TEST(Cli, BrdfFlagAndSceneSettingChooseTheBrdf) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/sphere_grid_point.scene.json";
    std::string text = readBytes(scene);
    const size_t open = text.find('{');
    ASSERT_NE(open, std::string::npos);
    text.insert(open + 1, "\n  \"brdf\": \"ue4\",");
    // In the temp folder: the glTF paths, relative to tests/scenes, made absolute.
    const std::string relativeAssets = "../../../shared/assets";
    for (size_t at = text.find(relativeAssets); at != std::string::npos;
         at = text.find(relativeAssets, at)) {
        text.replace(at, relativeAssets.size(), CANDELA_SHARED_ASSETS);
    }
    const std::filesystem::path ue4Scene = dir / "brdf_ue4.scene.json";
    std::ofstream(ue4Scene) << text;
    auto features = [&](const std::string& name, const std::string& args) {
        RunResult r = runCandela("run " + args + " --headless --size 32x32 --stats " +
                                 (dir / (name + ".json")).string() + " --capture " +
                                 (dir / (name + ".exr")).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(readBytes(dir / (name + ".json")))["features"]
            .get<std::vector<std::string>>();
    };
    auto has = [](const std::vector<std::string>& f, const char* name) {
        return std::find(f.begin(), f.end(), name) != f.end();
    };
    EXPECT_TRUE(has(features("default", scene), "brdf_energy_conserving"));
    EXPECT_TRUE(has(features("flag", scene + " --brdf ue4"), "brdf_ue4"));
    EXPECT_TRUE(has(features("setting", ue4Scene.string()), "brdf_ue4"));
    EXPECT_TRUE(has(features("override", ue4Scene.string() + " --brdf energy-conserving"),
                    "brdf_energy_conserving"));
    EXPECT_EQ(readBytes(dir / "flag.exr"), readBytes(dir / "setting.exr"));
    EXPECT_EQ(readBytes(dir / "default.exr"), readBytes(dir / "override.exr"));
    EXPECT_NE(readBytes(dir / "default.exr"), readBytes(dir / "flag.exr"));

    RunResult bad = runCandela(kTriangle + "--brdf phong");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("ue4 or energy-conserving"), std::string::npos) << bad.output;
}

// Issue 25: --ao picks the ambient occlusion (stats `features`, `ao_ms`, the passes in the
// graph), a scene file's "ambient_occlusion" mode does when the flag is absent, off declares
// no AO pass, GTAO accumulates over frames only with TAA, and a bad value is refused.
TEST(Cli, AoFlagAndSceneSettingChooseTheAmbientOcclusion) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/ibl_shading_models.scene.json";
    std::string text = readBytes(scene);
    const size_t open = text.find('{');
    ASSERT_NE(open, std::string::npos);
    text.insert(open + 1, "\n  \"ambient_occlusion\": {\"mode\": \"off\"},");
    const std::string relativeAssets = "../../../shared/assets";
    for (size_t at = text.find(relativeAssets); at != std::string::npos;
         at = text.find(relativeAssets, at)) {
        text.replace(at, relativeAssets.size(), CANDELA_SHARED_ASSETS);
    }
    const std::filesystem::path offScene = dir / "ao_off.scene.json";
    std::ofstream(offScene) << text;
    auto stats = [&](const std::string& name, const std::string& args) {
        RunResult r = runCandela("run " + args + " --headless --size 32x32 --stats " +
                                 (dir / (name + ".json")).string() + " --capture " +
                                 (dir / (name + ".exr")).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(readBytes(dir / (name + ".json")));
    };
    auto has = [](const nlohmann::json& s, const char* name) {
        const auto f = s["features"].get<std::vector<std::string>>();
        return std::find(f.begin(), f.end(), name) != f.end();
    };
    const nlohmann::json gtao = stats("gtao", scene + " --ao gtao");
    EXPECT_TRUE(has(gtao, "ao_gtao"));
    EXPECT_GT(gtao["ao_ms"].get<double>(), 0.0);
    EXPECT_TRUE(gtao["passes"].contains("ambient_occlusion_gtao")) << gtao["passes"].dump();
    // The application's default TAA brings history, so GTAO accumulates over frames; with
    // --aa off it does not (no history to reproject).
    EXPECT_TRUE(has(gtao, "ao_temporal"));
    EXPECT_TRUE(gtao["passes"].contains("ambient_occlusion_temporal")) << gtao["passes"].dump();
    const nlohmann::json single = stats("gtao_aa_off", scene + " --ao gtao --aa off");
    EXPECT_TRUE(has(single, "ao_gtao"));
    EXPECT_FALSE(has(single, "ao_temporal"));
    EXPECT_FALSE(single["passes"].contains("ambient_occlusion_temporal"));
    const nlohmann::json off = stats("setting", offScene.string());
    EXPECT_FALSE(has(off, "ao_gtao"));
    EXPECT_EQ(off["ao_ms"].get<double>(), 0.0);
    EXPECT_FALSE(off["passes"].contains("ambient_occlusion_gtao"));
    EXPECT_TRUE(has(stats("reference", offScene.string() + " --ao reference"), "ao_reference"));
    EXPECT_TRUE(has(stats("flag", scene + " --ao off"), "brdf_energy_conserving"));
    EXPECT_EQ(readBytes(dir / "flag.exr"), readBytes(dir / "setting.exr"));
    EXPECT_NE(readBytes(dir / "gtao.exr"), readBytes(dir / "flag.exr"));

    RunResult bad = runCandela(kTriangle + "--ao ssao");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("off, gtao or reference"), std::string::npos) << bad.output;
}

// Issue 18: --ssr picks the screen-space reflections: off declares no SSR pass and reports
// zeros; hiz and reference trace (stats ssr_ms, ssr_steps_mean, ssr_steps_max, ssr_hit_rate),
// Hi-Z in fewer steps; a bad value is refused.
TEST(Cli, SsrFlagChoosesTheReflectionsAndReportsSteps) {
    auto dir = tempDir();
    // A floor and boxes, one of them glossy (roughness 0.3, under the cut-off).
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/ambient_occlusion.scene.json";
    auto stats = [&](const std::string& name, const std::string& args) {
        RunResult r = runCandela(args + " --stats " + (dir / (name + ".json")).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(readBytes(dir / (name + ".json")));
    };
    const nlohmann::json off = stats("off", kTriangle + "--ssr off");
    EXPECT_EQ(off["ssr_ms"].get<double>(), 0.0);
    EXPECT_EQ(off["ssr_steps_max"].get<uint32_t>(), 0u);
    EXPECT_EQ(off["ssr_hit_rate"].get<double>(), 0.0);
    const std::string run = "run " + scene + " --headless --size 48x32 --aa off --ao off --ssr ";
    const nlohmann::json hiz = stats("hiz", run + "hiz");
    const nlohmann::json reference = stats("reference", run + "reference");
    for (const nlohmann::json* s : {&hiz, &reference}) {
        EXPECT_TRUE((*s)["passes"].contains("ssr_trace")) << (*s)["passes"].dump();
        EXPECT_GT((*s)["ssr_ms"].get<double>(), 0.0);
        EXPECT_GT((*s)["ssr_steps_mean"].get<double>(), 0.0);
        EXPECT_GT((*s)["ssr_hit_rate"].get<double>(), 0.0);
        EXPECT_LE((*s)["ssr_hit_rate"].get<double>(), 1.0);
    }
    EXPECT_LT(hiz["ssr_steps_mean"].get<double>(), reference["ssr_steps_mean"].get<double>());
    EXPECT_LT(hiz["ssr_steps_max"].get<uint32_t>(), 128u);  // SsrSettings' maxIterations

    RunResult bad = runCandela(kTriangle + "--ssr linear");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("off, hiz or reference"), std::string::npos) << bad.output;
}

TEST(Cli, UnknownIblModeIsRejected) {
    RunResult r = runCandela(kTriangle + "--ibl fancy");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.output.find("split-sum, mobile or reference"), std::string::npos) << r.output;
    EXPECT_EQ(runCandela(kTriangle + "--env").exitCode, 2);
}

// Issue 22: every file the engine writes is complete or absent, and a failed write exits 1
// naming the path and the operating system's error.
TEST(Cli, EveryOutputFileOnAFullDiskFailsNamingThePathAndTheError) {
    CANDELA_SMALL_FILESYSTEM_OR_SKIP(disk);
    disk->fill();
    const std::filesystem::path dir = disk->dir();
    for (const std::string& output :
         {"--stats " + (dir / "s.json").string(), "--summary " + (dir / "s.md").string(),
          "--capture " + (dir / "c.exr").string(), "--capture " + (dir / "c.png").string(),
          "--audio-capture " + (dir / "a.wav").string()}) {
        const std::string path = output.substr(output.find(' ') + 1);
        RunResult r = runCandela(kTriangle + "--frames 1 " + output);
        EXPECT_EQ(r.exitCode, 1) << output << "\n" << r.output;
        EXPECT_NE(r.output.find(path + ": cannot write: No space left on device"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(r.output.find("captured"), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(path)) << "a partial file was left: " << path;
    }
}

TEST(Cli, StatsToDevFullFailsWithTheOsError) {
    if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    for (const char* option : {"--stats", "--summary"}) {
        RunResult r = runCandela(kTriangle + "--frames 1 " + option + " /dev/full");
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_NE(r.output.find("/dev/full: cannot write: No space left on device"),
                  std::string::npos)
            << r.output;
    }
}

// Issue 22: a sky that is a FIFO used to hang, a 20 GB sparse file ended in "std::bad_alloc"
// with no file named. Both now name the file and fall back to the neutral sky; `timeout`
// turns a regression into a failure instead of a stuck test.
TEST(Cli, SpecialOrHugeSkyFilesGiveTheNeutralSkyWithoutHanging) {
    auto dir = tempDir() / "special_sky";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto fifo = dir / "sky_fifo.exr";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto huge = dir / "sky_huge.exr";
    std::ofstream(huge).close();
    std::filesystem::resize_file(huge, 20ull * 1000 * 1000 * 1000);  // sparse: no disk used
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/ibl_spheres_garden.scene.json";
    const std::pair<std::filesystem::path, std::string> cases[] = {
        {fifo, "not a regular file (a FIFO)"},
        {huge, "over the limit of"},
        {"/dev/zero", "not a regular file (a character device)"}};
    for (const auto& [sky, problem] : cases) {
        RunResult r = runCandela("run " + scene + " --headless --size 32x32 --env " + sky.string() +
                                     " --stats " + (dir / "s.json").string(),
                                 "CANDELA_CACHE_DIR=" + (dir / "cache").string() + " timeout 300 ");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(sky.string()), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(problem), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("neutral uniform sky"), std::string::npos) << r.output;
        nlohmann::json stats = nlohmann::json::parse(readBytes(dir / "s.json"));
        EXPECT_TRUE(stats["environment"]["fallback"].get<bool>());
    }
}

TEST(Cli, InputScriptsThatAreDevicesOrDirectoriesAreRejected) {
    for (const char* input : {"/dev/zero", "/tmp"}) {
        RunResult r = runCandela(kTriangle + "--frames 1 --input " + input, "timeout 120 ");
        EXPECT_EQ(r.exitCode, 2) << input << "\n" << r.output;
        EXPECT_NE(
            r.output.find(std::string(input) + ": cannot open input script: not a regular file"),
            std::string::npos)
            << r.output;
    }
}

// Issue 22: a glTF without lights run with --env used to get the default 100,000 lux sun and
// its fill on top of the sky. Default lights now come only when there is neither a light nor a
// sky, and the run says what it added.
TEST(Cli, DefaultLightsOnlyWithoutLightsOrASkyAndTheRunSaysSo) {
    auto dir = tempDir() / "default_lights";
    std::filesystem::create_directories(dir);
    const std::string box =
        std::string(CANDELA_SHARED_ASSETS) + "/models/Box/Box.glb --headless --size 32x32 ";
    const std::string cache = "CANDELA_CACHE_DIR=" + (dir / "cache").string() + " ";
    RunResult plain = runCandela("run " + box + "--stats " + (dir / "plain.json").string(), cache);
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_NE(plain.output.find("added a default sun of 100000 lux and a fill"), std::string::npos)
        << plain.output;
    EXPECT_EQ(nlohmann::json::parse(readBytes(dir / "plain.json"))["lights"], 2);

    RunResult sky =
        runCandela("run " + box + "--env " + CANDELA_SHARED_ASSETS +
                       "/env/studio_small_03_1k.exr --stats " + (dir / "sky.json").string(),
                   cache);
    ASSERT_EQ(sky.exitCode, 0) << sky.output;
    EXPECT_EQ(sky.output.find("default sun"), std::string::npos) << sky.output;
    EXPECT_EQ(nlohmann::json::parse(readBytes(dir / "sky.json"))["lights"], 0);
}

// Issue 22: a light colour of 3e38 at 8,000 lm gave NaN/Inf texels and a black PNG; a finite
// but huge light or an EV100 of -64 or below left the EXR fine and the PNG black (tonemapping
// overflowed). Now the light is clamped with a warning naming the file and element, and the
// frame is finite and lit: the spot's pool is white, not black.
TEST(Cli, AbsurdLightsAndExposuresGiveAFiniteLitFrame) {
    auto dir = tempDir() / "absurd";
    std::filesystem::create_directories(dir);
    const nlohmann::json base = spotLightScene();
    struct Case {
        const char* name;
        std::function<void(nlohmann::json&)> change;
        const char* warning;  // expected on stderr, or nullptr
    };
    const Case cases[] = {
        {"colour",
         [](nlohmann::json& s) {
             s["entities"][1]["light"]["color"] = {3e38, 3e38, 3e38};
         },
         "/entities/1/light/color: warning"},
        {"lumens", [](nlohmann::json& s) { s["entities"][1]["light"]["lumens"] = 3e38; },
         "/entities/1/light/lumens: warning"},
        {"ev_minus_64", [](nlohmann::json& s) { s["entities"][2]["camera"]["manualEv100"] = -64; },
         nullptr},
        {"ev_minus_200",
         [](nlohmann::json& s) { s["entities"][2]["camera"]["manualEv100"] = -200; }, nullptr},
    };
    for (const Case& c : cases) {
        nlohmann::json scene = base;
        c.change(scene);
        const auto path = dir / (std::string(c.name) + ".scene.json");
        std::ofstream(path) << scene.dump();
        const auto png = dir / (std::string(c.name) + ".png");
        const auto exr = dir / (std::string(c.name) + ".exr");
        RunResult r = runCandela("run " + path.string() + " --headless --size 48x32 --capture " +
                                 exr.string() + " --capture " + png.string());
        ASSERT_EQ(r.exitCode, 0) << c.name << "\n" << r.output;
        EXPECT_EQ(r.output.find("NaN/Inf"), std::string::npos) << c.name << "\n" << r.output;
        if (c.warning) {
            EXPECT_NE(r.output.find(path.string() + ": " + c.warning), std::string::npos)
                << r.output;
        }
        std::string error;
        auto hdr = candela::golden::readHdrExr(exr, error);
        ASSERT_TRUE(hdr) << error;
        EXPECT_EQ(hdr->nonFiniteTexels, 0u) << c.name;
        auto ldr = candela::golden::readLdrPng(png, error);
        ASSERT_TRUE(ldr) << error;
        // The centre of the frame is the spot's pool on the floor: saturated, not black.
        const std::size_t centre = (std::size_t(ldr->height / 2) * ldr->width + ldr->width / 2) * 3;
        EXPECT_EQ(ldr->rgb[centre], 255) << c.name;
    }
}

// Issue 44: --size 16384x16384 passed the parser and failed 20 s later with
// VK_ERROR_OUT_OF_DEVICE_MEMORY and a validation error that never named --size. A size this
// device cannot hold is refused before anything is allocated, naming the flag and the limit.
TEST(Cli, ASizeTheDeviceCannotHoldIsRefusedUpFront) {
    for (const char* size : {"16384x16384", "8192x8192"}) {
        RunResult r = runCandela(std::string("run builtin:triangle --headless --size ") + size);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(std::string("--size ") + size + ": "), std::string::npos)
            << r.output;
        EXPECT_EQ(r.output.find("validation"), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("VK_ERROR"), std::string::npos) << r.output;
    }
    RunResult fits = runCandela("run builtin:triangle --headless --size 2048x64");
    EXPECT_EQ(fits.exitCode, 0) << fits.output;
}

// Issue 44: hair of 600,000 strands (under the documented 1,000,000) bound a 154 MB segment
// buffer whole, past maxStorageBufferRange (a validation error on lavapipe, undefined
// behaviour on a GPU). The segments are now bound as two ranges (hair_segment.glsl): a million
// strands (4 M segments) render without a validation message, and the strands in the second
// range are drawn (twice the strands, about twice the A-buffer's fragments).
TEST(Cli, HairPastOneBindingIsSplitAcrossTwoRanges) {
    auto dir = tempDir() / "hair_binding";
    std::filesystem::create_directories(dir);
    auto fragments = [&](int strands) {
        nlohmann::json scene = spotLightScene();
        scene["entities"][0]["hair"] = {{"count", strands}, {"length", 0.05}};
        const auto path = dir / (std::to_string(strands) + ".scene.json");
        std::ofstream(path) << scene.dump();
        const auto stats = dir / (std::to_string(strands) + ".json");
        RunResult r = runCandela("run " + path.string() + " --headless --size 64x48 --stats " +
                                 stats.string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find("warning: hair"), std::string::npos) << r.output;
        const nlohmann::json json = nlohmann::json::parse(readBytes(stats));
        EXPECT_EQ(json["validation_messages"], 0) << strands;
        return json["hair_nodes"].get<double>();
    };
    const double half = fragments(500000);  // 2 M segments: the first range only
    const double all = fragments(1000000);  // 4 M: both
    EXPECT_GT(all, 1.6 * half) << half << " " << all;
}

// Issue 44: values the engine accepts gave whole frames of NaN with exit code 0: a height fog
// falling off at 30/m seen from 3 m above its base (the optical depth of a ray diving below
// the base overflowed), an atmosphere whose coefficients are 1e38 (clamped now, with a warning
// naming the field), an EV100 of -130 under TAA (the exposure overflowed and the history's
// clipping box turned to Inf - Inf). Each frame is now finite and the run's stats say so.
TEST(Cli, HostileMediaAndExposuresGiveFiniteFrames) {
    auto dir = tempDir() / "hostile_media";
    std::filesystem::create_directories(dir);
    const nlohmann::json base = spotLightScene();
    const float cameraHeight = base["entities"][2]["transform"]["translation"][1];
    const nlohmann::json fog = {{"name", "fog"},
                                {"fog",
                                 {{"scattering", 0.5},
                                  {"absorption", 0.1},
                                  {"anisotropy", 0.3},
                                  {"heightFalloff", 30.0},
                                  {"baseHeight", cameraHeight - 3.0f}}}};
    nlohmann::json air = {{"name", "air"},
                          {"atmosphere",
                           {{"rayleighScattering", {1e38, 1e38, 1e38}},
                            {"mieScattering", 1e38},
                            {"ozoneAbsorption", {1e38, 0.0, 0.0}}}}};
    struct Case {
        const char* name;
        nlohmann::json extra;  // an entity added, or null
        float ev100;           // the camera's manual EV100, or NaN to keep the scene's
        const char* flags;
        const char* warning;  // expected on stderr, or nullptr
    };
    const float keep = std::numeric_limits<float>::quiet_NaN();
    const Case cases[] = {
        {"fog_volumes", fog, keep, "--volumetrics volumes", nullptr},
        {"fog_froxels", fog, keep, "--volumetrics froxels", nullptr},
        {"atmosphere", air, keep, "", "/entities/3/atmosphere/rayleighScattering: warning"},
        {"ev_minus_130_taa", nullptr, -130.0f, "--aa taa", nullptr},
    };
    for (const Case& c : cases) {
        nlohmann::json scene = base;
        if (!c.extra.is_null()) scene["entities"].push_back(c.extra);
        if (!std::isnan(c.ev100)) scene["entities"][2]["camera"]["manualEv100"] = c.ev100;
        const auto path = dir / (std::string(c.name) + ".scene.json");
        std::ofstream(path) << scene.dump();
        const auto stats = dir / (std::string(c.name) + ".json");
        RunResult r = runCandela("run " + path.string() + " --headless --size 48x32 --frames 3 " +
                                 c.flags + " --stats " + stats.string());
        EXPECT_EQ(r.exitCode, 0) << c.name << "\n" << r.output;
        EXPECT_EQ(r.output.find("not finite"), std::string::npos) << c.name << "\n" << r.output;
        if (c.warning) {
            EXPECT_NE(r.output.find(path.string() + ": " + c.warning), std::string::npos)
                << r.output;
        }
        const nlohmann::json json = nlohmann::json::parse(readBytes(stats));
        EXPECT_EQ(json["nonfinite_pixels"], 0) << c.name;
        EXPECT_EQ(json["nonfinite_source"], "") << c.name;
        EXPECT_EQ(json["validation_messages"], 0) << c.name;
    }
}

// /dev/stdout is an open descriptor, not a place for a temporary file: the stats go to the
// pipe, or are appended to the file the shell redirected stdout to.
TEST(Cli, StatsToDevStdoutReachThePipeOrTheRedirectedFile) {
    RunResult piped = runCandela(kTriangle + "--frames 1 --stats /dev/stdout");
    EXPECT_EQ(piped.exitCode, 0) << piped.output;
    EXPECT_NE(piped.output.find("\"frames\": 1"), std::string::npos) << piped.output;

    const auto file = tempDir() / "stdout.txt";
    const std::string command = std::string(CANDELA_EXECUTABLE) + " " + kTriangle +
                                "--frames 1 --stats /dev/stdout > " + file.string() + " 2>&1";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readBytes(file);
    EXPECT_NE(readBytes(file).find("\"frames\": 1"), std::string::npos) << readBytes(file);
}

// The IBL cache is an optimisation: on a full disk the run still renders (exit 0), warns with
// the entry's path and the OS error, and leaves no partial entry for the next run to trip on.
TEST(Cli, AFullCacheDiskIsAWarningAndLeavesNoPartialEntry) {
    CANDELA_SMALL_FILESYSTEM_OR_SKIP(disk);
    const auto cache = disk->dir() / "cache";
    std::filesystem::create_directories(cache);
    disk->fill();
    RunResult r = runCandela(std::string("run ") + CANDELA_SOURCE_DIR +
                                 "/tests/scenes/ibl_spheres_garden.scene.json --headless "
                                 "--size 32x32 --frames 1",
                             "CANDELA_CACHE_DIR=" + cache.string() + " ");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("environment cache not written"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(cache.string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::is_empty(cache)) << "a partial cache entry was left";
}

// Issue 21: anisotropy and clear coat are compiled into the frames whose materials use them
// (stats `features`: material_anisotropy, material_clear_coat) and out of the others.
// Issue 21: material layers too (the G-buffer's layered variant).
TEST(Cli, MaterialExtensionFeaturesOnlyInFramesThatUseThem) {
    auto dir = tempDir();
    auto features = [&](const std::string& name) {
        const std::string scene =
            std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/" + name + ".scene.json";
        RunResult r = runCandela("run " + scene + " --headless --size 32x32 --stats " +
                                 (dir / (name + ".json")).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(readBytes(dir / (name + ".json")))["features"]
            .get<std::vector<std::string>>();
    };
    auto has = [](const std::vector<std::string>& f, const char* name) {
        return std::find(f.begin(), f.end(), name) != f.end();
    };
    const auto plain = features("sphere_grid_point");
    EXPECT_FALSE(has(plain, "material_anisotropy"));
    EXPECT_FALSE(has(plain, "material_clear_coat"));
    const auto brushed = features("anisotropy_strength");
    EXPECT_TRUE(has(brushed, "material_anisotropy"));
    EXPECT_FALSE(has(brushed, "material_clear_coat"));
    const auto coated = features("clear_coat");
    EXPECT_FALSE(has(coated, "material_anisotropy"));
    EXPECT_TRUE(has(coated, "material_clear_coat"));
    EXPECT_FALSE(has(plain, "material_layers"));
    EXPECT_FALSE(has(coated, "material_layers"));
    const auto layered = features("layered_material");
    EXPECT_TRUE(has(layered, "material_layers"));
    EXPECT_FALSE(has(layered, "material_clear_coat"));
}

// Issue 24: --aa, --bloom and --exposure reach the renderer and --stats reports taa_ms,
// bloom_ms and exposure_ev100; the scene file's "aa" is used when no flag is given.
TEST(Cli, AntialiasingBloomAndExposureFlagsAndStats) {
    auto dir = tempDir();
    const std::string scene =
        std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/sphere_grid_point.scene.json";
    auto stats = [&](const std::string& name, const std::string& args) {
        RunResult r = runCandela("run " + args + " --headless --size 32x32 --frames 3 --stats " +
                                 (dir / (name + ".json")).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(readBytes(dir / (name + ".json")));
    };
    auto has = [](const nlohmann::json& json, const char* feature) {
        const auto f = json["features"].get<std::vector<std::string>>();
        return std::find(f.begin(), f.end(), feature) != f.end();
    };
    const nlohmann::json defaults = stats("default", scene);
    EXPECT_TRUE(has(defaults, "taa"));
    EXPECT_TRUE(has(defaults, "bloom"));
    EXPECT_FALSE(has(defaults, "auto_exposure"));  // manual unless asked
    EXPECT_GT(defaults["taa_ms"].get<double>(), 0.0);
    EXPECT_GT(defaults["bloom_ms"].get<double>(), 0.0);
    const nlohmann::json fxaa =
        stats("fxaa", scene + " --aa fxaa --bloom 0 --exposure auto --exposure-compensation 1");
    EXPECT_TRUE(has(fxaa, "fxaa"));
    EXPECT_FALSE(has(fxaa, "taa"));
    EXPECT_FALSE(has(fxaa, "bloom"));
    EXPECT_TRUE(has(fxaa, "auto_exposure"));
    EXPECT_EQ(fxaa["taa_ms"].get<double>(), 0.0);
    // Metered from the frame, not the camera's; adapted one stop below it (compensation +1).
    EXPECT_NEAR(fxaa["exposure_adapted_ev100"].get<double>(),
                fxaa["exposure_ev100"].get<double>() - 1.0, 0.05);

    RunResult bad = runCandela(kTriangle + "--aa msaa");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("--aa needs off, fxaa, taa or gbaa"), std::string::npos)
        << bad.output;
}

// Issues 16, 17 and 24: a scene file's top-level "scattering", "volumetrics" and
// "sky_occlusion" choose the light shafts, the medium's lighting and the sky's occlusion, and
// the command line's flags override them.
TEST(Cli, SceneFileChoosesScatteringAndVolumetricsAndFlagsOverrideIt) {
    auto dir = tempDir() / "scattering_setting";
    std::filesystem::create_directories(dir);
    nlohmann::json scene = nlohmann::json::parse(
        readBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/atmosphere_sky.scene.json"));
    scene["scattering"] = "off";
    scene["volumetrics"] = "off";
    scene["sky_occlusion"] = "off";  // on by default with an atmosphere
    scene["volume_proxies"] = "on";  // seen only where --volumetrics volumes overrides "off"
    scene["entities"].push_back({{"name", "dust"}, {"fog", {{"scattering", 0.05}}}});
    const auto scenePath = dir / "air.scene.json";
    std::ofstream(scenePath) << scene.dump(2);
    auto run = [&](const std::string& name, const std::string& extra) {
        RunResult r = runCandela("run " + scenePath.string() +
                                 " --headless --size 32x32 --frames 1 --aa off --ssr off --ao off "
                                 "--bloom 0 --scattering-slices 16 --scattering-samples 32 "
                                 "--stats " +
                                 (dir / (name + ".json")).string() + extra);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(readBytes(dir / (name + ".json")));
    };
    auto ranPassesStartingWith = [](const nlohmann::json& stats, const std::string& prefix) {
        int count = 0;
        for (const auto& [name, ms] : stats["passes"].items())
            count += name.rfind(prefix, 0) == 0 ? 1 : 0;
        return count;
    };
    const nlohmann::json off = run("off", "");
    EXPECT_EQ(off["scattering_samples"].get<double>(), 0.0) << off.dump();
    EXPECT_EQ(ranPassesStartingWith(off, "scattering"), 0) << off["passes"].dump();
    EXPECT_EQ(ranPassesStartingWith(off, "volumetrics"), 0) << off["passes"].dump();
    auto hasFeature = [](const nlohmann::json& stats, const char* feature) {
        const auto features = stats["features"].get<std::vector<std::string>>();
        return std::find(features.begin(), features.end(), feature) != features.end();
    };
    EXPECT_FALSE(hasFeature(off, "sky_occlusion")) << off["features"].dump();
    const nlohmann::json on =
        run("on", " --scattering epipolar --volumetrics froxels --sky-occlusion on");
    EXPECT_TRUE(hasFeature(on, "sky_occlusion")) << on["features"].dump();
    EXPECT_GT(on["scattering_samples"].get<double>(), 0.0) << on.dump();
    EXPECT_GT(ranPassesStartingWith(on, "scattering"), 0) << on["passes"].dump();
    EXPECT_TRUE(on["passes"].contains("volumetrics_froxel_light")) << on["passes"].dump();
    EXPECT_EQ(on["validation_messages"].get<int>(), 0);
    // The per-light volumes find their lights as the file says (proxy meshes), unless the flag
    // says otherwise (tile lists).
    const nlohmann::json proxies = run("proxies", " --scattering off --volumetrics volumes");
    EXPECT_TRUE(proxies["passes"].contains("volumetrics_volumes_proxies"))
        << proxies["passes"].dump();
    EXPECT_FALSE(proxies["passes"].contains("volumetrics_volumes_march"));
    const nlohmann::json lists =
        run("lists", " --scattering off --volumetrics volumes --volume-proxies off");
    EXPECT_TRUE(lists["passes"].contains("volumetrics_volumes_march")) << lists["passes"].dump();
    EXPECT_FALSE(lists["passes"].contains("volumetrics_volumes_proxies"));
    EXPECT_EQ(proxies["validation_messages"].get<int>() + lists["validation_messages"].get<int>(),
              0);
}

// Issue 17: with a medium and no choice made, the scene's lights choose the volumetrics: the
// per-light volumes below 16 lights that light the medium, froxels from 16 (where froxels cost
// less, docs/speed-vs-error.md); lights whose "volumetric" is 0 do not count.
TEST(Cli, VolumetricsDefaultFollowsTheLightsInTheMedium) {
    auto dir = tempDir() / "volumetrics_default";
    std::filesystem::create_directories(dir);
    nlohmann::json scene = nlohmann::json::parse(
        readBytes(std::string(CANDELA_SOURCE_DIR) + "/tests/scenes/spot_light.scene.json"));
    scene["entities"].push_back({{"name", "dust"}, {"fog", {{"scattering", 0.05}}}});
    // The scene's spot plus `extra` small point lights, `volumetric` each.
    auto ran = [&](const std::string& name, int extra, double volumetric) {
        nlohmann::json lit = scene;
        for (int i = 0; i < extra; ++i) {
            lit["entities"].push_back(
                {{"name", "bulb" + std::to_string(i)},
                 {"light",
                  {{"type", "point"},
                   {"lumens", 100.0},
                   {"attenuationRadius", 1.0},
                   {"volumetric", volumetric}}},
                 {"transform", {{"translation", {0.2 * i - 1.5, 1.0, 0.0}}}}});
        }
        const auto scenePath = dir / (name + ".scene.json");
        std::ofstream(scenePath) << lit.dump();
        RunResult r = runCandela("run " + scenePath.string() +
                                 " --headless --size 32x32 --frames 1 --aa off --ssr off --ao off "
                                 "--bloom 0 --stats " +
                                 (dir / (name + ".json")).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        const nlohmann::json stats = nlohmann::json::parse(readBytes(dir / (name + ".json")));
        EXPECT_EQ(stats["validation_messages"].get<int>(), 0);
        return stats["passes"];
    };
    const nlohmann::json few = ran("few", 14, 1.0);  // 15 lights
    EXPECT_TRUE(few.contains("volumetrics_volumes_march")) << few.dump();
    EXPECT_FALSE(few.contains("volumetrics_froxel_light")) << few.dump();
    const nlohmann::json many = ran("many", 15, 1.0);  // 16 lights
    EXPECT_TRUE(many.contains("volumetrics_froxel_light")) << many.dump();
    EXPECT_FALSE(many.contains("volumetrics_volumes_march")) << many.dump();
    const nlohmann::json dark = ran("dark", 15, 0.0);  // 16 lights, 15 of them not in the medium
    EXPECT_TRUE(dark.contains("volumetrics_volumes_march")) << dark.dump();
}

// Issue 16: --ibl reference samples the atmosphere's sky by a table read back from its cube,
// which the first frame renders; that frame lights by the split sum (with a note) and the
// second by the reference, with no validation message. The reference lands near the split
// sum (mean within 10 %: the split sum's error on these rough surfaces is a few per cent).
TEST(Cli, IblReferenceUnderAnAtmosphereStartsOnTheSecondFrame) {
    auto dir = tempDir() / "ibl_reference_atmosphere";
    std::filesystem::create_directories(dir);
    auto render = [&](const std::string& name, const std::string& ibl) {
        RunResult r = runCandela("run " + std::string(CANDELA_SOURCE_DIR) +
                                 "/tests/scenes/atmosphere_sky.scene.json --headless --size "
                                 "32x32 --frames 2 --aa off --ssr off --ao off --bloom 0 "
                                 "--scattering off --ibl " +
                                 ibl + " --stats " + (dir / (name + ".json")).string() +
                                 " --capture " + (dir / (name + ".exr")).string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        nlohmann::json stats = nlohmann::json::parse(readBytes(dir / (name + ".json")));
        EXPECT_EQ(stats["validation_messages"].get<int>(), 0) << r.output;
        candela::content::Diagnostics diagnostics;
        auto image = candela::content::readExrImage(dir / (name + ".exr"), diagnostics);
        double sum = 0.0;
        for (uint32_t y = 0; image && y < image->image.height; ++y)
            for (uint32_t x = 0; x < image->image.width; ++x)
                sum += image->image.texel(x, y)[1];
        return std::make_pair(stats, sum);
    };
    const auto [reference, referenceSum] = render("reference", "reference");
    const auto features = reference["features"].get<std::vector<std::string>>();
    EXPECT_NE(std::find(features.begin(), features.end(), "ibl_reference"), features.end());
    const auto [splitSum, splitSumSum] = render("split_sum", "split-sum");
    ASSERT_GT(splitSumSum, 0.0);
    EXPECT_NEAR(referenceSum / splitSumSum, 1.0, 0.1);
}

// Issue 46: --stats "physics" (present once a scene has colliders: the frames' physics time
// and what the world held) and --physics-debug (colliders drawn as wires, validation clean).
// Issue 47: --audio-capture writes the loopback mix in step with the headless frames, the
// same bytes run after run; a bad clip is an error naming it, and the run goes on.
TEST(Cli, AudioCaptureWritesWhatThePlayerHears) {
    auto dir = tempDir();
    std::filesystem::create_directories(dir / "sounds");
    std::vector<float> tone(4800);  // 0.1 s of 1 kHz at 0.5: whole periods, looped
    for (std::size_t i = 0; i < tone.size(); ++i)
        tone[i] = 0.5f * float(std::sin(2 * std::numbers::pi * 1000.0 * double(i) / 48000.0));
    ASSERT_EQ(candela::content::writeFileAtomically(dir / "sounds" / "tone.wav",
                                                    candela::audio::encodeWav16(tone, 48000, 1)),
              "");
    std::ofstream(dir / "sounds" / "noise.wav") << "not a sound";
    const std::filesystem::path scene = dir / "beep.scene.json";
    std::ofstream(scene) << R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "camera", "transform": {"translation": [0, 0, 0]}, "camera": {}},
        {"name": "beep", "transform": {"translation": [-4, 0, 0]},
         "audioSource": {"clip": "sounds/tone.wav", "loop": true, "gain": 1.0, "spatial": true}},
        {"name": "bad", "audioSource": {"clip": "sounds/noise.wav"}}]})";
    const auto run = [&](const std::string& name) {
        return runCandela("run " + scene.string() + " --headless --size 32x32 --frames 12 " +
                          "--audio-capture " + (dir / name).string() + " --stats " +
                          (dir / (name + ".json")).string());
    };
    const RunResult first = run("a.wav");
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("noise.wav: error: not an audio clip"), std::string::npos)
        << first.output;
    const std::string bytes = readBytes(dir / "a.wav");
    // 12 frames of 1/30 s: 19,200 stereo 16-bit frames after the 44-byte header.
    ASSERT_EQ(bytes.size(), 44u + 12u * 1600u * 4u);
    EXPECT_EQ(bytes.substr(0, 4), "RIFF");
    std::vector<float> left, right;
    for (std::size_t at = 44; at + 4 <= bytes.size(); at += 4) {
        const auto sample = [&](std::size_t i) {
            return float(std::int16_t(std::uint16_t(std::uint8_t(bytes[i])) |
                                      std::uint16_t(std::uint8_t(bytes[i + 1])) << 8)) /
                   32767.0f;
        };
        left.push_back(sample(at));
        right.push_back(sample(at + 2));
    }
    const auto rms = [](const std::vector<float>& v) {
        double sum = 0;
        for (float x : v)
            sum += double(x) * x;
        return std::sqrt(sum / double(v.size()));
    };
    // 4 m to the camera's left: a quarter of the clip's RMS, all in the left channel.
    EXPECT_NEAR(rms(left), 0.5 / std::sqrt(2.0) / 4.0, 0.002);
    EXPECT_LT(rms(right), 1e-4);
    const nlohmann::json stats = nlohmann::json::parse(readBytes(dir / "a.wav.json"));
    ASSERT_TRUE(stats.contains("audio")) << stats.dump();
    EXPECT_EQ(stats["audio"]["voices_max"], 1);
    EXPECT_EQ(stats["audio"]["frames"], 12);

    const RunResult second = run("b.wav");
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_EQ(readBytes(dir / "b.wav"), bytes) << "the same run mixes the same bytes";

    const RunResult notWav = runCandela(kTriangle + "--audio-capture " + (dir / "a.mp3").string());
    EXPECT_EQ(notWav.exitCode, 2);
    EXPECT_NE(notWav.output.find("must end in .wav"), std::string::npos) << notWav.output;
    // A scene without sounds opens no audio device and has no "audio" stats.
    const RunResult silent = runCandela(kTriangle + "--stats " + (dir / "t.json").string());
    ASSERT_EQ(silent.exitCode, 0) << silent.output;
    EXPECT_FALSE(nlohmann::json::parse(readBytes(dir / "t.json")).contains("audio"));
}

TEST(Cli, PhysicsStatsAndDebugWires) {
    auto dir = tempDir();
    const std::filesystem::path scene = dir / "drop.scene.json";
    std::ofstream(scene) << R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "camera", "transform": {"translation": [0, 2, 6], "lookAt": [0, 0.5, 0]},
         "camera": {"exposureMode": "manual", "manualEv100": 0}},
        {"name": "floor", "transform": {"translation": [0, -0.5, 0]},
         "collider": {"shape": "box", "halfExtents": [3, 0.5, 3]}},
        {"name": "ball", "transform": {"translation": [0, 2, 0]},
         "rigidBody": {"type": "dynamic"}, "collider": {"shape": "sphere"}}]})";
    const std::string flags = scene.string() + " --size 64x48 --frames 30 --aa off --bloom 0";
    CapturedRun plain = captureRun(dir, "plain", flags);
    CapturedRun debug = captureRun(dir, "debug", flags + " --physics-debug");
    ASSERT_TRUE(plain.stats.contains("physics")) << plain.stats.dump();
    const nlohmann::json& physics = plain.stats["physics"];
    EXPECT_EQ(physics["frames"], 30);
    // Two 1/60 s steps per 1/30 s frame; the first frame advances no time.
    EXPECT_EQ(physics["steps"], 58);
    EXPECT_EQ(physics["bodies_max"], 2);
    EXPECT_GT(physics["simulate_ms_median"].get<double>(), 0.0);
    EXPECT_EQ(debug.stats["validation_messages"], 0);
    ASSERT_TRUE(plain.capture && debug.capture);
    const LuminanceSums sums = luminanceSums(debug.capture->image, plain.capture->image);
    EXPECT_GT(sums.image, sums.reference) << "the wires glow over the black scene";
    const RunResult triangle = runCandela(kTriangle + "--stats " + (dir / "t.json").string());
    ASSERT_EQ(triangle.exitCode, 0) << triangle.output;
    EXPECT_FALSE(nlohmann::json::parse(readBytes(dir / "t.json")).contains("physics"));
}
