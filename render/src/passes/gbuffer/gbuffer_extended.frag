#version 460
#extension GL_GOOGLE_include_directive : require
// gbuffer.frag plus the anisotropy and clear-coat targets (gbuffer_targets.h).
#define GBUFFER_MATERIAL_EXTENSIONS
#include "gbuffer_fragment.glsl"
