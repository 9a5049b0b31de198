#pragma once
// One Ogg Vorbis stream decoded from memory by libvorbisfile (Debian's libvorbis-dev, the
// reference decoder, which is fuzzed upstream: a damaged file is an error, never a crash).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace candela::content {

class VorbisStream {
public:
    // `bytes` must outlive the stream. ok() is false when they are not a Vorbis stream.
    explicit VorbisStream(std::span<const std::byte> bytes);
    ~VorbisStream();
    VorbisStream(const VorbisStream&) = delete;
    VorbisStream& operator=(const VorbisStream&) = delete;

    bool ok() const;
    std::string error() const { return error_; }
    std::uint32_t channels() const;
    std::uint32_t sampleRate() const;
    std::uint64_t frames() const;  // 0 when the length is unknown (no last page: truncated)
    // Fills `out` with interleaved frames from where the last read stopped; returns the frames
    // written, fewer only at the end or at damage it cannot decode past.
    std::size_t read(float* out, std::size_t frames);
    void rewind();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string error_;
};

}  // namespace candela::content
