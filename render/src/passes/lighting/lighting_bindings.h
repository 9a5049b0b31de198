// Bindings of lighting.comp, shared by the shader and lighting_pass.cpp (valid in C++ and
// GLSL). Camera, lights and the other lit inputs: common/lit_bindings.h.
#ifndef CANDELA_LIGHTING_BINDINGS_H
#define CANDELA_LIGHTING_BINDINGS_H

#include "common/lit_bindings.h"

// The G-buffer (gbuffer_targets.h order) and its depth.
#define LIGHTING_BINDING_GBUFFER_BASE_COLOR 2
#define LIGHTING_BINDING_GBUFFER_NORMAL 3
#define LIGHTING_BINDING_GBUFFER_SPECULAR_MODEL 4
#define LIGHTING_BINDING_GBUFFER_CUSTOM_DATA 5
#define LIGHTING_BINDING_GBUFFER_DEPTH 6
#define LIGHTING_BINDING_HDR 7
#define LIGHTING_BINDING_PAIR_COUNTS 10
// Image-based lighting (ibl/environment_descriptors.h).
#define LIGHTING_BINDING_ENVIRONMENT 12
#define LIGHTING_BINDING_SAMPLING_TABLE 16
// gbuffer_targets.h's optional targets (the base colour image stands in without them).
#define LIGHTING_BINDING_GBUFFER_ANISOTROPY 17
#define LIGHTING_BINDING_GBUFFER_CLEAR_COAT 18
// Ambient occlusion (passes/ambient_occlusion): (bent normal, visibility), and the reference's
// specular visibility.
#define LIGHTING_BINDING_AMBIENT_OCCLUSION 19
#define LIGHTING_BINDING_SPECULAR_OCCLUSION 20
// Textured rects and sky occlusion: compiled in (lit inputs the hair and wires leave out).
#define AREA_LIGHT_TEXTURE_BINDING LIT_BINDING_AREA_LIGHT_TEXTURES
#define SKY_OCCLUSION_BINDING LIT_BINDING_SKY_OCCLUSION

#endif
