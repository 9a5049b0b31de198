// The names of the renderer's option values (renderer_options.h), as the CLI, --stats and
// the reports spell them.

#include "candela/render/renderer_options.h"

namespace candela::render {

const char* iblModeName(IblMode mode) {
    switch (mode) {
        case IblMode::SplitSum:
            return "split_sum";
        case IblMode::Mobile:
            return "mobile";
        case IblMode::Reference:
            return "reference";
    }
    return "unknown";
}

const char* antiAliasingName(AntiAliasing aa) {
    switch (aa) {
        case AntiAliasing::Off:
            return "off";
        case AntiAliasing::Fxaa:
            return "fxaa";
        case AntiAliasing::Taa:
            return "taa";
        case AntiAliasing::Gbaa:
            return "gbaa";
    }
    return "unknown";
}

const char* volumetricsModeName(VolumetricsMode mode) {
    switch (mode) {
        case VolumetricsMode::Off:
            return "off";
        case VolumetricsMode::Volumes:
            return "volumes";
        case VolumetricsMode::Froxels:
            return "froxels";
        case VolumetricsMode::Reference:
            return "reference";
    }
    return "?";
}

const char* scatteringModeName(ScatteringMode mode) {
    switch (mode) {
        case ScatteringMode::Off:
            return "off";
        case ScatteringMode::Epipolar:
            return "epipolar";
        case ScatteringMode::BruteForce:
            return "brute-force";
    }
    return "?";
}

const char* aoModeName(AoMode mode) {
    switch (mode) {
        case AoMode::Off:
            return "off";
        case AoMode::Gtao:
            return "gtao";
        case AoMode::Reference:
            return "reference";
    }
    return "unknown";
}

const char* areaLightModeName(AreaLightMode mode) {
    return mode == AreaLightMode::Representative ? "representative" : "ltc";
}

const char* ssrModeName(SsrMode mode) {
    switch (mode) {
        case SsrMode::Off:
            return "off";
        case SsrMode::Hiz:
            return "hiz";
        case SsrMode::Reference:
            return "reference";
    }
    return "off";
}

const char* brdfModelName(BrdfModel model) {
    return model == BrdfModel::Ue4 ? "ue4" : "energy-conserving";
}

}  // namespace candela::render
