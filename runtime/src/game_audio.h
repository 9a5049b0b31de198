#pragma once
// The application's sound for one run: opens a device when the run first needs one (a world
// with an AudioSource, or --audio-capture), syncs the ECS's sources every frame and, on a
// loopback device, mixes the frame's samples in step with its scene time. Headless runs and
// --audio-capture use loopback; a window plays to the sound device, or warns once and stays
// silent when there is none (still mixing to nowhere, so sounds end when they would).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "candela/audio/audio_capture.h"
#include "candela/audio/audio_device.h"
#include "candela/audio/audio_system.h"
#include "candela/runtime/frame_context.h"
#include "candela/runtime/frame_stats.h"

namespace candela::runtime {

class SceneWorld;

class GameAudio {
public:
    GameAudio(bool headless, std::optional<std::filesystem::path> capturePath);
    // Syncs `world`'s sounds and mixes up to `frame`'s scene time plus `stepSeconds` (the
    // frame being made is heard until the next one).
    void update(SceneWorld& world, const FrameContext& frame, double stepSeconds,
                FrameStats& stats);
    // A new world: its sounds start afresh.
    void clear();
    // Writes --audio-capture; false (with the error on stderr) when it cannot be written.
    bool finish();

private:
    bool open();

    bool headless_;
    std::optional<std::filesystem::path> capturePath_;
    std::unique_ptr<audio::AudioDevice> device_;
    std::unique_ptr<audio::AudioSystem> system_;
    std::unique_ptr<audio::AudioCapture> capture_;
    bool openFailed_ = false;
    std::uint64_t mixedFrames_ = 0;  // sample frames mixed so far (loopback)
    std::vector<float> buffer_;
};

}  // namespace candela::runtime
