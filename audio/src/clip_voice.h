#pragma once
// One entity's sound: an OpenAL source playing its clip. A short clip plays from one buffer
// shared by every voice of that clip (OpenAL loops it seamlessly); a streamed clip is decoded
// into a small ring of queued buffers that update() refills, looping by rewinding the stream.
#include <AL/al.h>

#include <array>
#include <memory>
#include <vector>

#include "candela/content/audio_clip.h"
#include "candela/content/components/audio_source.h"
#include "candela/ecs/transform_math.h"

namespace candela::audio {

class ClipVoice {
public:
    ClipVoice();
    ~ClipVoice();
    ClipVoice(const ClipVoice&) = delete;
    ClipVoice& operator=(const ClipVoice&) = delete;

    // `sharedBuffer` holds a decoded clip (0 for a streamed one, or none: silence).
    void setClip(std::shared_ptr<const content::AudioClip> clip, ALuint sharedBuffer);
    bool hasClip() const { return clip_ != nullptr; }
    bool streamed() const { return stream_ != nullptr; }

    // Gain, pitch, distance model, looping and, for a spatial source, where it is and how fast
    // it moves (Doppler). A stereo clip is never positioned (OpenAL plays it as is).
    void apply(const content::AudioSource& source, ecs::Vec3 position, ecs::Vec3 velocity);

    void start(bool loop);  // from the beginning
    void pause();
    void resume();
    void stop();
    bool started() const { return started_; }
    bool paused() const { return paused_; }
    // It was started and has played to its end (never true while looping).
    bool finished();
    // A streamed voice queues the buffers that played out again, refilled.
    void refill(bool loop);

private:
    bool fill(ALuint buffer, bool loop);
    void queueFromStart(bool loop);
    ALint state() const;

    ALuint source_ = 0;
    std::shared_ptr<const content::AudioClip> clip_;
    ALuint sharedBuffer_ = 0;
    std::unique_ptr<content::AudioClipStream> stream_;
    std::array<ALuint, 4> streamBuffers_{};
    std::vector<float> scratch_;  // one stream buffer's samples, decoded before upload
    bool streamEnded_ = false;
    bool started_ = false;
    bool paused_ = false;
};

// OpenAL's float formats (AL_EXT_float32) for a clip's channel count.
ALenum floatFormat(std::uint32_t channels);

}  // namespace candela::audio
