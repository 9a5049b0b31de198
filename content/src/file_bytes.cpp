#include "candela/content/file_bytes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace candela::content {

namespace {

const char* kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a plain file";
}

std::string systemError(const char* what, int error) {
    return std::string(what) + ": " + std::strerror(error);
}

}  // namespace

FileBytes readFileBytes(const std::filesystem::path& path, std::uint64_t maxBytes) {
    FileBytes result;
    // O_NONBLOCK: opening a FIFO must not wait for a writer; the type check below rejects it.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        result.error = errno == ENOENT ? "no such file" : systemError("cannot open", errno);
        return result;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        result.error = systemError("cannot read its size", errno);
    } else if (!S_ISREG(st.st_mode)) {
        result.error = std::string("not a regular file (") + kindOf(st.st_mode) + ")";
    } else if (static_cast<std::uint64_t>(st.st_size) > maxBytes) {
        result.error = "file is " + std::to_string(st.st_size) + " bytes, over the limit of " +
                       std::to_string(maxBytes);
    }
    if (!result.error.empty()) {
        ::close(fd);
        return result;
    }
    const auto size = static_cast<std::size_t>(st.st_size);
    result.bytes.resize(size);
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::read(fd, result.bytes.data() + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            result.error = systemError("cannot read", errno);
            break;
        }
        if (n == 0) {
            result.error = "short read (the file shrank while being read)";
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    if (!result.error.empty()) result.bytes.clear();
    return result;
}

}  // namespace candela::content
