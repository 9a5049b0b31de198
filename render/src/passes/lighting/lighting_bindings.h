// Bindings of lighting.comp, shared by the shader and lighting_pass.cpp (valid in C++ and
// GLSL). Camera and lights: common/shared_bindings.h.
#ifndef CANDELA_LIGHTING_BINDINGS_H
#define CANDELA_LIGHTING_BINDINGS_H

#include "common/shared_bindings.h"

// The G-buffer (gbuffer_targets.h order) and its depth.
#define LIGHTING_BINDING_GBUFFER_BASE_COLOR 2
#define LIGHTING_BINDING_GBUFFER_NORMAL 3
#define LIGHTING_BINDING_GBUFFER_SPECULAR_MODEL 4
#define LIGHTING_BINDING_GBUFFER_CUSTOM_DATA 5
#define LIGHTING_BINDING_GBUFFER_DEPTH 6
#define LIGHTING_BINDING_HDR 7
#define LIGHTING_BINDING_CLUSTER_RANGES 8
#define LIGHTING_BINDING_LIGHT_INDICES 9
#define LIGHTING_BINDING_PAIR_COUNTS 10
#define LIGHTING_BINDING_DEPTH_RANGE 11
// Image-based lighting (ibl/environment_descriptors.h).
#define LIGHTING_BINDING_ENVIRONMENT 12
#define LIGHTING_BINDING_PREFILTERED 13
#define LIGHTING_BINDING_BRDF_LUT 14
#define LIGHTING_BINDING_IRRADIANCE_SH 15
#define LIGHTING_BINDING_SAMPLING_TABLE 16
// gbuffer_targets.h's optional targets (the base colour image stands in without them).
#define LIGHTING_BINDING_GBUFFER_ANISOTROPY 17
#define LIGHTING_BINDING_GBUFFER_CLEAR_COAT 18
// Ambient occlusion (passes/ambient_occlusion): (bent normal, visibility), and the reference's
// specular visibility.
#define LIGHTING_BINDING_AMBIENT_OCCLUSION 19
#define LIGHTING_BINDING_SPECULAR_OCCLUSION 20
// Shadows (common/shadows.glsl, passes/shadows/shadow_pass.h).
#define LIGHTING_BINDING_SHADOW_ATLAS 21
#define LIGHTING_BINDING_SHADOW_VIEWS 22
#define LIGHTING_BINDING_SHADOW_LIGHTS 23
#define LIGHTING_BINDING_SHADOW_ATLAS_COMPARE 24
// The area lights' LTC table (lights/ltc_table_texture.h, common/area_lights.glsl).
#define LIGHTING_BINDING_LTC_MATRIX 25
#define LIGHTING_BINDING_LTC_MAGNITUDE 26
#define AREA_LIGHT_LTC_MATRIX_BINDING LIGHTING_BINDING_LTC_MATRIX
#define AREA_LIGHT_LTC_MAGNITUDE_BINDING LIGHTING_BINDING_LTC_MAGNITUDE
// Textured rect lights' image atlas (lights/area_light_textures.h).
#define LIGHTING_BINDING_AREA_LIGHT_TEXTURES 27
#define AREA_LIGHT_TEXTURE_BINDING LIGHTING_BINDING_AREA_LIGHT_TEXTURES
// Sky occlusion's depth-map atlas (passes/sky_occlusion, common/sky_occlusion.glsl).
#define LIGHTING_BINDING_SKY_OCCLUSION 28

#endif
