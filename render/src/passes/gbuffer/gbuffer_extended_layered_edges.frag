#version 460
#extension GL_GOOGLE_include_directive : require
// gbuffer_extended_layered.frag plus GBAA's edge target (--aa gbaa; gbuffer_edges.geom).
#define GBUFFER_MATERIAL_EXTENSIONS
#define GBUFFER_MATERIAL_LAYERS
#define GBUFFER_EDGES
#include "gbuffer_fragment.glsl"
