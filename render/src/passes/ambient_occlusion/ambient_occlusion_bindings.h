// Bindings of the ambient occlusion passes (gtao.comp, ao_denoise.comp, ao_reference.comp),
// shared by the shaders and ambient_occlusion_pass.cpp (valid in C++ and GLSL). Camera:
// common/shared_bindings.h.
#ifndef CANDELA_AMBIENT_OCCLUSION_BINDINGS_H
#define CANDELA_AMBIENT_OCCLUSION_BINDINGS_H

#include "common/shared_bindings.h"

// Inputs: the G-buffer's depth and its normal + roughness + metallic image.
#define AO_BINDING_DEPTH 2
#define AO_BINDING_NORMAL 3
// gtao.comp and ao_reference.comp write (world bent normal xyz, visibility) here;
// ao_denoise.comp reads it.
#define AO_BINDING_OUTPUT 4
// ao_denoise.comp: the filtered result. gtao.comp and ao_reference.comp: the reflection lobe's
// visibility.
#define AO_BINDING_SECOND_OUTPUT 5
#define AO_BINDING_INPUT 6
// ao_temporal.comp: the G-buffer's motion, last frame's history (read) and this frame's
// (written); it writes the accumulated result to AO_BINDING_SECOND_OUTPUT.
#define AO_BINDING_MOTION 7
#define AO_BINDING_HISTORY 8
#define AO_BINDING_HISTORY_OUTPUT 9

#endif
