// Bindings of gbuffer.vert and gbuffer.frag, shared by them and gbuffer_pass.cpp (valid in
// C++ and GLSL). The camera: common/shared_bindings.h.
#ifndef CANDELA_GBUFFER_BINDINGS_H
#define CANDELA_GBUFFER_BINDINGS_H

#include "common/shared_bindings.h"

// common/material.glsl: the material array, then one sampler per TextureSlot.
#define GBUFFER_BINDING_MATERIALS 1
#define GBUFFER_BINDING_FIRST_TEXTURE 2
// common/material_layers.glsl (layered variants only): one sampler per LayerTextureSlot, after
// the kTextureSlotCount (11) material slots.
#define GBUFFER_BINDING_FIRST_LAYER_TEXTURE 13

#endif
