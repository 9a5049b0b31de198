#pragma once
// Where the mix goes: the system's sound output (OpenAL Soft's playback device, mixed on its
// own thread), or a loopback device (ALC_SOFT_loopback) that mixes only when asked, into
// memory, 48 kHz stereo float. Headless runs use loopback so the same frames give the same
// samples byte for byte; a window without a sound device falls back to it and stays silent.
//
//   std::string problem;
//   auto device = AudioDevice::openLoopback(problem);
//   std::vector<float> stereo(2 * 1600);
//   device->render(stereo);  // the next 1/30 s of the mix
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace candela::audio {

inline constexpr std::uint32_t kLoopbackSampleRate = 48000;

class AudioDevice {
public:
    // Null with `problem` set when OpenAL cannot make the device.
    static std::unique_ptr<AudioDevice> openLoopback(std::string& problem);
    // The default output (PulseAudio, ALSA, ...). Null with `problem` set when there is none.
    static std::unique_ptr<AudioDevice> openPlayback(std::string& problem);
    ~AudioDevice();
    AudioDevice(const AudioDevice&) = delete;
    AudioDevice& operator=(const AudioDevice&) = delete;

    bool isLoopback() const;
    std::uint32_t sampleRate() const;
    // Loopback only: mixes the next stereo.size() / 2 frames (interleaved left, right). Source
    // parameters change only between calls; the same call sizes give the same samples.
    void render(std::span<float> stereo);
    // Makes this device's context current (OpenAL calls go to it); AudioSystem does it.
    void makeCurrent();

private:
    AudioDevice();
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace candela::audio
