#pragma once
// The renderer's settings for a run: each named choice is its command-line flag if given, else
// the scene file's field, else the engine's default (the reasons for each default are in
// frame_settings.cpp).
#include "candela/render/renderer_options.h"
#include "candela/runtime/application_options.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

// `world` may be null (no scene): the flags and the defaults decide.
render::RendererOptions rendererOptionsFor(const ApplicationOptions& options,
                                           const SceneWorld* world);

}  // namespace candela::runtime
