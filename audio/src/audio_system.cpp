#include "candela/audio/audio_system.h"

#include <AL/al.h>

#include <cmath>
#include <map>
#include <unordered_map>

#include "candela/audio/audio_device.h"
#include "candela/content/components/audio_listener.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/camera.h"
#include "candela/ecs/transform.h"
#include "clip_voice.h"

namespace candela::audio {
namespace {

using content::AudioSource;
using content::PlaybackState;

ecs::Vec3 column(const ecs::Mat4& m, int c) {
    return {m(0, c), m(1, c), m(2, c)};
}

ecs::Vec3 normalizedOr(ecs::Vec3 v, ecs::Vec3 fallback) {
    const float length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(length > 1e-12f) || !std::isfinite(length)) return fallback;
    return {v.x / length, v.y / length, v.z / length};
}

bool finite(ecs::Vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// How far `position` moved since `last`, per second; zero on the first update or a zero step.
ecs::Vec3 velocityOf(ecs::Vec3 position, const ecs::Vec3* last, double deltaSeconds) {
    if (!last || !(deltaSeconds > 0)) return {};
    const float inv = static_cast<float>(1.0 / deltaSeconds);
    const ecs::Vec3 v{(position.x - last->x) * inv, (position.y - last->y) * inv,
                      (position.z - last->z) * inv};
    return finite(v) ? v : ecs::Vec3{};
}

struct Voice {
    ClipVoice voice;
    std::string clipPath;
    std::uint32_t starts = 0;
    ecs::Vec3 lastPosition{};
    bool hasLastPosition = false;
    std::uint64_t seen = 0;
};

}  // namespace

struct AudioSystem::Impl {
    AudioDevice& device;
    std::unordered_map<std::uint64_t, std::unique_ptr<Voice>> voices;
    // One OpenAL buffer per decoded clip, shared by its voices; the clip is kept alive with it.
    std::map<const content::AudioClip*,
             std::pair<std::shared_ptr<const content::AudioClip>, ALuint>>
        buffers;
    ecs::Vec3 lastListener{};
    bool hasLastListener = false;
    std::uint64_t generation = 0;

    explicit Impl(AudioDevice& d) : device(d) {}
    ~Impl() { clear(); }

    void clear() {
        device.makeCurrent();
        voices.clear();  // sources first: a buffer attached to one cannot be deleted
        for (auto& [clip, entry] : buffers)
            alDeleteBuffers(1, &entry.second);
        buffers.clear();
        hasLastListener = false;
    }

    ALuint bufferFor(const std::shared_ptr<const content::AudioClip>& clip) {
        if (!clip || clip->streamed()) return 0;
        auto [it, added] = buffers.try_emplace(clip.get(), clip, 0);
        if (added) {
            alGenBuffers(1, &it->second.second);
            alBufferData(it->second.second, floatFormat(clip->channels), clip->samples.data(),
                         static_cast<ALsizei>(clip->samples.size() * sizeof(float)),
                         static_cast<ALsizei>(clip->sampleRate));
        }
        return it->second.second;
    }

    void updateListener(ecs::Registry& registry, double deltaSeconds) {
        const ecs::WorldTransform* ears = nullptr;
        float gain = 1.0f;
        registry.view<const ecs::WorldTransform, const content::AudioListener>().each(
            [&](const ecs::WorldTransform& t, const content::AudioListener& listener) {
                if (ears) return;
                ears = &t;
                gain = listener.gain;
            });
        if (!ears) {
            registry.view<const ecs::WorldTransform, const content::Camera>().each(
                [&](const ecs::WorldTransform& t, const content::Camera&) {
                    if (!ears) ears = &t;
                });
        }
        ecs::Vec3 position{}, forward{0, 0, -1}, up{0, 1, 0};
        if (ears && finite(ears->position())) {
            position = ears->position();
            const ecs::Vec3 back = column(ears->matrix, 2);
            forward = normalizedOr({-back.x, -back.y, -back.z}, forward);
            up = normalizedOr(column(ears->matrix, 1), up);
        }
        const ecs::Vec3 velocity =
            velocityOf(position, hasLastListener ? &lastListener : nullptr, deltaSeconds);
        lastListener = position;
        hasLastListener = true;
        const float orientation[6] = {forward.x, forward.y, forward.z, up.x, up.y, up.z};
        alListener3f(AL_POSITION, position.x, position.y, position.z);
        alListener3f(AL_VELOCITY, velocity.x, velocity.y, velocity.z);
        alListenerfv(AL_ORIENTATION, orientation);
        alListenerf(AL_GAIN, gain);
    }

    void updateVoice(ecs::Registry& registry, ecs::Entity e, const AudioSource& source, Voice& v,
                     content::AssetCache& cache, double deltaSeconds,
                     content::Diagnostics& diagnostics) {
        if (v.clipPath != source.clip) {
            v.clipPath = source.clip;
            const auto clip = cache.audioClip(source.clip, diagnostics);
            v.voice.setClip(clip, bufferFor(clip));
            v.starts = source.starts;
        }
        if (!v.voice.hasClip()) return;  // silence; the error was reported with the file
        ecs::Vec3 position{};
        if (const auto* t = registry.tryGet<ecs::WorldTransform>(e); t && finite(t->position()))
            position = t->position();
        const ecs::Vec3 velocity =
            velocityOf(position, v.hasLastPosition ? &v.lastPosition : nullptr, deltaSeconds);
        v.lastPosition = position;
        v.hasLastPosition = true;
        v.voice.apply(source, position, velocity);

        if (source.starts != v.starts) {
            v.starts = source.starts;
            if (source.state == PlaybackState::Playing) v.voice.start(source.loop);
        }
        switch (source.state) {
            case PlaybackState::Playing:
                if (!v.voice.started()) {
                    v.voice.start(source.loop);
                } else if (v.voice.paused()) {
                    v.voice.resume();
                } else if (v.voice.finished()) {
                    registry.patch<AudioSource>(
                        e, [](AudioSource& a) { a.state = PlaybackState::Stopped; });
                }
                break;
            case PlaybackState::Paused:
                if (v.voice.started() && !v.voice.paused()) v.voice.pause();
                break;
            case PlaybackState::Stopped:
                if (v.voice.started()) v.voice.stop();
                break;
        }
        v.voice.refill(source.loop);
    }
};

AudioSystem::AudioSystem(AudioDevice& device) : impl_(std::make_unique<Impl>(device)) {}
AudioSystem::~AudioSystem() = default;

void AudioSystem::update(ecs::Registry& registry, content::AssetCache& cache, double deltaSeconds,
                         content::Diagnostics& diagnostics) {
    Impl& s = *impl_;
    s.device.makeCurrent();
    const std::uint64_t generation = ++s.generation;
    s.updateListener(registry, deltaSeconds);
    // Entities in creation order (the pool's order), so the same scene starts its sources in
    // the same order every run.
    // The entities first: updating a voice may patch its component (a clip that ended), which
    // a view being iterated refuses.
    std::vector<ecs::Entity> sources;
    registry.view<const AudioSource>().each(
        [&](ecs::Entity e, const AudioSource&) { sources.push_back(e); });
    for (ecs::Entity e : sources) {
        auto& slot = s.voices[e.bits()];
        if (!slot) slot = std::make_unique<Voice>();
        slot->seen = generation;
        s.updateVoice(registry, e, registry.get<AudioSource>(e), *slot, cache, deltaSeconds,
                      diagnostics);
    }
    std::erase_if(s.voices, [&](const auto& entry) { return entry.second->seen != generation; });
}

void AudioSystem::clear() {
    impl_->clear();
}

AudioCounts AudioSystem::counts() const {
    AudioCounts counts;
    for (const auto& [bits, v] : impl_->voices) {
        if (!v->voice.hasClip()) continue;
        ++counts.voices;
        if (v->voice.started() && !v->voice.paused()) ++counts.playing;
        if (v->voice.streamed()) ++counts.streamed;
    }
    return counts;
}

}  // namespace candela::audio
