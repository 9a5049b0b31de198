// Specialization-constant IDs, shared by the GLSL that declares them and the C++ that sets
// them (valid in both languages): one number per switch, written once.
#ifndef CANDELA_SPECIALIZATION_IDS_H
#define CANDELA_SPECIALIZATION_IDS_H

// Shading models a variant contains (shading_models.glsl).
#define SPEC_SUBSURFACE_ENABLED 10
#define SPEC_LEGACY_DIFFUSE_SPECULAR_ENABLED 11
// The BRDF (brdf.glsl, --brdf): Karis 2013's ("Real Shading in Unreal Engine 4") UE4 terms (false)
// or energy-conserving (true).
#define SPEC_ENERGY_CONSERVING 12
// Material extensions a variant contains (shading_models.glsl): KHR_materials_anisotropy and
// KHR_materials_clearcoat.
#define SPEC_ANISOTROPY_ENABLED 13
#define SPEC_CLEAR_COAT_ENABLED 14
// Light shapes a variant contains (lights.glsl).
#define SPEC_SPHERE_LIGHTS_ENABLED 20
#define SPEC_TUBE_LIGHTS_ENABLED 21
#define SPEC_SPOT_LIGHTS_ENABLED 22
// How sphere and tube lights integrate (lights.glsl, --area-lights): Karis 2013's representative
// point (false) or linearly transformed cosines (true).
#define SPEC_AREA_LIGHTS_LTC 23
// Area light shapes a variant contains (lights.glsl, issue 15).
#define SPEC_RECT_LIGHTS_ENABLED 24
#define SPEC_DISK_LIGHTS_ENABLED 25
// The ways the frame's sized lights are integrated (lights.glsl), one bit each: a rect or disk
// by LTC, by representative point, a textured rect, a constant-intensity emitter, a sphere or
// tube by LTC. Each per-light choice is a branch lavapipe runs for every light; a path no light
// takes is compiled out.
#define SPEC_AREA_LIGHT_PATHS 26
#define AREA_PATH_LTC 1u
#define AREA_PATH_REPRESENTATIVE 2u
#define AREA_PATH_TEXTURED 4u
#define AREA_PATH_CONSTANT_INTENSITY 8u
#define AREA_PATH_PUNCTUAL_LTC 16u
#define AREA_PATHS_ALL 31u
// A textured rect by LTC: cells per side of the image its specular lobe is integrated over
// (area_lights.glsl; its diffuse takes half as many, at least one).
#define SPEC_AREA_TEXTURE_CELLS 27
// Lighting and forward passes: clustered lists or brute force, pair counters, IBL mode
// (0 none, 1 split sum, 2 mobile, 3 reference).
#define SPEC_CLUSTERED 30
#define SPEC_COUNT_LIGHT_PAIRS 31
#define SPEC_IBL_MODE 32
// Lighting pass: ambient occlusion of the sky's light (0 off, 1 GTAO, 2 reference).
#define SPEC_AMBIENT_OCCLUSION 33
// Shadow sampling (shadows.glsl): on only in frames where a light casts.
#define SPEC_SHADOWS_ENABLED 34
// Lighting pass: sky occlusion of the sky's light (common/sky_occlusion.glsl).
#define SPEC_SKY_OCCLUSION 35
// Lighting pass: of the lights that cast, a directional one (cascades) and a local one (cube
// faces and spot views, penumbrae): each kind's shadow code only in frames that have it.
#define SPEC_DIRECTIONAL_SHADOWS 37
#define SPEC_LOCAL_SHADOWS 38
// Shadow sampling: penumbrae of sphere and tube lights by blocker search (false: hard PCF for
// every map, and the search's code compiled out).
#define SPEC_SOFT_SHADOWS 39
// Shadow sampling: hard shadows' compare taps per axis (2: a 3x3-texel tent, 1: one tap).
#define SPEC_HARD_SHADOW_TAPS 41
// Volumetrics: the frame has rect or disk lights, lit in the medium by their exact form factor;
// its code alone, never run, made the per-light march 10x slower on lavapipe.
#define SPEC_MEDIUM_AREA_LIGHTS 36
// assign_lights.comp: the counting or the writing walk.
#define SPEC_ASSIGN_WRITE_PASS 40
// material.glsl: which texture slots a draw's material may have (bit i: slot i); a slot
// outside the mask reads as its white default without a lookup.
#define SPEC_MATERIAL_TEXTURE_SLOTS 42
// lighting.comp: the local-light loops the frame's lights reach (light_loop_bits.h).
#define SPEC_LIGHT_LOOPS 43

#endif
