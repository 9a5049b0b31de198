// The view rays of the volumetric lighting shaders, without TAA's jitter.
#ifndef CANDELA_VOLUMETRIC_VIEW_RAY_GLSL
#define CANDELA_VOLUMETRIC_VIEW_RAY_GLSL

#include "common/camera.glsl"

// The world point on the near plane at `ndc` of the unjittered frame. The medium is smooth and
// lit at coarser than a pixel, so TAA's sub-pixel jitter has nothing to antialias in it; marched
// along jittered rays it only moved from frame to frame (steeply near a light, where the fog's
// brightness changes fastest), and the history clamp let that through as flicker. Unjittered,
// a static camera adds the same medium every frame. viewProjection = jitter * unjittered, so
// the jittered inverse at ndc + 2 jitter / size is the unjittered one at ndc (the same bits
// without TAA, whose jitter is 0).
vec3 unjitteredNearPoint(vec2 ndc) {
    vec2 shift = 2.0 * camera.jitter.xy / vec2(camera.frameInfo.xy);
    vec4 p = camera.inverseViewProjection * vec4(ndc + shift, 1.0, 1.0);
    return p.xyz / p.w;
}

#endif
