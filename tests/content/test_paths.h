#pragma once
// Per-test scratch files under the system temp directory.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <string>

namespace candela::content::testing {

// A fresh path unique to this process and test, in a directory that exists.
inline std::filesystem::path tempPath(const std::string& fileName) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("candela-content-" + std::to_string(::getpid())) /
                                (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    return dir / fileName;
}

}  // namespace candela::content::testing
