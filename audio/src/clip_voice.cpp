#include "clip_voice.h"

#include <AL/alext.h>

#include <vector>

#include "candela/content/component_validation.h"

namespace candela::audio {
namespace {

// 8,192 frames a buffer, four queued: 0.68 s ahead at 48 kHz, far more than a frame takes.
constexpr std::size_t kStreamBufferFrames = 8192;

}  // namespace

ALenum floatFormat(std::uint32_t channels) {
    return channels == 2 ? AL_FORMAT_STEREO_FLOAT32 : AL_FORMAT_MONO_FLOAT32;
}

ClipVoice::ClipVoice() {
    alGenSources(1, &source_);
    // OpenAL clamps a source's gain to AL_MAX_GAIN, 1 by default: allow what validation does.
    alSourcef(source_, AL_MAX_GAIN, content::kMaxAudioGain);
}

ClipVoice::~ClipVoice() {
    alSourceStop(source_);
    alSourcei(source_, AL_BUFFER, 0);
    alDeleteSources(1, &source_);
    if (streamBuffers_[0]) alDeleteBuffers(ALsizei(streamBuffers_.size()), streamBuffers_.data());
}

void ClipVoice::setClip(std::shared_ptr<const content::AudioClip> clip, ALuint sharedBuffer) {
    alSourceStop(source_);
    alSourcei(source_, AL_BUFFER, 0);
    started_ = paused_ = false;
    clip_ = std::move(clip);
    sharedBuffer_ = sharedBuffer;
    stream_.reset();
    if (!clip_) return;
    // A stereo clip's channels go straight to the left and right outputs, as recorded (OpenAL
    // would otherwise place them at +-30 degrees and pan each into both outputs).
    alSourcei(source_, AL_DIRECT_CHANNELS_SOFT, clip_->channels == 2 ? AL_TRUE : AL_FALSE);
    if (clip_->streamed()) {
        stream_ = std::make_unique<content::AudioClipStream>(clip_);
        if (!streamBuffers_[0]) alGenBuffers(ALsizei(streamBuffers_.size()), streamBuffers_.data());
    } else {
        alSourcei(source_, AL_BUFFER, static_cast<ALint>(sharedBuffer_));
    }
}

void ClipVoice::apply(const content::AudioSource& s, ecs::Vec3 position, ecs::Vec3 velocity) {
    alSourcef(source_, AL_GAIN, s.gain);
    alSourcef(source_, AL_PITCH, s.pitch);
    // A streamed clip loops by rewinding its stream, never by OpenAL's looping.
    alSourcei(source_, AL_LOOPING, s.loop && !stream_ ? AL_TRUE : AL_FALSE);
    const bool spatial = s.spatial && clip_ && clip_->channels == 1;
    alSourcei(source_, AL_SOURCE_RELATIVE, spatial ? AL_FALSE : AL_TRUE);
    if (spatial) {
        alSource3f(source_, AL_POSITION, position.x, position.y, position.z);
        alSource3f(source_, AL_VELOCITY, velocity.x, velocity.y, velocity.z);
        alSourcef(source_, AL_REFERENCE_DISTANCE, s.minDistance);
        alSourcef(source_, AL_MAX_DISTANCE, s.maxDistance);
        alSourcef(source_, AL_ROLLOFF_FACTOR, s.rolloff);
    } else {
        // At the listener, not moving with it: no attenuation, panning or Doppler.
        alSource3f(source_, AL_POSITION, 0, 0, 0);
        alSource3f(source_, AL_VELOCITY, 0, 0, 0);
        alSourcef(source_, AL_ROLLOFF_FACTOR, 0);
    }
}

bool ClipVoice::fill(ALuint buffer, bool loop) {
    const std::uint32_t channels = clip_->channels;
    std::vector<float>& samples = scratch_;  // kept: a refill every 0.17 s allocates nothing
    samples.resize(kStreamBufferFrames * channels);
    std::size_t frames = 0;
    while (frames < kStreamBufferFrames) {
        const std::size_t got = stream_->read(std::span<float>(samples).subspan(frames * channels));
        frames += got;
        if (frames < kStreamBufferFrames) {
            if (!loop) break;
            if (got == 0 && frames == 0) break;  // an empty stream would spin forever
            stream_->rewind();
        }
    }
    if (frames == 0) return false;
    alBufferData(buffer, floatFormat(channels), samples.data(),
                 static_cast<ALsizei>(frames * channels * sizeof(float)),
                 static_cast<ALsizei>(clip_->sampleRate));
    return true;
}

void ClipVoice::queueFromStart(bool loop) {
    alSourceStop(source_);
    alSourcei(source_, AL_BUFFER, 0);
    stream_->rewind();
    streamEnded_ = false;
    for (ALuint buffer : streamBuffers_) {
        if (!fill(buffer, loop)) {
            streamEnded_ = true;
            break;
        }
        alSourceQueueBuffers(source_, 1, &buffer);
    }
}

void ClipVoice::start(bool loop) {
    if (!clip_) return;
    if (stream_) {
        queueFromStart(loop);
    } else {
        alSourceRewind(source_);
    }
    alSourcePlay(source_);
    started_ = true;
    paused_ = false;
}

void ClipVoice::pause() {
    alSourcePause(source_);
    paused_ = true;
}

void ClipVoice::resume() {
    alSourcePlay(source_);
    paused_ = false;
}

void ClipVoice::stop() {
    alSourceStop(source_);
    started_ = paused_ = false;
}

ALint ClipVoice::state() const {
    ALint value = AL_INITIAL;
    alGetSourcei(source_, AL_SOURCE_STATE, &value);
    return value;
}

bool ClipVoice::finished() {
    if (!started_ || paused_ || state() != AL_STOPPED) return false;
    if (stream_ && !streamEnded_) return false;  // an underrun: refill() restarts it
    started_ = false;
    return true;
}

void ClipVoice::refill(bool loop) {
    if (!stream_ || !started_ || paused_) return;
    ALint processed = 0;
    alGetSourcei(source_, AL_BUFFERS_PROCESSED, &processed);
    for (; processed > 0 && !streamEnded_; --processed) {
        ALuint buffer = 0;
        alSourceUnqueueBuffers(source_, 1, &buffer);
        if (!fill(buffer, loop)) {
            streamEnded_ = true;
            break;
        }
        alSourceQueueBuffers(source_, 1, &buffer);
    }
    // The queue ran dry before it was refilled (a stalled frame): play on from what is queued.
    ALint queued = 0;
    alGetSourcei(source_, AL_BUFFERS_QUEUED, &queued);
    if (!streamEnded_ && state() == AL_STOPPED && queued > 0) alSourcePlay(source_);
}

}  // namespace candela::audio
