// The G-buffer fragment shader's body, compiled eight times: gbuffer.frag (the four targets
// every frame has), gbuffer_extended.frag (GBUFFER_MATERIAL_EXTENSIONS: also the anisotropy and
// clear-coat targets, for frames whose materials use them), and each of them with
// GBUFFER_MATERIAL_LAYERS (material layers blended, for frames with a layered material); and
// those four with GBUFFER_EDGES (*_edges.frag: GBAA's edge target after the others, fed by
// gbuffer_edges.geom, for --aa gbaa frames).
#include "gbuffer_bindings.h"
// Writes the G-buffer (layout in gbuffer_targets.h) and the emissive radiance into the HDR
// target. Blended materials are drawn by the forward transparency pass instead.
#define MATERIAL_BUFFER_BINDING GBUFFER_BINDING_MATERIALS
#define MATERIAL_TEXTURE_BINDING GBUFFER_BINDING_FIRST_TEXTURE
#include "common/material.glsl"
#ifdef GBUFFER_MATERIAL_LAYERS
#define MATERIAL_LAYER_TEXTURE_BINDING GBUFFER_BINDING_FIRST_LAYER_TEXTURE
#include "common/material_layers.glsl"
#endif
#include "common/motion_vectors.glsl"
#ifdef GBUFFER_EDGES
#include "common/gbaa_edges.glsl"
#endif

layout(push_constant) uniform Draw {
    mat4 world;
    uint material;
} draw;

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec4 inTangent;
layout(location = 2) in vec2 inUv0;
layout(location = 3) in vec2 inUv1;
layout(location = 4) in vec4 inColor;
layout(location = 5) in vec4 inCurrentClip;
layout(location = 6) in vec4 inPreviousClip;
#ifdef GBUFFER_EDGES
layout(location = 7) flat in vec3 inEdgeLines[3];  // gbuffer_edges.geom
#endif

layout(location = 0) out vec4 outBaseColor;  // rgb, a = occlusion
layout(location = 1) out vec4 outNormalRoughMetal;  // oct normal xy, roughness, metallic
layout(location = 2) out vec4 outSpecularModel;  // specular, shading model / 255
layout(location = 3) out vec4 outCustomData;
layout(location = 4) out vec4 outEmissive;  // HDR radiance, cd/m^2
layout(location = 5) out vec2 outMotion;    // gbuffer.motion (motion_vectors.glsl)
#ifdef GBUFFER_MATERIAL_EXTENSIONS
layout(location = 6) out vec2 outAnisotropy;  // tangent angle / pi, strength
layout(location = 7) out vec4 outClearCoat;   // factor, roughness, oct coat normal xy

// The anisotropy direction as its angle in [0, pi) from the first axis of tangentFrame(N), N
// as the lighting pass decodes it (16-bit octahedral): the lobe is symmetric under T -> -T,
// so half a turn is enough, and one 16-bit channel holds it to pi / 65535 = 0.0027 degrees.
float anisotropyAngle(vec2 encodedNormal, vec3 T) {
    vec3 N = octDecode(round(encodedNormal * 65535.0) / 65535.0);
    mat3 frame = tangentFrame(N);
    float angle = atan(dot(T, frame[1]), dot(T, frame[0]));
    if (angle < 0.0) angle += PI;
    return min(angle / PI, 1.0);
}
#endif
#ifdef GBUFFER_EDGES
// gbuffer.edges (common/gbaa_edges.glsl), after the targets above.
#ifdef GBUFFER_MATERIAL_EXTENSIONS
layout(location = 8) out vec4 outEdges;
#else
layout(location = 6) out vec4 outEdges;
#endif
#endif

void main() {
    MaterialUv uv = materialGradients(inUv0, inUv1);
    Material m = materials[draw.material];
#ifdef GBUFFER_MATERIAL_LAYERS
    vec4 baseColor = materialBaseColor(m, uv, layeredVertexTint(m, inColor));
#else
    vec4 baseColor = materialBaseColor(m, uv, inColor);
#endif
    if (m.alphaCutoff >= 0.0 && baseColor.a < m.alphaCutoff) discard;

    MaterialSample s = evaluateMaterial(m, uv, baseColor, inNormal, inTangent, gl_FrontFacing);
#ifdef GBUFFER_MATERIAL_LAYERS
    blendMaterialLayers(s, m, uv, inColor, inNormal, inTangent, gl_FrontFacing);
#endif
    outBaseColor = vec4(s.baseColor.rgb, s.occlusion);
    outNormalRoughMetal = vec4(octEncode(s.N), s.roughness, s.metallic);
    outSpecularModel = vec4(s.specular, float(s.shadingModel) / 255.0, 0.0, 0.0);
    outCustomData = s.customData;
    outEmissive = vec4(s.emissive, 1.0);
    outMotion = screenMotion(inCurrentClip, inPreviousClip);
#ifdef GBUFFER_MATERIAL_EXTENSIONS
    MaterialExtensions e = evaluateMaterialExtensions(m, uv, inNormal, inTangent, gl_FrontFacing, s.N);
    outAnisotropy = vec2(e.anisotropy > 0.0 ? anisotropyAngle(outNormalRoughMetal.xy, e.anisotropyT)
                                            : 0.0,
                         e.anisotropy);
    outClearCoat = vec4(e.clearCoat, e.clearCoatRoughness, octEncode(e.clearCoatN));
#endif
#ifdef GBUFFER_EDGES
    outEdges = gbaaEdgeDistances(gl_FragCoord.xy, inEdgeLines);
#endif
}
