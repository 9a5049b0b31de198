#include "game_audio.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "candela/content/components/audio_source.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {
namespace {

double millisecondsBetween(std::chrono::steady_clock::time_point a,
                           std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

GameAudio::GameAudio(bool headless, std::optional<std::filesystem::path> capturePath)
    : headless_(headless), capturePath_(std::move(capturePath)) {
    if (capturePath_) open();
}

bool GameAudio::open() {
    if (device_) return true;
    if (openFailed_) return false;
    std::string problem;
    if (!headless_ && !capturePath_) {
        device_ = audio::AudioDevice::openPlayback(problem);
        if (!device_) {
            std::fprintf(stderr, "candela: warning: %s; the game is silent\n", problem.c_str());
        }
    }
    if (!device_) device_ = audio::AudioDevice::openLoopback(problem);
    if (!device_) {
        std::fprintf(stderr, "candela: warning: %s; the game is silent\n", problem.c_str());
        openFailed_ = true;
        return false;
    }
    system_ = std::make_unique<audio::AudioSystem>(*device_);
    if (capturePath_ && device_->isLoopback())
        capture_ = std::make_unique<audio::AudioCapture>(device_->sampleRate());
    return true;
}

void GameAudio::update(SceneWorld& world, const FrameContext& frame, double stepSeconds,
                       FrameStats& stats) {
    if (!device_ && world.registry.view<content::AudioSource>().empty()) return;
    if (!open()) return;
    const auto start = std::chrono::steady_clock::now();
    content::Diagnostics diagnostics;
    system_->update(world.registry, world.assetCache(), frame.deltaSeconds, diagnostics);
    for (const content::Diagnostic& d : diagnostics.messages)
        std::fprintf(stderr, "%s\n", content::formatDiagnostic(d).c_str());
    const auto synced = std::chrono::steady_clock::now();
    if (device_->isLoopback()) {
        // Up to the next frame's scene time, rounded to whole samples without drifting.
        const double until = frame.seconds + stepSeconds;
        const auto target = static_cast<std::uint64_t>(std::llround(until * device_->sampleRate()));
        if (target > mixedFrames_) {
            buffer_.resize(2 * (target - mixedFrames_));
            device_->render(buffer_);
            if (capture_) capture_->append(buffer_);
            mixedFrames_ = target;
        }
    }
    const audio::AudioCounts counts = system_->counts();
    stats.audio.push_back({millisecondsBetween(start, synced),
                           millisecondsBetween(synced, std::chrono::steady_clock::now()),
                           counts.voices, counts.playing});
}

void GameAudio::clear() {
    if (system_) system_->clear();
}

bool GameAudio::finish() {
    if (!capturePath_) return true;
    if (!capture_) {
        std::fprintf(stderr, "candela: %s: no audio was mixed (no sound device could open)\n",
                     capturePath_->c_str());
        return false;
    }
    if (std::string error = capture_->write(*capturePath_); !error.empty()) {
        std::fprintf(stderr, "candela: %s\n", error.c_str());
        return false;
    }
    std::printf("captured %s\n", capturePath_->c_str());
    return true;
}

}  // namespace candela::runtime
