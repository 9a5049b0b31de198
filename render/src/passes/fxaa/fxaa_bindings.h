// Bindings of fxaa.comp, shared by the shader and fxaa_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_FXAA_BINDINGS_H
#define CANDELA_FXAA_BINDINGS_H

#define FXAA_BINDING_INPUT 0   // the tonemapped, sRGB-encoded image (sampled, bilinear)
#define FXAA_BINDING_OUTPUT 1  // the LDR target (storage, write)

#endif
