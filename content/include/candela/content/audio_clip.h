#pragma once
// AudioClip: a sound from a WAV or Ogg Vorbis file, as float samples the mixer plays
// (audio/README.md). Short clips are decoded whole. An Ogg Vorbis clip longer than
// kStreamAboveSeconds keeps its encoded bytes instead and is decoded while it plays
// (AudioClipStream), so a music track costs its file size in memory, not ten times that.
//
//   Diagnostics diagnostics;
//   std::shared_ptr<const AudioClip> clip = loadAudioClip("sounds/tone.wav", diagnostics);
//   if (!clip) ...;  // diagnostics names the file and the problem; play silence
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include "candela/content/diagnostics.h"

namespace candela::content {

inline constexpr double kStreamAboveSeconds = 10.0;
// Larger files are refused (a clip is read whole before it is decoded or streamed).
inline constexpr std::uint64_t kMaxAudioFileBytes = 256ull * 1024 * 1024;

struct AudioClip {
    std::uint32_t sampleRate = 0;    // frames per second, 8,000..192,000
    std::uint32_t channels = 0;      // 1 (mono: may be positioned) or 2 (stereo: played as is)
    std::uint64_t frames = 0;        // samples per channel
    std::vector<float> samples;      // interleaved, -1..1; empty when streamed
    std::vector<std::byte> encoded;  // the Ogg Vorbis file, when streamed

    bool streamed() const { return samples.empty() && !encoded.empty(); }
    double seconds() const { return sampleRate ? static_cast<double>(frames) / sampleRate : 0.0; }
};

// Decodes a WAV (PCM 8/16/24/32-bit or IEEE float, mono or stereo) or Ogg Vorbis file, told
// apart by its first bytes, not its name. Null on failure, with an error naming `path`.
std::shared_ptr<const AudioClip> decodeAudioClip(std::span<const std::byte> bytes,
                                                 const std::filesystem::path& path,
                                                 Diagnostics& diagnostics);
std::shared_ptr<const AudioClip> loadAudioClip(const std::filesystem::path& path,
                                               Diagnostics& diagnostics);

// Reads a clip from its start, frame by frame, whether it is held decoded or streamed: one per
// playing voice.
class AudioClipStream {
public:
    explicit AudioClipStream(std::shared_ptr<const AudioClip> clip);
    ~AudioClipStream();
    AudioClipStream(const AudioClipStream&) = delete;
    AudioClipStream& operator=(const AudioClipStream&) = delete;

    // Fills `out` (interleaved, whole frames) from where the last read stopped; returns the
    // frames written, fewer than asked only at the clip's end.
    std::size_t read(std::span<float> out);
    void rewind();
    const AudioClip& clip() const { return *clip_; }

private:
    std::shared_ptr<const AudioClip> clip_;
    std::uint64_t position_ = 0;  // frames read, decoded clips
    struct Decoder;
    std::unique_ptr<Decoder> decoder_;  // streamed clips
};

}  // namespace candela::content
