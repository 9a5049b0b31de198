#pragma once
// WAV and Ogg Vorbis decoding behind decodeAudioClip (audio_clip.h). Each returns an empty
// string on success, else the problem without the path (the caller names the file).
#include <cstddef>
#include <span>
#include <string>

#include "candela/content/audio_clip.h"

namespace candela::content {

std::string decodeWav(std::span<const std::byte> bytes, AudioClip& clip);
std::string decodeVorbis(std::span<const std::byte> bytes, AudioClip& clip);

}  // namespace candela::content
