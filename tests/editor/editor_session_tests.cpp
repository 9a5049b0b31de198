// candela-editor driven by a script under a virtual display (ctest runs this binary through
// xvfb-run): a light edit is saved to the scene file and visible in the viewport, undo shows
// the old light again, and bad scripts or scenes fail with clear messages.
#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "candela/content/exr_image.h"
#include "candela/content/scene_file.h"
#include "full_filesystem.h"

namespace {

namespace fs = std::filesystem;
namespace content = candela::content;

const fs::path kScene = fs::path(CANDELA_SOURCE_DIR) / "tests/scenes/spot_light.scene.json";

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
    // Mean Rec. 709 luma over a rectangle, in 8-bit levels.
    double meanLuma(int x0, int y0, int x1, int y1) const {
        double sum = 0.0;
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const unsigned char* p = &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4];
                sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            }
        }
        return sum / double((x1 - x0) * (y1 - y0));
    }
};

Image readPng(const fs::path& path) {
    Image image;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 4);
    if (data) {
        image.rgba.assign(data, data + size_t(image.width) * size_t(image.height) * 4);
        stbi_image_free(data);
    }
    return image;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class EditorSession : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("candela_editor_session_" +
               std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir);
    }

    // Runs the editor on `scene` with `script`; returns its exit status, stderr in `errors`.
    int runEditor(const fs::path& scene, const std::string& script, std::string& errors) {
        const fs::path scriptPath = dir / "session.txt";
        std::ofstream(scriptPath) << script;
        const fs::path errPath = dir / "stderr.txt";
        const std::string command = std::string("\"") + CANDELA_EDITOR + "\" \"" + scene.string() +
                                    "\" --size 640x360 --script \"" + scriptPath.string() +
                                    "\" 2> \"" + errPath.string() + "\"";
        const int status = std::system(command.c_str());
        errors = readText(errPath);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    // Renders `scene` with `candela run` at the editor's size and returns the worst relative
    // difference of the editor's EXR screenshot from it (RGB); `editor` gets the screenshot.
    // `frames`: the frame of the scene the editor's screenshot shows (TAA, the default, makes
    // each frame of a scene differ from the one before).
    double differenceFromCandelaRun(const fs::path& scene, const fs::path& editorExr,
                                    std::optional<content::ExrImage>& editor, int frames = 1) {
        const fs::path runExr = dir / "run.exr";
        const std::string command = std::string("\"") + CANDELA_ENGINE + "\" run \"" +
                                    scene.string() + "\" --headless --size 640x360 --frames " +
                                    std::to_string(frames) + " --capture \"" + runExr.string() +
                                    "\" > /dev/null 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0);
        content::Diagnostics diagnostics;
        editor = content::readExrImage(editorExr, diagnostics);
        std::optional<content::ExrImage> run = content::readExrImage(runExr, diagnostics);
        if (!editor || !run || editor->image.width != run->image.width ||
            editor->image.height != run->image.height) {
            ADD_FAILURE() << "missing or differently sized captures";
            editor.reset();
            return 1.0;
        }
        double worst = 0.0;
        for (size_t i = 0; i < run->image.rgba.size(); ++i) {
            if (i % 4 == 3) continue;
            const double a = editor->image.rgba[i], b = run->image.rgba[i];
            worst = std::max(worst, std::abs(a - b) / std::max(std::abs(b), 1e-6));
        }
        return worst;
    }

    fs::path dir;
};

TEST_F(EditorSession, LightEditIsSavedShownAndUndone) {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run through xvfb-run (ctest does)";
    const std::string original = readText(kScene);
    const fs::path saved = dir / "edited.scene.json";
    std::string errors;
    const int status = runEditor(kScene,
                                 "select spot\n"
                                 "screenshot " +
                                     (dir / "before.png").string() +
                                     "\n"
                                     "set light.lumens 2000\n"
                                     "screenshot " +
                                     (dir / "after.png").string() +
                                     "\n"
                                     "undo\n"
                                     "screenshot " +
                                     (dir / "undone.png").string() +
                                     "\n"
                                     "redo\n"
                                     "save " +
                                     saved.string() +
                                     "\n"
                                     "quit\n",
                                 errors);
    ASSERT_EQ(status, 0) << errors;  // 3 would be validation messages
    EXPECT_EQ(readText(kScene), original) << "saving elsewhere must not touch the opened file";

    // The saved scene has the new value, and everything else the file had.
    content::Diagnostics diagnostics;
    std::optional<content::SceneDocument> doc = content::loadSceneFile(saved, diagnostics);
    ASSERT_TRUE(doc);
    EXPECT_TRUE(diagnostics.messages.empty());
    ASSERT_EQ(doc->entities.size(), 3u);
    ASSERT_TRUE(doc->entities[1].light);
    EXPECT_EQ(doc->entities[1].name, "spot");
    EXPECT_EQ(doc->entities[1].light->lumens, 2000.0f);
    ASSERT_TRUE(doc->entities[0].mesh);
    // The floor's glTF path was rebased to the new directory and still resolves.
    EXPECT_TRUE(fs::exists(content::resolveScenePath(saved, doc->entities[0].mesh->gltfPath)))
        << doc->entities[0].mesh->gltfPath;

    const Image before = readPng(dir / "before.png");
    const Image after = readPng(dir / "after.png");
    const Image undone = readPng(dir / "undone.png");
    ASSERT_EQ(before.width, 640);
    ASSERT_EQ(before.height, 360);
    ASSERT_EQ(after.width, 640);
    ASSERT_EQ(undone.width, 640);
    // The spot's pool of light on the floor, between the hierarchy (left) and inspector (right)
    // panels: a quarter of the light is visibly darker there.
    const int x0 = 250, y0 = 150, x1 = 390, y1 = 230;
    const double lit = before.meanLuma(x0, y0, x1, y1);
    const double dimmed = after.meanLuma(x0, y0, x1, y1);
    std::printf("lit pool mean luma (8-bit): 8000 lm %.1f, 2000 lm %.1f, after undo %.1f\n", lit,
                dimmed, undone.meanLuma(x0, y0, x1, y1));
    EXPECT_GT(lit, 150.0) << "the region is not the lit pool";
    EXPECT_LT(dimmed, lit * 0.8) << "before " << lit << ", after " << dimmed;
    // Undo brings the old light back (the renderer is deterministic).
    EXPECT_NEAR(undone.meanLuma(x0, y0, x1, y1), lit, 0.5);
}

// The editor renders what `candela run` renders: the same scene, camera and size give the same
// HDR radiance, sky and image-based lighting included (the editor once showed this scene's
// spheres black on grey: it never loaded the Sky component).
TEST_F(EditorSession, ViewportMatchesCandelaRunWithASky) {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run through xvfb-run (ctest does)";
    const fs::path scene =
        fs::path(CANDELA_SOURCE_DIR) / "tests/scenes/ibl_spheres_garden.scene.json";
    const fs::path editorExr = dir / "editor.exr";
    std::string errors;
    ASSERT_EQ(runEditor(scene, "screenshot " + editorExr.string() + "\nquit\n", errors), 0)
        << errors;
    std::optional<content::ExrImage> editor;
    const double worst = differenceFromCandelaRun(scene, editorExr, editor);
    ASSERT_TRUE(editor);
    std::printf("editor vs candela run: worst relative difference %.3g\n", worst);
    EXPECT_LE(worst, 1e-4);
    // Both show the garden sky behind the spheres, not the uniform clear colour a frame without
    // a sky has: the top row varies across the image.
    const float* left = editor->image.texel(0, 0);
    size_t differing = 0;
    for (uint32_t x = 0; x < editor->image.width; ++x) {
        differing += std::abs(editor->image.texel(x, 0)[1] - left[1]) > 1e-3f ? 1u : 0u;
    }
    EXPECT_GT(differing, editor->image.width / 2);
}

// Opening another scene from the editor hands the application a new world mid-run: the next
// frame shows that scene as `candela run` renders it, nothing of the first one left.
TEST_F(EditorSession, AnOpenedSceneReplacesTheWorldAsCandelaRunShowsIt) {
    ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run through xvfb-run (ctest does)";
    const fs::path garden =
        fs::path(CANDELA_SOURCE_DIR) / "tests/scenes/ibl_spheres_garden.scene.json";
    const fs::path editorExr = dir / "editor.exr";
    std::string errors;
    ASSERT_EQ(
        runEditor(kScene,
                  "open " + garden.string() + "\nscreenshot " + editorExr.string() + "\nquit\n",
                  errors),
        0)
        << errors;
    std::optional<content::ExrImage> editor;
    // The new world is shown from the frame of the `open` step on (the application restarts
    // TAA's history there), so the screenshot one step later is its second frame.
    const double worst = differenceFromCandelaRun(garden, editorExr, editor, 2);
    std::printf("opened scene vs candela run: worst relative difference %.3g\n", worst);
    EXPECT_LE(worst, 1e-4);
}

TEST_F(EditorSession, AFailingScriptStepNamesTheLineAndFails) {
    std::string errors;
    EXPECT_EQ(runEditor(kScene, "select spot\nselect nobody\nquit\n", errors), 1);
    EXPECT_NE(errors.find("session.txt:2: select: no entity named 'nobody'"), std::string::npos)
        << errors;
    EXPECT_EQ(runEditor(kScene, "select spot\nset light.lumen 3\nquit\n", errors), 1);
    EXPECT_NE(errors.find("session.txt:2: set: light.lumen: unknown property"), std::string::npos)
        << errors;
    EXPECT_EQ(runEditor(kScene, "frobnicate\n", errors), 2);
    EXPECT_NE(errors.find("session.txt:1: unknown step 'frobnicate'"), std::string::npos) << errors;
}

TEST_F(EditorSession, AMissingSceneIsABadArgument) {
    std::string errors;
    EXPECT_EQ(runEditor(dir / "missing.scene.json", "quit\n", errors), 2);
    EXPECT_NE(errors.find("missing.scene.json: no such file"), std::string::npos) << errors;
    // Issue 44: a device or a folder is named as what it is, not as missing.
    EXPECT_EQ(runEditor("/dev/zero", "quit\n", errors), 2);
    EXPECT_NE(errors.find("/dev/zero: not a regular file"), std::string::npos) << errors;
    EXPECT_EQ(errors.find("no such file"), std::string::npos) << errors;
    EXPECT_EQ(runEditor(dir, "quit\n", errors), 2);
    EXPECT_NE(errors.find("is a directory, not a scene file"), std::string::npos) << errors;
}

// Issue 22: saving over a file keeps what the file is. A read-only scene is refused unless the
// user says so, and keeps its mode; a symlinked scene stays a link and its target changes; a
// full disk is a failed step naming the file and the error.
TEST_F(EditorSession, SavingKeepsReadOnlyLinkedAndFullDiskScenesIntact) {
    const fs::path target = dir / "real.scene.json";
    fs::copy_file(kScene, target);
    ASSERT_EQ(::chmod(target.c_str(), 0444), 0);
    const std::string original = readText(target);
    std::string errors;
    EXPECT_EQ(runEditor(target, "select spot\nset light.lumens 2000\nsave\nquit\n", errors), 1);
    EXPECT_NE(errors.find(target.string() + ": the file is read-only (mode 0444)"),
              std::string::npos)
        << errors;
    EXPECT_EQ(readText(target), original);
    EXPECT_EQ(
        runEditor(target, "select spot\nset light.lumens 2000\nsave --replace-read-only\nquit\n",
                  errors),
        0)
        << errors;
    EXPECT_NE(readText(target), original);
    EXPECT_EQ(fs::status(target).permissions() & fs::perms::all, fs::perms(0444));

    ASSERT_EQ(::chmod(target.c_str(), 0600), 0);
    const fs::path link = dir / "link.scene.json";
    fs::create_symlink(target.filename(), link);
    EXPECT_EQ(runEditor(link, "select spot\nset light.lumens 1234\nsave\nquit\n", errors), 0)
        << errors;
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_NE(readText(target).find("1234"), std::string::npos);
    EXPECT_EQ(fs::status(target).permissions() & fs::perms::all, fs::perms(0600));

    CANDELA_SMALL_FILESYSTEM_OR_SKIP(disk);
    disk->fill();
    const fs::path full = disk->dir() / "saved.scene.json";
    EXPECT_EQ(runEditor(target, "save " + full.string() + "\nquit\n", errors), 1);
    EXPECT_NE(errors.find(full.string() + ": cannot write: No space left on device"),
              std::string::npos)
        << errors;
    EXPECT_FALSE(fs::exists(full));
}

}  // namespace
