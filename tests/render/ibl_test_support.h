#pragma once
// Test support shared by the IBL tests: the shared assets, scratch folders, and the three IBL
// modes (one device per process: offscreen_frame.h's sharedContext).
#include <filesystem>
#include <string>

#include "candela/render/gpu_context.h"
#include "candela/render/renderer_options.h"
#include "offscreen_frame.h"
#include "test_scene.h"

namespace candela::render::test {

inline std::filesystem::path sharedAsset(const std::string& relative) {
    return std::filesystem::path(CANDELA_SHARED_ASSETS) / relative;
}

// An empty folder under the temp directory (removed first if it exists).
inline std::filesystem::path freshDirectory(const std::string& name) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() / ("candela_ibl_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline constexpr IblMode kIblModes[] = {IblMode::SplitSum, IblMode::Mobile, IblMode::Reference};

// A sphere of radius 1 at the origin under `environment`, seen from 3 m in a 64x64 frame: the
// centre 16x16 pixels are on it.
inline TestScene sphereInSky(const content::Material& material,
                             std::shared_ptr<const Environment> environment) {
    TestScene scene;
    scene.width = 64;
    scene.height = 64;
    scene.add(content::makeSphere(1.0f, 96, 48), material);
    scene.lookAt({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    scene.environment = std::move(environment);
    return scene;
}

}  // namespace candela::render::test
