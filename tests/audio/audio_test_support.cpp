#include "audio_test_support.h"

#include <cmath>
#include <numbers>

#include "candela/audio/wav_encoding.h"
#include "candela/content/atomic_file_write.h"

namespace candela::audio::test {

std::vector<float> sine(double seconds, double frequency, float amplitude, std::uint32_t rate) {
    std::vector<float> out(static_cast<std::size_t>(std::llround(seconds * rate)));
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = amplitude * static_cast<float>(std::sin(2 * std::numbers::pi * frequency *
                                                         static_cast<double>(i) / rate));
    return out;
}

std::filesystem::path writeClip(const std::string& name, const std::vector<float>& samples,
                                std::uint32_t rate, std::uint32_t channels) {
    static const std::filesystem::path directory = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "candela-audio-XXXXXX");
        return std::filesystem::path(mkdtemp(pattern.data()));
    }();
    const std::filesystem::path path = directory / name;
    const std::string error =
        content::writeFileAtomically(path, encodeWav16(samples, rate, channels));
    if (!error.empty()) throw std::runtime_error(error);
    return path;
}

std::filesystem::path testSound(const std::string& name) {
    return std::filesystem::path(CANDELA_TEST_SOUNDS) / name;
}

double rms(const std::vector<float>& samples, std::size_t from) {
    double sum = 0;
    for (std::size_t i = from; i < samples.size(); ++i)
        sum += double(samples[i]) * samples[i];
    return samples.size() > from ? std::sqrt(sum / double(samples.size() - from)) : 0.0;
}

LoopbackMix::LoopbackMix() {
    std::string problem;
    device = AudioDevice::openLoopback(problem);
    if (!device) throw std::runtime_error(problem);
    system = std::make_unique<AudioSystem>(*device);
}

ecs::Entity LoopbackMix::addSource(const content::AudioSource& source, ecs::Vec3 position) {
    const ecs::Entity e = registry.create();
    registry.emplace<content::AudioSource>(e, source);
    registry.emplace<ecs::WorldTransform>(e);
    move(e, position);
    return e;
}

ecs::Entity LoopbackMix::addListener(ecs::Vec3 position) {
    const ecs::Entity e = registry.create();
    registry.emplace<content::AudioListener>(e);
    registry.emplace<ecs::WorldTransform>(e);
    move(e, position);
    return e;
}

void LoopbackMix::move(ecs::Entity e, ecs::Vec3 position) {
    registry.patch<ecs::WorldTransform>(e, [&](ecs::WorldTransform& t) {
        t.matrix(0, 3) = position.x;
        t.matrix(1, 3) = position.y;
        t.matrix(2, 3) = position.z;
    });
}

Channels LoopbackMix::run(std::uint32_t steps, std::uint32_t framesPerStep) {
    Channels out;
    std::vector<float> buffer(2 * framesPerStep);
    for (std::uint32_t i = 0; i < steps; ++i) {
        system->update(registry, cache, double(framesPerStep) / kRate, diagnostics);
        device->render(buffer);
        for (std::uint32_t f = 0; f < framesPerStep; ++f) {
            out.left.push_back(buffer[2 * f]);
            out.right.push_back(buffer[2 * f + 1]);
        }
    }
    return out;
}

}  // namespace candela::audio::test
