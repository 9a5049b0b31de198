// Bindings of upscale.comp, shared by the shader and upscale_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_UPSCALE_BINDINGS_H
#define CANDELA_UPSCALE_BINDINGS_H

#define UPSCALE_BINDING_INPUT 0   // radiance at the render size (sampled, bilinear, clamped)
#define UPSCALE_BINDING_OUTPUT 1  // radiance at the output size (storage, write)

#endif
