#pragma once
// Reads a whole file into memory with an upper bound, so a huge or special file cannot make a
// loader hang or allocate without limit. The file is opened without blocking and checked to
// be a regular file before anything is read: a FIFO, a device such as /dev/zero, or a
// directory is an error, never a hang or an empty read.
//
//   FileBytes file = readFileBytes(path, 16 * 1024 * 1024);
//   if (!file.error.empty()) report(path.string() + ": " + file.error);
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace candela::content {

struct FileBytes {
    std::vector<std::byte> bytes;
    // Empty when the read succeeded, else the problem without the path (the caller names
    // the file): "no such file", "not a regular file (a FIFO)", "file is N bytes, over the
    // limit of M", or the operating system's error.
    std::string error;
};

FileBytes readFileBytes(const std::filesystem::path& path, std::uint64_t maxBytes);

}  // namespace candela::content
