#pragma once
// What a frame's scene needs from the renderer, asked before its passes are declared: the
// lighting variant, and whether wires, light shafts, SSR or material layers have anything
// to draw (frames without them declare no pass for them).

#include "candela/render/frame_scene.h"
#include "candela/render/renderer_options.h"
#include "passes/lighting/lighting_pass.h"

namespace candela::render {

class SceneResources;

// The integration paths (AREA_PATH_* bits) a light takes in the lighting shaders: a rect or disk
// by LTC or representative point (its quality, else the renderer's default), textured,
// constant intensity; a sphere or tube by LTC. None for the other lights.
uint32_t areaLightPathsOf(const content::Light& light, AreaLightMode renderersDefault);

// The shader variant a scene needs: only the shading models its drawn materials use and the
// light shapes its lights have.
LightingFeatures featuresOf(const FrameScene& scene, const SceneResources& resources,
                            const RendererOptions& options);

// Whether the frame draws wires (WirePass::prepare draws when some wire has a segment).
bool hasWireSegments(const FrameScene& scene);

// Whether the frame draws light shafts: an atmosphere, shafts asked for and a sun (the first
// directional light, ScatteringPass::frameOf).
bool scatteringDrawn(const FrameScene& scene, ScatteringMode mode);

// Whether an opaque draw may have a surface smoother than SSR's roughness cut-off: its
// roughness factor is under it, or a texture (which only scales the factor down) may bring it
// there. Frames without one trace no ray and declare no SSR pass.
bool hasGlossySurface(const FrameScene& scene, const SceneResources& resources, float cutoff);

// Whether an opaque draw's material blends layers over its base (its base layer alone needs
// no blending: content::withBaseLayer folds it into the base fields).
bool usesMaterialLayers(const FrameScene& scene, const SceneResources& resources);

}  // namespace candela::render
