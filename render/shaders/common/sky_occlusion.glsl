// Sky occlusion (render/README.md "Sky occlusion"; passes/sky_occlusion): how much of the sky a
// surface sees past the scene's static geometry. Each of n directions over the sky hemisphere
// has an orthographic depth map of the scene (a tile of one atlas) whose texels hold the
// highest surface of their column; a point sees the sky in that direction when it is no lower
// than that surface. Its sky light is the cosine-weighted (diffuse) or lobe-weighted
// (specular) share of the directions that see the sky; directions below the horizon are the
// sky model's own ground and count as seen. The includer defines SKY_OCCLUSION_BINDING and
// includes common/camera.glsl (the sphere and layout travel in the camera block).
#ifndef CANDELA_SKY_OCCLUSION_GLSL
#define CANDELA_SKY_OCCLUSION_GLSL

#include "common/math.glsl"

layout(binding = SKY_OCCLUSION_BINDING) uniform sampler2DShadow skyOcclusionMaps;

const float kSkyGoldenAngle = 2.39996323;  // pi (3 - sqrt 5)
// Bias in texels of the maps: the receiver moves off its surface along its normal, and toward
// the sky by a constant plus a slope term (the texel's depth spread at a grazing direction).
const float kSkyNormalOffset = 1.5;
const float kSkyDepthBias = 1.0;
const float kSkySlopeBias = 1.5;
const float kSkyMaxSlope = 100.0;

// Direction i of n: equal-area over the upper hemisphere (sky_occlusion_directions.cpp).
vec3 skyOcclusionDirection(uint i, uint n) {
    float y = (float(i) + 0.5) / float(n);
    float r = sqrt(max(0.0, 1.0 - y * y));
    float phi = float(i) * kSkyGoldenAngle;
    return vec3(r * cos(phi), y, r * sin(phi));
}

// The sky seen from P in direction i (0 blocked .. 1 open, bilinear compare of 4 texels).
float skyOcclusionTest(uint i, vec3 P, vec3 N) {
    uint n = camera.skyOcclusionLayout.x;
    vec3 d = skyOcclusionDirection(i, n);
    vec3 helper = abs(d.y) > 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 right = normalize(cross(helper, d));
    vec3 up = cross(d, right);
    float radius = camera.skyOcclusionSphere.w;
    float tile = float(camera.skyOcclusionLayout.z);
    float texel = 2.0 * radius / tile;
    float NoL = dot(N, d);
    float sinL = sqrt(saturate(1.0 - NoL * NoL));
    vec3 q = P + N * (kSkyNormalOffset * texel) - camera.skyOcclusionSphere.xyz;
    vec2 uv = vec2(dot(right, q), dot(up, q)) / radius * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    float slope = min(sinL / max(abs(NoL), 1e-2), kSkyMaxSlope);
    float height = dot(d, q) + texel * (kSkyDepthBias + kSkySlopeBias * slope);
    // Above the maps' range nothing blocks; below it, the receiver compares as the lowest
    // depth (0, what an empty texel holds), so only geometry in the range blocks it.
    float stored = (height + radius) / (4.0 * radius);
    if (stored >= 1.0) return 1.0;
    stored = max(stored, 0.0);
    uint perRow = camera.skyOcclusionLayout.y;
    vec2 first = vec2(float(i % perRow), float(i / perRow)) * tile;
    vec2 tc = clamp(first + uv * tile, first + 0.5, first + tile - 0.5);
    return textureLod(skyOcclusionMaps,
                      vec3(tc / float(camera.skyOcclusionLayout.w), stored), 0.0);
}

struct SkyVisibility {
    float diffuse;    // cosine-weighted share of the sky seen around N
    float specular;   // share of the specular lobe around R that sees the sky
    vec3 bentNormal;  // N turned away from the blocked directions (N when nothing blocks)
};

// The Phong exponent of a roughness's lobe, held wide enough to span about four of the n
// directions (each 2 pi / n sr; a Phong lobe covers about 2 pi / (e + 1)).
float skyLobeExponent(float roughness, uint n) {
    float alpha = max(roughness * roughness, 1e-3);
    return clamp(2.0 / (alpha * alpha) - 2.0, 1.0, max(float(n) / 4.0 - 1.0, 1.0));
}

// Every direction is tested once and weighted twice. The lower hemisphere's mirror image of
// each direction (the same weights at -y) stands for the ground's share of the lobe: the sky
// model's ground, lit by the sky. Under a roof the ground in view is lit by as little sky as
// the roof lets in, so that share is scaled by `ground`: the sky a floor sees at the point
// kSkyGroundReach in front of the surface (horizontally along N, at P's height; P itself for
// a floor), the directions weighted by their height d_i.y. In the open ground = 1 and nothing
// changes; a wall inside a hall sees a covered floor; a beam's face under an overhang that
// looks out over a sunlit floor keeps its ground light.
// visibility = (below x ground + sum w open) / (below + sum w).
const float kSkyGroundReach = 2.0;

SkyVisibility skyVisibility(vec3 P, vec3 N, vec3 R, float roughness) {
    SkyVisibility v = SkyVisibility(1.0, 1.0, N);
    uint n = camera.skyOcclusionLayout.x;
    if (n == 0u) return v;
    float exponent = skyLobeExponent(roughness, n);
    float diffuseAll = 0.0, diffuseOpen = 0.0, diffuseBelow = 0.0;
    float specularAll = 0.0, specularOpen = 0.0, specularBelow = 0.0;
    vec3 blocked = vec3(0.0);
    float groundAll = 0.0, groundOpen = 0.0;
    vec3 across = vec3(N.x, 0.0, N.z);
    bool groundElsewhere = dot(across, across) > 1e-4;
    vec3 groundPoint = groundElsewhere ? P + normalize(across) * kSkyGroundReach : P;
    for (uint i = 0u; i < n; ++i) {
        vec3 d = skyOcclusionDirection(i, n);
        vec3 mirrored = vec3(d.x, -d.y, d.z);
        float wb = max(dot(N, mirrored), 0.0);
        float wbs = pow(max(dot(R, mirrored), 0.0), exponent);
        diffuseBelow += wb;
        specularBelow += wbs;
        float wd = max(dot(N, d), 0.0);
        float ws = pow(max(dot(R, d), 0.0), exponent);
        if (groundElsewhere && (wb > 0.0 || wbs > 0.0)) {
            groundAll += d.y;
            groundOpen += d.y * skyOcclusionTest(i, groundPoint, vec3(0.0, 1.0, 0.0));
        }
        if (wd == 0.0 && ws == 0.0) continue;
        float open = skyOcclusionTest(i, P, N);
        diffuseAll += wd;
        diffuseOpen += wd * open;
        specularAll += ws;
        specularOpen += ws * open;
        blocked += wd * (1.0 - open) * d;
        if (!groundElsewhere) {
            groundAll += d.y;
            groundOpen += d.y * open;
        }
    }
    float ground = groundAll > 0.0 ? groundOpen / groundAll : 1.0;
    float diffuseTotal = diffuseAll + diffuseBelow;
    if (diffuseTotal > 0.0) {
        v.diffuse = (diffuseBelow * ground + diffuseOpen) / diffuseTotal;
        // The cosine lobe's mean direction is 2/3 N; take out the blocked directions' share.
        if (any(notEqual(blocked, vec3(0.0)))) {
            v.bentNormal = safeNormalize(N * (2.0 / 3.0) - blocked / diffuseTotal);
            if (dot(v.bentNormal, N) <= 0.0) v.bentNormal = N;
        }
    }
    float specularTotal = specularAll + specularBelow;
    if (specularTotal > 0.0) {
        v.specular = (specularBelow * ground + specularOpen) / specularTotal;
    }
    return v;
}

#endif
