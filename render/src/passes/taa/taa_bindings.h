// Bindings of taa.comp, shared by the shader and taa_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_TAA_BINDINGS_H
#define CANDELA_TAA_BINDINGS_H

#define TAA_BINDING_CURRENT 0   // this frame's jittered HDR radiance (storage, read)
#define TAA_BINDING_MOTION 1    // gbuffer.motion (sampled)
#define TAA_BINDING_HISTORY 2   // last frame's resolve (sampled, bilinear)
#define TAA_BINDING_RESOLVED 3  // this frame's resolve (storage, write): next frame's history

#endif
