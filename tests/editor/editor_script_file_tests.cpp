// The editor's --script reader (issue 22): /dev/zero used to end in std::bad_alloc and a
// directory ran as an empty script. Special and oversized files are refused, naming the file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "app/editor_script.h"

namespace candela::editor {
namespace {

TEST(EditorScriptFile, SpecialFilesAndHugeFilesAreRefusedBeforeReading) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("candela-editor-script-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path fifo = dir / "fifo.txt";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const std::filesystem::path huge = dir / "huge.txt";
    { std::ofstream(huge) << "quit\n"; }
    std::filesystem::resize_file(huge, EditorScript::kMaxFileBytes + 1);  // sparse
    const std::pair<std::filesystem::path, std::string> cases[] = {
        {"/dev/zero", "not a regular file (a character device)"},
        {dir, "not a regular file (a directory)"},
        {fifo, "not a regular file (a FIFO)"},
        {huge, "file is 16777217 bytes, over the limit of 16777216"},
        {dir / "missing.txt", "no such file"}};
    for (const auto& [path, problem] : cases) {
        std::string error;
        EXPECT_FALSE(EditorScript::load(path, error).has_value()) << path;
        EXPECT_EQ(error, path.string() + ": cannot read the script: " + problem);
    }
    std::filesystem::resize_file(huge, 5);
    std::string error;
    EXPECT_TRUE(EditorScript::load(huge, error).has_value()) << error;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace candela::editor
