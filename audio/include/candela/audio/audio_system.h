#pragma once
// Plays the ECS's sounds: each AudioSource becomes an OpenAL source at its entity's world
// position, heard by the AudioListener (or, without one, the first camera). Run update()
// once a frame after transforms propagate; AudioDevice::render() then mixes the frame's
// samples on a loopback device (a playback device mixes on its own).
//
//   AudioSystem audio(device);
//   audio.update(registry, cache, frame.deltaSeconds, diagnostics);
//
// Game code plays, pauses and stops sounds through the component (audio_source.h); a clip
// that ends without looping is set to PlaybackState::Stopped here. Velocities for Doppler
// come from how far an entity moved since the last update.
#include <cstdint>
#include <memory>

#include "candela/content/asset_cache.h"
#include "candela/content/diagnostics.h"
#include "candela/ecs/registry.h"

namespace candela::audio {

class AudioDevice;

struct AudioCounts {
    std::uint32_t voices = 0;    // AudioSource entities with a playable clip
    std::uint32_t playing = 0;   // of them, started and not paused
    std::uint32_t streamed = 0;  // of them, streaming their clip
};

class AudioSystem {
public:
    explicit AudioSystem(AudioDevice& device);
    ~AudioSystem();
    AudioSystem(const AudioSystem&) = delete;
    AudioSystem& operator=(const AudioSystem&) = delete;

    void update(ecs::Registry& registry, content::AssetCache& cache, double deltaSeconds,
                content::Diagnostics& diagnostics);
    // Every voice goes (another world replaces the registry).
    void clear();
    AudioCounts counts() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace candela::audio
