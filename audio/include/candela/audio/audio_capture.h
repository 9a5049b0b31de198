#pragma once
// What --audio-capture records: every sample a loopback device mixed during the run, written
// once at the end as a 16-bit stereo WAV (atomically; a failed write names the path and the
// operating system's error).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace candela::audio {

class AudioCapture {
public:
    explicit AudioCapture(std::uint32_t sampleRate) : sampleRate_(sampleRate) {}
    void append(std::span<const float> stereo) {
        samples_.insert(samples_.end(), stereo.begin(), stereo.end());
    }
    const std::vector<float>& samples() const { return samples_; }
    // Empty on success, else "<path>: cannot write: <error>".
    std::string write(const std::filesystem::path& path) const;

private:
    std::uint32_t sampleRate_;
    std::vector<float> samples_;  // interleaved left, right
};

}  // namespace candela::audio
