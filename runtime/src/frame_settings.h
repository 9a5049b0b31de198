#pragma once
// The renderer's settings for a run: each named choice is its command-line flag if given, else
// the scene file's field, else the engine's default (the reasons for each default are in
// frame_settings.cpp).
#include "candela/render/renderer_options.h"
#include "candela/runtime/application_options.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

// The quality preset a run uses and where it came from: --quality, else the scene file's
// "quality", else the device's level (content::qualityForDevice).
struct QualityChoice {
    content::QualityLevel level = content::QualityLevel::Ultra;
    content::QualitySource source = content::QualitySource::Device;
};
QualityChoice qualityFor(const ApplicationOptions& options, const SceneWorld* world,
                         bool cpuDevice);

// `world` may be null (no scene): the flags, the preset and the defaults decide. A setting
// neither the flags nor the scene file choose takes `quality`'s preset value (ultra: the
// engine's settings before presets).
render::RendererOptions rendererOptionsFor(const ApplicationOptions& options,
                                           const SceneWorld* world, QualityChoice quality = {});

}  // namespace candela::runtime
