// Bindings of tonemap.comp, shared by the shader and tonemap_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_TONEMAP_BINDINGS_H
#define CANDELA_TONEMAP_BINDINGS_H

#define TONEMAP_BINDING_HDR 0
#define TONEMAP_BINDING_LDR 1

#endif
