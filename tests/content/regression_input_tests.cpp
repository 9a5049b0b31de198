// Replays every file under tests/content/regressions/{gltf,scene,exr,audio}/ through its loader.
// Files there are fuzzer finds and hand-made nasties; the test passes when nothing crashes
// (sanitizer builds turn memory errors into failures) and failures come with messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "candela/content/audio_clip.h"
#include "candela/content/exr_image.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/scene_file.h"

namespace candela::content {
namespace {

std::vector<std::filesystem::path> filesIn(const char* kind) {
    std::vector<std::filesystem::path> files;
    const auto folder = std::filesystem::path(CANDELA_CONTENT_TEST_DIR) / "regressions" / kind;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.is_regular_file() && entry.path().filename() != "README.md") {
            files.push_back(entry.path());
        }
    }
    return files;
}

std::vector<std::byte> bytesOf(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::byte> bytes(chars.size());
    std::copy_n(reinterpret_cast<const std::byte*>(chars.data()), chars.size(), bytes.begin());
    return bytes;
}

TEST(RegressionInputs, GltfFilesLoadOrFailWithAMessage) {
    for (const auto& path : filesIn("gltf")) {
        Diagnostics diagnostics;
        GltfLoadOptions options;
        options.allowExternalFiles = false;
        auto model = loadGltfFromMemory(bytesOf(path), path, diagnostics, options);
        if (!model) {
            EXPECT_TRUE(diagnostics.hasErrors()) << path;
        }
    }
}

TEST(RegressionInputs, SceneFilesLoadOrFailWithAMessage) {
    for (const auto& path : filesIn("scene")) {
        Diagnostics diagnostics;
        auto scene = loadSceneFile(path, diagnostics);
        if (!scene) {
            EXPECT_TRUE(diagnostics.hasErrors()) << path;
        }
    }
}

TEST(RegressionInputs, ExrFilesLoadOrFailWithAMessage) {
    for (const auto& path : filesIn("exr")) {
        Diagnostics diagnostics;
        auto image = readExrImage(path, diagnostics);
        if (!image) {
            EXPECT_TRUE(diagnostics.hasErrors()) << path;
        }
    }
}

// Clips a fuzzer broke decode or fail with a message, and a decoded one streams to its end.
// audio/vorbis_header_leak.ogg: stb_vorbis, the first decoder, leaked its scratch memory when
// it rejected this damaged header (and dereferenced a null comment list on another input);
// Ogg Vorbis is now libvorbisfile's.
TEST(RegressionInputs, AudioClipsDecodeOrFailWithAMessage) {
    for (const auto& path : filesIn("audio")) {
        Diagnostics diagnostics;
        auto clip = loadAudioClip(path, diagnostics);
        if (!clip) {
            EXPECT_TRUE(diagnostics.hasErrors()) << path;
            continue;
        }
        AudioClipStream stream(clip);
        std::vector<float> chunk(2 * 4096);
        while (stream.read(chunk) > 0) {
        }
    }
}

}  // namespace
}  // namespace candela::content
