// Bindings of the volumetric lighting shaders (passes/volumetrics), shared by the GLSL and
// volumetrics_pass.cpp (valid in C++ and GLSL). Camera and lights: common/shared_bindings.h.
#ifndef CANDELA_VOLUMETRICS_BINDINGS_H
#define CANDELA_VOLUMETRICS_BINDINGS_H

#include "common/shared_bindings.h"

#define VOLUMETRICS_BINDING_DEPTH 2
#define VOLUMETRICS_BINDING_HDR 3
// Per light (same index as the light buffer): its volumetric scale.
#define VOLUMETRICS_BINDING_LIGHT_SCALES 4
// Froxels: per froxel (in-scattered radiance per metre, extinction per metre), then per slice
// boundary (in-scattered radiance from the camera, transmittance).
#define VOLUMETRICS_BINDING_FROXEL_MEDIUM 5
#define VOLUMETRICS_BINDING_FROXEL_INTEGRATED 6
// Per-light volumes: the half-resolution march and its bilateral blur, each (in-scattered
// radiance, view depth) per pixel.
#define VOLUMETRICS_BINDING_VOLUMES_MARCHED 12
#define VOLUMETRICS_BINDING_VOLUMES_BLURRED 13
// Per workgroup of the volumes' march or the froxel lighting: the lights that reach its tile or
// cluster (light_bins.h).
#define VOLUMETRICS_BINDING_LIGHT_BINS 14
// The rasterised per-light volumes: the light index of each proxy instance (light_proxies.h).
#define VOLUMETRICS_BINDING_PROXY_INSTANCES 15
// Shadows (common/shadows.glsl, passes/shadows/shadow_pass.h).
#define VOLUMETRICS_BINDING_SHADOW_ATLAS 7
#define VOLUMETRICS_BINDING_SHADOW_VIEWS 8
#define VOLUMETRICS_BINDING_SHADOW_LIGHTS 9
#define VOLUMETRICS_BINDING_SHADOW_ATLAS_COMPARE 10

#endif
