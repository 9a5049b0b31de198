#include "candela/content/atomic_file_write.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <system_error>

namespace candela::content {
namespace {

namespace fs = std::filesystem;

// Linux gives up on symlink chains at 40 hops (ELOOP); so do we.
constexpr int kMaxSymlinkHops = 40;

std::string osError(const fs::path& path, const char* what, int error) {
    return path.string() + ": " + what + ": " + std::strerror(error);
}

// Follows symbolic links to the file that is really written, so that a link stays a link and
// its target is what changes. A dangling link resolves to the path it names. Links into /proc
// (/dev/stdout -> /proc/self/fd/1 -> "pipe:[...]" or the file the shell redirected to) name an
// open file, not a place to put a new one: `openDescriptor` is set and `path` stays the link.
std::string resolveSymlinks(fs::path& path, bool& openDescriptor) {
    for (int hop = 0; hop < kMaxSymlinkHops; ++hop) {
        struct stat st {};
        if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return {};
        std::error_code ec;
        const fs::path target = fs::read_symlink(path, ec);
        if (ec) return path.string() + ": cannot read the symbolic link: " + ec.message();
        if (path.string().starts_with("/proc/") || target.string().starts_with("/proc/")) {
            openDescriptor = true;
            return {};
        }
        path = target.is_absolute() ? target : path.parent_path() / target;
    }
    return osError(path, "cannot follow the symbolic link", ELOOP);
}

bool writeAll(int fd, std::string_view contents) {
    while (!contents.empty()) {
        const ssize_t written = ::write(fd, contents.data(), contents.size());
        if (written < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        if (written == 0) {
            errno = EIO;
            return false;
        }
        contents.remove_prefix(static_cast<std::size_t>(written));
    }
    return true;
}

// Devices, pipes and open descriptors cannot be renamed over: write them in place, checking
// every step. O_APPEND, so /dev/stdout redirected to a file adds to what is already there.
std::string writeInPlace(const fs::path& path, std::string_view contents) {
    // O_NONBLOCK: a FIFO without a reader fails (ENXIO) instead of hanging the engine.
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return osError(path, "cannot open for writing", errno);
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    if (!writeAll(fd, contents)) {
        const int error = errno;
        ::close(fd);
        return osError(path, "cannot write", error);
    }
    if (::close(fd) != 0) return osError(path, "cannot write", errno);
    return {};
}

// A short name, so that a target whose own name is near NAME_MAX (255) still gets one.
int createTemporary(const fs::path& directory, mode_t mode, fs::path& temporary) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
        const unsigned long long salt = static_cast<unsigned long long>(now) ^
                                        (static_cast<unsigned long long>(::getpid()) << 20) ^
                                        counter.fetch_add(1);
        char name[32];
        std::snprintf(name, sizeof name, ".candela-%08llx.tmp", salt & 0xffffffffull);
        temporary = directory / name;
        const int fd =
            ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, mode);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}

}  // namespace

std::string writeFileAtomically(const fs::path& requested, std::string_view contents,
                                AtomicWriteOptions options) {
    if (requested.empty()) return "cannot write a file with an empty name";
    fs::path path = requested;
    bool openDescriptor = false;
    if (std::string error = resolveSymlinks(path, openDescriptor); !error.empty()) return error;
    if (openDescriptor) return writeInPlace(requested, contents);

    struct stat existing {};
    const bool exists = ::stat(path.c_str(), &existing) == 0;
    if (!exists && errno != ENOENT) return osError(requested, "cannot write", errno);
    if (exists && S_ISDIR(existing.st_mode)) return osError(requested, "cannot write", EISDIR);
    if (exists && !S_ISREG(existing.st_mode)) return writeInPlace(requested, contents);
    if (exists && !options.replaceReadOnly) {
        // Mode bits rather than access(): root may write anything, but a 0444 file still
        // says "do not change me".
        if ((existing.st_mode & 0222) == 0) {
            char mode[8];
            std::snprintf(mode, sizeof mode, "%04o", unsigned(existing.st_mode & 07777));
            return requested.string() + ": the file is read-only (mode " + mode +
                   "); not replacing it";
        }
        if (::access(path.c_str(), W_OK) != 0) return osError(requested, "cannot write", errno);
    }

    const fs::path directory = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    fs::path temporary;
    // An existing file's contents are not exposed through a wider mode while being written.
    const int fd = createTemporary(directory, exists ? 0600 : 0666, temporary);
    if (fd < 0) return osError(requested, "cannot create a temporary file beside it", errno);
    auto abandon = [&](const char* what, int error) {
        ::close(fd);
        ::unlink(temporary.c_str());
        return osError(requested, what, error);
    };
    if (!writeAll(fd, contents)) return abandon("cannot write", errno);
    if (exists) {
        struct stat written {};
        if (::fstat(fd, &written) != 0) return abandon("cannot write", errno);
        if ((written.st_uid != existing.st_uid || written.st_gid != existing.st_gid) &&
            ::fchown(fd, existing.st_uid, existing.st_gid) != 0) {
            return abandon("cannot keep the file's owner", errno);
        }
        if (::fchmod(fd, existing.st_mode & 07777) != 0) {
            return abandon("cannot keep the file's mode", errno);
        }
    }
    // The data and the metadata reach the disk before the rename makes them the file.
    if (::fsync(fd) != 0) return abandon("cannot write", errno);
    if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        return osError(requested, "cannot write", error);
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const int error = errno;
        ::unlink(temporary.c_str());
        return osError(requested, "cannot replace", error);
    }
    // Make the rename itself durable.
    if (const int dir = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return {};
}

}  // namespace candela::content
