#include "candela/audio/audio_capture.h"

#include "candela/audio/wav_encoding.h"
#include "candela/content/atomic_file_write.h"

namespace candela::audio {

std::string AudioCapture::write(const std::filesystem::path& path) const {
    return content::writeFileAtomically(path, encodeWav16(samples_, sampleRate_, 2));
}

}  // namespace candela::audio
