#include "candela/audio/audio_device.h"

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

namespace candela::audio {

struct AudioDevice::Impl {
    ALCdevice* device = nullptr;
    ALCcontext* context = nullptr;
    bool loopback = false;
    std::uint32_t sampleRate = 0;
    LPALCRENDERSAMPLESSOFT renderSamples = nullptr;

    ~Impl() {
        if (context) {
            if (alcGetCurrentContext() == context) alcMakeContextCurrent(nullptr);
            alcDestroyContext(context);
        }
        if (device) alcCloseDevice(device);
    }
};

AudioDevice::AudioDevice() : impl_(std::make_unique<Impl>()) {}
AudioDevice::~AudioDevice() = default;

std::unique_ptr<AudioDevice> AudioDevice::openLoopback(std::string& problem) {
    if (!alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback")) {
        problem = "OpenAL has no ALC_SOFT_loopback extension (OpenAL Soft 1.14 or later)";
        return nullptr;
    }
    auto openDevice = reinterpret_cast<LPALCLOOPBACKOPENDEVICESOFT>(
        alcGetProcAddress(nullptr, "alcLoopbackOpenDeviceSOFT"));
    std::unique_ptr<AudioDevice> out(new AudioDevice());
    Impl& d = *out->impl_;
    d.renderSamples = reinterpret_cast<LPALCRENDERSAMPLESSOFT>(
        alcGetProcAddress(nullptr, "alcRenderSamplesSOFT"));
    d.device = openDevice ? openDevice(nullptr) : nullptr;
    if (!d.device || !d.renderSamples) {
        problem = "OpenAL could not open a loopback device";
        return nullptr;
    }
    // Float output: no dither and no limiter (both would change samples with the call size or
    // the user's alsoft.conf); no HRTF: plain stereo panning.
    const ALCint attributes[] = {ALC_FORMAT_CHANNELS_SOFT,
                                 ALC_STEREO_SOFT,
                                 ALC_FORMAT_TYPE_SOFT,
                                 ALC_FLOAT_SOFT,
                                 ALC_FREQUENCY,
                                 static_cast<ALCint>(kLoopbackSampleRate),
                                 ALC_HRTF_SOFT,
                                 ALC_FALSE,
                                 ALC_OUTPUT_LIMITER_SOFT,
                                 ALC_FALSE,
                                 0};
    d.context = alcCreateContext(d.device, attributes);
    if (!d.context) {
        problem = "OpenAL could not make a 48 kHz stereo float loopback context";
        return nullptr;
    }
    d.loopback = true;
    d.sampleRate = kLoopbackSampleRate;
    out->makeCurrent();
    return out;
}

std::unique_ptr<AudioDevice> AudioDevice::openPlayback(std::string& problem) {
    std::unique_ptr<AudioDevice> out(new AudioDevice());
    Impl& d = *out->impl_;
    d.device = alcOpenDevice(nullptr);
    if (!d.device) {
        problem =
            "no sound output device (OpenAL found no PulseAudio, ALSA or other backend "
            "that opens)";
        return nullptr;
    }
    d.context = alcCreateContext(d.device, nullptr);
    if (!d.context) {
        problem = "OpenAL could not make a context on the sound output device";
        return nullptr;
    }
    ALCint frequency = 0;
    alcGetIntegerv(d.device, ALC_FREQUENCY, 1, &frequency);
    d.sampleRate = static_cast<std::uint32_t>(frequency);
    out->makeCurrent();
    return out;
}

bool AudioDevice::isLoopback() const {
    return impl_->loopback;
}

std::uint32_t AudioDevice::sampleRate() const {
    return impl_->sampleRate;
}

void AudioDevice::render(std::span<float> stereo) {
    if (!impl_->loopback || stereo.size() < 2) return;
    impl_->renderSamples(impl_->device, stereo.data(), static_cast<ALCsizei>(stereo.size() / 2));
}

void AudioDevice::makeCurrent() {
    if (alcGetCurrentContext() != impl_->context) alcMakeContextCurrent(impl_->context);
}

}  // namespace candela::audio
