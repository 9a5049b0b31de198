// Light type codes of the light buffer (stream 3's w), shared by the C++ that packs them
// (render/src/lights/gpu_light_types.h) and the GLSL that dispatches on them (lights.glsl):
// one number per type, written once (valid in both languages).
#ifndef CANDELA_LIGHT_TYPES_H
#define CANDELA_LIGHT_TYPES_H

#define LIGHT_TYPE_POINT 0
#define LIGHT_TYPE_SPOT 1
#define LIGHT_TYPE_DIRECTIONAL 2

#endif
