#pragma once
// A real full disk for tests of file writers: a 64 KiB tmpfs mounted on a fresh directory and
// filled to the last block. Mounting needs root (CAP_SYS_ADMIN); where it is refused, tests
// skip with the reason (GTEST_SKIP) rather than pretend.
#include <sys/mount.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace candela::testing {

class FullFilesystem {
public:
    // nullptr and `whyNot` set when no filesystem could be mounted.
    static std::unique_ptr<FullFilesystem> mount(std::string& whyNot) {
        std::string pattern = (std::filesystem::temp_directory_path() / "candela-full-XXXXXX");
        if (::mkdtemp(pattern.data()) == nullptr) {
            whyNot = "mkdtemp: " + std::string(std::strerror(errno));
            return nullptr;
        }
        if (::mount("tmpfs", pattern.c_str(), "tmpfs", 0, "size=64k,mode=0777") != 0) {
            whyNot =
                "cannot mount a small tmpfs (needs root): " + std::string(std::strerror(errno));
            ::rmdir(pattern.c_str());
            return nullptr;
        }
        return std::unique_ptr<FullFilesystem>(new FullFilesystem(pattern));
    }

    ~FullFilesystem() {
        ::umount2(dir_.c_str(), MNT_DETACH);
        ::rmdir(dir_.c_str());
    }
    FullFilesystem(const FullFilesystem&) = delete;
    FullFilesystem& operator=(const FullFilesystem&) = delete;

    const std::filesystem::path& dir() const { return dir_; }

    // Takes every free block, so the next write of even one byte fails with ENOSPC. Files
    // made before this call stay as they are.
    void fill() const {
        std::ofstream filler(dir_ / "filler", std::ios::binary);
        const std::vector<char> block(4096, 'x');
        while (filler.write(block.data(), std::streamsize(block.size()))) {
        }
    }

private:
    explicit FullFilesystem(std::filesystem::path dir) : dir_(std::move(dir)) {}
    std::filesystem::path dir_;
};

}  // namespace candela::testing

// Declares `disk` (a mounted FullFilesystem, not yet filled) or skips the test with the reason.
#define CANDELA_SMALL_FILESYSTEM_OR_SKIP(disk)                         \
    std::string disk##WhyNot;                                          \
    auto disk = candela::testing::FullFilesystem::mount(disk##WhyNot); \
    if (!disk) GTEST_SKIP() << disk##WhyNot
