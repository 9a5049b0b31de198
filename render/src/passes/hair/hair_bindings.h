// Bindings of the hair shaders (hair_fill.*, hair_resolve.frag, hair_depth.frag), shared with
// hair_pass.cpp (valid in C++ and GLSL). The resolve also binds the lit inputs
// (common/lit_bindings.h).
#ifndef CANDELA_HAIR_BINDINGS_H
#define CANDELA_HAIR_BINDINGS_H

#include "common/lit_bindings.h"

// The frame's strand segments, world space (HairSegment in hair_pass.cpp): two ranges of one
// buffer, each at most maxStorageBufferRange, so hair past one binding's reach is split
// (hair_segment.glsl's hairSegment reads either).
#define HAIR_BINDING_SEGMENTS 2
#define HAIR_BINDING_SEGMENTS_HIGH 18
// The A-buffer: one list head per pixel, the node pool, and the pool's allocation counter.
#define HAIR_BINDING_HEADS 3
#define HAIR_BINDING_NODES 4
#define HAIR_BINDING_COUNTERS 5
// The hair depth map (hair_shadow.vert): the nearest strand from each shadow view, laid out as
// the shadow atlas.
#define HAIR_BINDING_HAIR_SHADOW 16
// The integrated froxel buffer (common/froxel_lookup.glsl): the fog and air in front of the hair.
#define HAIR_BINDING_FROXEL_INTEGRATED 17

// The push block's `mode`: lit (Kajiya-Kay), or every fragment unlit radiance 1 (its coverage
// alone: the GPAA measurement, RendererOptions::hairShading).
#define HAIR_MODE_LIT 0
#define HAIR_MODE_COVERAGE 1

// The push block's `selfShadow` (RendererOptions::hairSelfShadow): none; the hair depth map's
// estimate of the fibres in front (Martin et al. 2014, GPU Pro 5, "TressFX: Advanced Real-Time Hair
// Rendering"); or the reference, every segment between the fragment and the light counted exactly.
#define HAIR_SELF_SHADOW_OFF 0
#define HAIR_SELF_SHADOW_DEPTH_MAP 1
#define HAIR_SELF_SHADOW_REFERENCE 2
// Self-shadowing's fibre model (TressFX): each fibre in front lets 1 - HAIR_SHADOW_OPACITY of
// the light through, and fibres lie HAIR_FIBRE_SPACING strand radii apart along a light ray
// behind the first hair. 128 is fitted to the reference (every fibre counted) on candela-report's
// fur balls: 8 and 32 darkened them 22% to 42% too much on average (docs/speed-vs-error.md).
#define HAIR_SHADOW_OPACITY 0.35
#define HAIR_FIBRE_SPACING 128.0

// The end of a pixel's list (the heads' cleared value).
#define HAIR_LIST_END 0xffffffffu
// Fragments per pixel fully shaded, nearest first; the rest blend cheaply (hair_resolve.frag).
#define HAIR_FULLY_SHADED 4
// Nodes a pixel's walk visits at most (lavapipe's loop limiter allows 65,535 iterations).
#define HAIR_MAX_WALK 4096

#endif
