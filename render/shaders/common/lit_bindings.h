// Binding numbers of the lit inputs (render/src/lit_inputs.h, common/lit_inputs.glsl): what
// every pass that lights surfaces binds beside its own inputs (the deferred lighting, hair,
// wires, blended surfaces). Valid in C++ and GLSL. Above every pass's own numbers and
// PREVIOUS_WORLDS_BINDING, so any lit pipeline's layout can hold them.
#ifndef CANDELA_LIT_BINDINGS_H
#define CANDELA_LIT_BINDINGS_H

#include "common/shared_bindings.h"

// The cluster lists (clusters.glsl) and the slicing the depth occupancy pass derived.
#define LIT_BINDING_CLUSTER_RANGES 40
#define LIT_BINDING_LIGHT_INDICES 41
#define LIT_BINDING_DEPTH_RANGE 42
// The sky (ibl.glsl, ambient_lighting.glsl): prefiltered cube, BRDF LUT, SH irradiance.
#define LIT_BINDING_PREFILTERED 43
#define LIT_BINDING_BRDF_LUT 44
#define LIT_BINDING_IRRADIANCE_SH 45
// Shadows (shadows.glsl, passes/shadows/shadow_pass.h).
#define LIT_BINDING_SHADOW_ATLAS 46
#define LIT_BINDING_SHADOW_VIEWS 47
#define LIT_BINDING_SHADOW_LIGHTS 48
#define LIT_BINDING_SHADOW_ATLAS_COMPARE 49
// The area lights' LTC table (lights/ltc_table_texture.h, area_lights.glsl) and the textured
// rects' prefiltered textures (area_light_texture.glsl).
#define LIT_BINDING_LTC_MATRIX 50
#define LIT_BINDING_LTC_MAGNITUDE 51
#define LIT_BINDING_AREA_LIGHT_TEXTURES 52
// The sky occlusion atlas (sky_occlusion.glsl, passes/sky_occlusion).
#define LIT_BINDING_SKY_OCCLUSION 53

// What the shared includes expect. Textured rects and sky occlusion stay opt-in (a pass defines
// AREA_LIGHT_TEXTURE_BINDING or SKY_OCCLUSION_BINDING as the numbers above to compile them in).
#define SHADOW_ATLAS_BINDING LIT_BINDING_SHADOW_ATLAS
#define SHADOW_ATLAS_COMPARE_BINDING LIT_BINDING_SHADOW_ATLAS_COMPARE
#define SHADOW_VIEWS_BINDING LIT_BINDING_SHADOW_VIEWS
#define SHADOW_LIGHTS_BINDING LIT_BINDING_SHADOW_LIGHTS
#define AREA_LIGHT_LTC_MATRIX_BINDING LIT_BINDING_LTC_MATRIX
#define AREA_LIGHT_LTC_MAGNITUDE_BINDING LIT_BINDING_LTC_MAGNITUDE

#endif
