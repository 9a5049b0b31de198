// Bindings of debug_text.comp, shared by the shader and debug_text_pass.cpp (valid in C++ and
// GLSL).
#ifndef CANDELA_DEBUG_TEXT_BINDINGS_H
#define CANDELA_DEBUG_TEXT_BINDINGS_H

#define DEBUG_TEXT_BINDING_LDR 0
#define DEBUG_TEXT_BINDING_TEXT 1

#endif
