#version 460
#extension GL_GOOGLE_include_directive : require
// gbuffer_extended.frag with material layers blended (common/material_layers.glsl).
#define GBUFFER_MATERIAL_EXTENSIONS
#define GBUFFER_MATERIAL_LAYERS
#include "gbuffer_fragment.glsl"
