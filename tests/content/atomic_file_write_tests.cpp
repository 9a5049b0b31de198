// The engine's one file writer: a full disk, /dev/full, read-only files, file modes and
// owners, symbolic links, long names, FIFOs and directories. Every failure must name the
// path and the operating system's error, and leave the old file as it was.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "candela/content/atomic_file_write.h"
#include "candela/content/exr_image.h"
#include "candela/content/png_writer.h"
#include "full_filesystem.h"
#include "test_paths.h"

namespace {

namespace fs = std::filesystem;
using candela::content::AtomicWriteOptions;
using candela::content::writeFileAtomically;
using candela::content::testing::tempPath;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

unsigned modeOf(const fs::path& path) {
    struct stat st {};
    EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
    return st.st_mode & 07777;
}

// Everything in `dir` but the named files: temporaries that a writer left behind.
std::vector<std::string> leftovers(const fs::path& dir, const std::vector<std::string>& known) {
    std::vector<std::string> extra;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (std::find(known.begin(), known.end(), name) == known.end()) extra.push_back(name);
    }
    return extra;
}

TEST(AtomicFileWrite, FullDiskFailsNamingPathAndErrorAndKeepsTheOldFile) {
    CANDELA_SMALL_FILESYSTEM_OR_SKIP(disk);
    const fs::path old = disk->dir() / "old.json";
    writeText(old, "the old contents");
    disk->fill();
    for (const fs::path& path : {old, disk->dir() / "new.json"}) {
        const std::string error = writeFileAtomically(path, std::string(100, 'n'));
        EXPECT_NE(error.find(path.string()), std::string::npos) << error;
        EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
    }
    EXPECT_EQ(readText(old), "the old contents");
    EXPECT_FALSE(fs::exists(disk->dir() / "new.json"));
    EXPECT_TRUE(leftovers(disk->dir(), {"old.json", "filler"}).empty());
}

TEST(AtomicFileWrite, ImageWritersFailOnAFullDisk) {
    CANDELA_SMALL_FILESYSTEM_OR_SKIP(disk);
    disk->fill();
    const std::vector<float> rgb(4 * 4 * 3, 0.5f);
    const std::vector<std::uint8_t> rgba(4 * 4 * 4, 128);
    const fs::path exr = disk->dir() / "small.exr";
    const fs::path png = disk->dir() / "small.png";
    const std::string exrError = candela::content::writeExrRgbFloat(exr, 4, 4, rgb.data());
    const std::string pngError = candela::content::writePng(png, 4, 4, 4, rgba.data());
    for (const std::string& error : {exrError, pngError}) {
        EXPECT_NE(error.find(disk->dir().string()), std::string::npos) << error;
        EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
    }
    EXPECT_FALSE(fs::exists(exr));
    EXPECT_FALSE(fs::exists(png));
}

TEST(AtomicFileWrite, DevFullFailsWithTheOsError) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    const std::string error = writeFileAtomically("/dev/full", "stats");
    EXPECT_NE(error.find("/dev/full"), std::string::npos) << error;
    EXPECT_NE(error.find("No space left on device"), std::string::npos) << error;
}

TEST(AtomicFileWrite, WrittenImagesReadBack) {
    const fs::path exr = tempPath("small.exr");
    const std::vector<float> rgb = {0.25f, 0.5f, 1.0f, 2.0f, 4.0f, 8.0f};
    ASSERT_EQ(candela::content::writeExrRgbFloat(exr, 2, 1, rgb.data()), "");
    candela::content::Diagnostics diagnostics;
    const auto image = candela::content::readExrImage(exr, diagnostics);
    ASSERT_TRUE(image.has_value());
    ASSERT_EQ(image->image.width, 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_EQ(image->image.rgba[i * 4 + c], rgb[i * 3 + c]);
    }
}

TEST(AtomicFileWrite, KeepsTheModeOfTheFileItReplaces) {
    for (unsigned mode : {0600u, 0640u, 0755u, 0444u}) {
        const fs::path path = tempPath("mode.json");
        writeText(path, "old");
        ASSERT_EQ(::chmod(path.c_str(), mode), 0);
        ASSERT_EQ(writeFileAtomically(path, "new", AtomicWriteOptions{.replaceReadOnly = true}),
                  "");
        EXPECT_EQ(readText(path), "new");
        EXPECT_EQ(modeOf(path), mode);
        fs::remove(path);
    }
}

TEST(AtomicFileWrite, KeepsTheOwnerOfTheFileItReplaces) {
    if (::geteuid() != 0) GTEST_SKIP() << "changing a file's owner needs root";
    const fs::path path = tempPath("owned.json");
    writeText(path, "old");
    ASSERT_EQ(::chown(path.c_str(), 4321, 4322), 0);
    ASSERT_EQ(writeFileAtomically(path, "new"), "");
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_uid, 4321u);
    EXPECT_EQ(st.st_gid, 4322u);
}

TEST(AtomicFileWrite, RefusesToReplaceAReadOnlyFileUnlessAsked) {
    const fs::path path = tempPath("read_only.scene.json");
    writeText(path, "keep me");
    ASSERT_EQ(::chmod(path.c_str(), 0444), 0);
    const std::string error = writeFileAtomically(path, "replaced");
    EXPECT_NE(error.find(path.string()), std::string::npos) << error;
    EXPECT_NE(error.find("read-only"), std::string::npos) << error;
    EXPECT_EQ(readText(path), "keep me");
    ASSERT_EQ(writeFileAtomically(path, "replaced", AtomicWriteOptions{.replaceReadOnly = true}),
              "");
    EXPECT_EQ(readText(path), "replaced");
    EXPECT_EQ(modeOf(path), 0444u);
}

TEST(AtomicFileWrite, WritesThroughASymbolicLinkToItsTarget) {
    const fs::path linkDir = tempPath("links");
    const fs::path targetDir = tempPath("targets");
    fs::create_directories(linkDir);
    fs::create_directories(targetDir);
    writeText(targetDir / "scene.json", "old");
    ASSERT_EQ(::chmod((targetDir / "scene.json").c_str(), 0600), 0);
    // A relative link, two hops: link -> hop -> ../targets/scene.json
    fs::create_symlink("../targets/scene.json", linkDir / "hop.json");
    fs::create_symlink("hop.json", linkDir / "scene.json");
    ASSERT_EQ(writeFileAtomically(linkDir / "scene.json", "new"), "");
    EXPECT_TRUE(fs::is_symlink(linkDir / "scene.json"));
    EXPECT_TRUE(fs::is_symlink(linkDir / "hop.json"));
    EXPECT_EQ(readText(targetDir / "scene.json"), "new");
    EXPECT_EQ(modeOf(targetDir / "scene.json"), 0600u);
    EXPECT_TRUE(leftovers(linkDir, {"scene.json", "hop.json"}).empty());
    EXPECT_TRUE(leftovers(targetDir, {"scene.json"}).empty());
}

TEST(AtomicFileWrite, ALinkLoopIsAnError) {
    const fs::path dir = tempPath("loop");
    fs::create_directories(dir);
    fs::create_symlink("b", dir / "a");
    fs::create_symlink("a", dir / "b");
    const std::string error = writeFileAtomically(dir / "a", "x");
    EXPECT_NE(error.find("symbolic link"), std::string::npos) << error;
}

TEST(AtomicFileWrite, ANameOf250CharactersCanBeReplaced) {
    const fs::path path = tempPath(std::string(240, 'n') + ".scene.json");
    ASSERT_EQ(path.filename().string().size(), 251u);
    writeText(path, "old");
    ASSERT_EQ(writeFileAtomically(path, "new"), "");
    EXPECT_EQ(readText(path), "new");
}

TEST(AtomicFileWrite, AFifoWithoutAReaderFailsInsteadOfHanging) {
    const fs::path path = tempPath("fifo");
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    const std::string error = writeFileAtomically(path, "x");
    EXPECT_NE(error.find(path.string()), std::string::npos) << error;
    EXPECT_TRUE(fs::is_fifo(path));
}

TEST(AtomicFileWrite, ADirectoryIsAnErrorNamingIt) {
    const fs::path dir = tempPath("a_directory");
    fs::create_directories(dir);
    const std::string error = writeFileAtomically(dir, "x");
    EXPECT_NE(error.find(dir.string()), std::string::npos) << error;
    EXPECT_NE(error.find("Is a directory"), std::string::npos) << error;
}

TEST(AtomicFileWrite, AMissingDirectoryIsAnErrorNamingThePath) {
    const fs::path path = tempPath("no_such_dir") / "file.json";
    const std::string error = writeFileAtomically(path, "x");
    EXPECT_NE(error.find(path.string()), std::string::npos) << error;
    EXPECT_NE(error.find("No such file or directory"), std::string::npos) << error;
}

}  // namespace
