// Light type codes of the light buffer (stream 3's w), shared by the C++ that packs them
// (render/src/lights/gpu_light_types.h) and the GLSL that dispatches on them (lights.glsl):
// one number per type, written once (valid in both languages); and each type's cluster bounds.
#ifndef CANDELA_LIGHT_TYPES_H
#define CANDELA_LIGHT_TYPES_H

#define LIGHT_TYPE_POINT 0
#define LIGHT_TYPE_SPOT 1
#define LIGHT_TYPE_DIRECTIONAL 2
#define LIGHT_TYPE_RECT 3
#define LIGHT_TYPE_DISK 4
#define LIGHT_TYPE_COUNT 5

// What clustered culling bounds each type by (ClusterBounds in gpu_light_types.h, whose table is
// checked against this list at compile time), listed by type code: the culling shaders look a
// light's bounds kind up by its code (lights.glsl's lightBoundsKind) instead of naming types.
#define LIGHT_BOUNDS_EVERYWHERE 0u
#define LIGHT_BOUNDS_FALLOFF 1u
#define LIGHT_BOUNDS_CONE 2u
// One-sided area lights: the falloff sphere cut by the half-space in front of the light.
#define LIGHT_BOUNDS_HALF_SPACE 3u
#define LIGHT_BOUNDS_BY_TYPE                                                 \
    LIGHT_BOUNDS_FALLOFF, LIGHT_BOUNDS_CONE, LIGHT_BOUNDS_EVERYWHERE,        \
        LIGHT_BOUNDS_HALF_SPACE, LIGHT_BOUNDS_HALF_SPACE

#endif
