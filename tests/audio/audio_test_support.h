#pragma once
// A loopback mix of an ECS registry for the audio tests: clips synthesised in memory (written
// as WAV files into a temporary directory), sources placed by WorldTransform, and the stereo
// samples the loopback device renders.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "candela/audio/audio_device.h"
#include "candela/audio/audio_system.h"
#include "candela/content/asset_cache.h"
#include "candela/content/components/audio_listener.h"
#include "candela/content/components/audio_source.h"
#include "candela/content/components/camera.h"
#include "candela/ecs/registry.h"
#include "candela/ecs/transform.h"

namespace candela::audio::test {

inline constexpr std::uint32_t kRate = kLoopbackSampleRate;

// A sine of whole periods: `seconds` long, `frequency` Hz, peak `amplitude`.
std::vector<float> sine(double seconds, double frequency, float amplitude, std::uint32_t rate);
// Writes `samples` as a 16-bit WAV under a fresh temporary directory; returns its path.
std::filesystem::path writeClip(const std::string& name, const std::vector<float>& samples,
                                std::uint32_t rate = kRate, std::uint32_t channels = 1);
std::filesystem::path testSound(const std::string& name);  // tests/audio/sounds/<name>

struct Channels {
    std::vector<float> left, right;
};
double rms(const std::vector<float>& samples, std::size_t from = 0);

class LoopbackMix {
public:
    LoopbackMix();
    ecs::Entity addSource(const content::AudioSource& source, ecs::Vec3 position);
    ecs::Entity addListener(ecs::Vec3 position);
    void move(ecs::Entity e, ecs::Vec3 position);
    // Syncs and mixes `frames` frames per step, `steps` times; returns the samples.
    Channels run(std::uint32_t steps, std::uint32_t framesPerStep = 1600);

    ecs::Registry registry;
    content::AssetCache cache;
    content::Diagnostics diagnostics;
    std::unique_ptr<AudioDevice> device;
    std::unique_ptr<AudioSystem> system;
};

}  // namespace candela::audio::test
