#version 460
#extension GL_GOOGLE_include_directive : require
// Deferred lighting: reads the G-buffer and adds the lit radiance to the HDR target, which
// holds emissive already. Clustered: each pixel evaluates its cluster's light list (plus the
// directional lights); brute force: every light at every pixel, the reference.
#include "common/camera.glsl"
#include "common/clusters.glsl"
#include "common/light_buffer.glsl"
#include "common/shading_models.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = 30) const bool kClustered = true;
// Stats variant: counts evaluated and lit light-pixel pairs per workgroup.
layout(constant_id = 31) const bool kCountLightPairs = false;

layout(binding = 2) uniform sampler2D gbufferBaseColor;
layout(binding = 3) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = 4) uniform sampler2D gbufferSpecularModel;
layout(binding = 5) uniform sampler2D gbufferCustomData;
layout(binding = 6) uniform sampler2D gbufferDepth;
layout(binding = 7, rgba32f) uniform image2D hdrRadiance;
layout(std430, binding = 8) readonly buffer ClusterRanges { uint clusterRanges[]; };
layout(std430, binding = 9) readonly buffer LightIndices { uint lightIndices[]; };
// Per workgroup: evaluated pairs, lit pairs (each fits 32 bits: 64 pixels x 2^26 lights).
layout(std430, binding = 10) writeonly buffer PairCounts { uvec2 pairCounts[]; };
// The slicing the depth occupancy pass derived ([2] sliceNear, [3] logRatio as float bits):
// read here rather than pushed, so lists assigned on the device need no host round trip.
layout(std430, binding = 11) readonly buffer DepthRange { uint depthRange[]; };

// A cluster whose list did not fit the device-assigned index buffer (light_assignment_pass.h):
// it evaluates every light instead, so no light is ever dropped.
const uint kListOverflow = 0xffffffffu;

layout(push_constant) uniform Push {
    ClusterGridParams grid;
    uint directionalCount;
} push;

shared uint groupEvaluations;
shared uint groupLitPairs;

Surface decodeSurface(ivec2 pixel, out vec3 N) {
    vec4 gb0 = texelFetch(gbufferBaseColor, pixel, 0);
    vec4 gb1 = texelFetch(gbufferNormalRoughMetal, pixel, 0);
    vec4 gb2 = texelFetch(gbufferSpecularModel, pixel, 0);
    Surface s;
    s.baseColor = gb0.rgb;
    s.roughness = gb1.z;
    s.metallic = gb1.w;
    s.specular = gb2.r;
    s.shadingModel = uint(gb2.g * 255.0 + 0.5);
    s.customData = texelFetch(gbufferCustomData, pixel, 0);
    N = octDecode(gb1.xy);
    return s;
}

struct PixelShading {
    Surface surface;
    vec3 P;
    vec3 N;
    vec3 V;
    vec3 R;
    float alpha;
    vec3 radiance;
    uint evaluations;
    uint litPairs;
};

void addLight(inout PixelShading px, uint lightIndex) {
    Light light = loadLight(lightIndex, camera.frameInfo.w);
    LightIncidence incidence = light.type == kLightDirectional
                                   ? evaluateDirectionalLight(light, px.N)
                                   : evaluateLocalLight(light, px.P, px.N, px.R, px.alpha);
    px.radiance += shadeSurface(px.surface, px.N, px.V, incidence);
    if (kCountLightPairs) {
        px.evaluations += 1u;
        px.litPairs += any(greaterThan(incidence.incidentIlluminance, vec3(0.0))) ? 1u : 0u;
    }
}

void shadePixel(ivec2 pixel, inout PixelShading px) {
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    if (depth <= 0.0) return;  // background (reverse-Z: 0 is infinitely far)
    px.surface = decodeSurface(pixel, px.N);
    if (px.surface.shadingModel == kShadingUnlit) return;

    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 world = camera.inverseViewProjection * vec4(ndc, depth, 1.0);
    px.P = world.xyz / world.w;
    px.V = safeNormalize(camera.cameraPosition.xyz - px.P);
    px.R = reflect(-px.V, px.N);
    px.alpha = alphaFromRoughness(px.surface.roughness);

    if (kClustered) {
        for (uint i = 0u; i < push.directionalCount; ++i) addLight(px, lightIndices[i]);
        uvec2 tile = uvec2(pixel) / push.grid.tileSize;
        float viewDepth = viewDepthFromNdc(depth, push.grid.projectionNear);
        uint slice = sliceOfDepth(uintBitsToFloat(depthRange[2]), uintBitsToFloat(depthRange[3]),
                                  push.grid.slices, viewDepth);
        uint cluster = (slice * push.grid.tilesY + tile.y) * push.grid.tilesX + tile.x;
        uint first = clusterRanges[2u * cluster];
        uint count = clusterRanges[2u * cluster + 1u];
        if (count == kListOverflow) {
            for (uint i = 0u; i < camera.frameInfo.z; ++i) {
                // Stream 3's w is the light type (light_buffer.glsl).
                if (uint(lightData[3u * camera.frameInfo.w + i].w) != kLightDirectional) {
                    addLight(px, i);
                }
            }
        } else {
            for (uint i = 0u; i < count; ++i) addLight(px, lightIndices[first + i]);
        }
    } else {
        for (uint i = 0u; i < camera.frameInfo.z; ++i) addLight(px, i);
    }
    vec4 previous = imageLoad(hdrRadiance, pixel);
    imageStore(hdrRadiance, pixel, vec4(previous.rgb + px.radiance, 1.0));
}

void main() {
    if (kCountLightPairs && gl_LocalInvocationIndex == 0u) {
        groupEvaluations = 0u;
        groupLitPairs = 0u;
    }
    if (kCountLightPairs) barrier();

    PixelShading px;
    px.radiance = vec3(0.0);
    px.evaluations = 0u;
    px.litPairs = 0u;
    shadePixel(ivec2(gl_GlobalInvocationID.xy), px);

    if (kCountLightPairs) {
        atomicAdd(groupEvaluations, px.evaluations);
        atomicAdd(groupLitPairs, px.litPairs);
        barrier();
        if (gl_LocalInvocationIndex == 0u) {
            uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
            pairCounts[group] = uvec2(groupEvaluations, groupLitPairs);
        }
    }
}
