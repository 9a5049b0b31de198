// Bindings of the screen-space reflection passes (ssr_hiz.comp, ssr_trace.comp,
// ssr_composite.comp), shared by the shaders and ssr_pass.cpp (valid in C++ and GLSL). Camera:
// common/shared_bindings.h.
#ifndef CANDELA_SSR_BINDINGS_H
#define CANDELA_SSR_BINDINGS_H

#include "common/shared_bindings.h"

// The G-buffer's depth, normal + roughness + metallic, base colour and specular + model.
#define SSR_BINDING_DEPTH 2
#define SSR_BINDING_NORMAL 3
#define SSR_BINDING_BASE_COLOR 4
#define SSR_BINDING_SPECULAR_MODEL 5
// The Hi-Z pyramid (RGBA32F: nearest depth in r, farthest in g; every level in one image:
// ssr_pass.h), read-write while built.
#define SSR_BINDING_HIZ 6
// The lit HDR radiance the rays read (trace), and the one the reflection is added to
// (composite).
#define SSR_BINDING_HDR 7
// The split sum's textures, to weight the reflection and to take out what the environment's
// specular already put there.
#define SSR_BINDING_PREFILTERED 8
#define SSR_BINDING_BRDF_LUT 9
// What the trace adds to each pixel (rgb) and its confidence (a).
#define SSR_BINDING_REFLECTION 10
// Counters for --stats: steps summed, most steps, hits, rays.
#define SSR_BINDING_COUNTERS 11

// The pre-convolved scene (ssr_color.comp): RGBA16F, the Hi-Z pyramid's layout.
#define SSR_BINDING_COLOR 12
// Temporal filtering (ssr_temporal.comp): the G-buffer's motion, last frame's filtered
// reflection, and this frame's (written, what the composite adds).
#define SSR_BINDING_MOTION 13
#define SSR_BINDING_HISTORY 14
#define SSR_BINDING_HISTORY_OUTPUT 15
// The pre-integrated visibility of each Hi-Z cell (ssr_visibility.comp): R32F, the pyramid's
// layout.
#define SSR_BINDING_VISIBILITY 16
// The ambient occlusion the lighting pass applied (its AO image and specular occlusion, or the
// LUT as a placeholder without it), so the trace takes out the sky's specular as occluded.
#define SSR_BINDING_AMBIENT_OCCLUSION 17
#define SSR_BINDING_SPECULAR_OCCLUSION 18

// Highest Hi-Z level + 1 (a 65536-pixel side needs 17).
#define SSR_MAX_LEVELS 16

#endif
