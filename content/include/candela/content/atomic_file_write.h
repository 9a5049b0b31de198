#pragma once
// The one way the engine writes a file. A regular file is replaced atomically: a temporary
// file with a short name is written in the target's own directory, flushed to disk (fsync),
// given the old file's mode and owner, and renamed over the target, then the directory is
// synced. Readers see the old or the new file, never a mix, and a full disk leaves the old
// file untouched. A symbolic link is followed, so its target is updated and the link stays a
// link. A file without any write permission bit is not replaced unless asked. A target that
// is not a regular file (/dev/full, a FIFO with a reader) or that names an open descriptor
// (/dev/stdout, /proc/self/fd/N) is written in place (appending), every write checked. When
// the old file's owner cannot be kept (another user's group-writable file, without root), the
// write fails rather than silently changing who owns the file.
//
//   if (std::string error = writeFileAtomically("stats.json", text); !error.empty())
//       fail(error);  // e.g. "stats.json: cannot write: No space left on device"
#include <filesystem>
#include <string>
#include <string_view>

namespace candela::content {

struct AtomicWriteOptions {
    // A read-only file (no write bit for anyone) is the user saying "keep this".
    bool replaceReadOnly = false;
};

// Returns an empty string on success, else a message that starts with the path and ends with
// the operating system's error, e.g. "a.exr: cannot write: No space left on device". On
// failure the target is unchanged and no temporary file is left behind.
std::string writeFileAtomically(const std::filesystem::path& path, std::string_view contents,
                                AtomicWriteOptions options = {});

}  // namespace candela::content
