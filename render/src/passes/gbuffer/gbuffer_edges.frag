#version 460
#extension GL_GOOGLE_include_directive : require
// gbuffer.frag plus GBAA's edge target (--aa gbaa; gbuffer_edges.geom).
#define GBUFFER_EDGES
#include "gbuffer_fragment.glsl"
