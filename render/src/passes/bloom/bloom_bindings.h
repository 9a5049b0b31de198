// Bindings of bloom_downsample.comp and bloom_composite.comp, shared by the shaders and
// bloom_pass.cpp (valid in C++ and GLSL).
#ifndef CANDELA_BLOOM_BINDINGS_H
#define CANDELA_BLOOM_BINDINGS_H

// bloom_downsample.comp: one level from the one above it (or the HDR target).
#define BLOOM_DOWNSAMPLE_BINDING_SOURCE 0  // storage, read
#define BLOOM_DOWNSAMPLE_BINDING_TARGET 1  // storage, write

// bloom_composite.comp: the HDR target, read and rewritten in place, and every level.
#define BLOOM_COMPOSITE_BINDING_HDR 0
#define BLOOM_COMPOSITE_BINDING_FIRST_LEVEL 1  // sampled, bilinear; BLOOM_MAX_LEVELS of them
#define BLOOM_MAX_LEVELS 6

#endif
