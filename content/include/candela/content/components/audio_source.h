#pragma once
// AudioSource component: a sound an entity plays (audio/README.md). A spatial source sits at
// the entity's world position: its gain falls with distance from the listener, it is panned
// by direction, and its speed relative to the listener shifts its pitch (Doppler).
//
//   "audioSource": {"clip": "sounds/tone.wav", "loop": true, "gain": 1.0, "spatial": true}
//
// Game code controls playback through the component (registry.patch): play(), pause(), stop().
#include <cstdint>
#include <string>

namespace candela::content {

enum class PlaybackState : std::uint8_t { Playing, Paused, Stopped };

struct AudioSource {
    // WAV or Ogg Vorbis. In a scene file relative to the scene file; in the ECS as resolved.
    std::string clip;
    float gain = 1.0f;   // linear, >= 0 (1: the clip as recorded, at minDistance)
    float pitch = 1.0f;  // playback speed, > 0 (2: an octave up, and twice as fast)
    bool loop = false;
    // False: no attenuation, panning or Doppler (music, interface sounds).
    bool spatial = true;
    // Inverse-distance attenuation, clamped (OpenAL's AL_INVERSE_DISTANCE_CLAMPED):
    // gain * minDistance / (minDistance + rolloff * (d - minDistance)), d clamped to
    // [minDistance, maxDistance]; beyond maxDistance the gain stops falling.
    float minDistance = 1.0f;    // metres, > 0: full gain up to here
    float maxDistance = 100.0f;  // metres, >= minDistance
    float rolloff = 1.0f;        // >= 0; 0 turns attenuation off
    // What the game wants; a clip that ends without looping is set to Stopped by the audio
    // system. Scene files write "playing": false for a source that waits for play().
    PlaybackState state = PlaybackState::Playing;
    // Bumped by play() to start the clip again from its beginning, even while it plays
    // (a one-shot sound fired twice).
    std::uint32_t starts = 0;

    void play() {
        state = PlaybackState::Playing;
        ++starts;
    }
    void pause() { state = PlaybackState::Paused; }
    // Resumes a paused source where it stopped (play() starts it again from the beginning).
    void resume() { state = PlaybackState::Playing; }
    void stop() { state = PlaybackState::Stopped; }

    bool operator==(const AudioSource&) const = default;
};

}  // namespace candela::content
