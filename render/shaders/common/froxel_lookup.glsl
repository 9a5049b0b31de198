// Reading the integrated froxel grid (passes/volumetrics): the in-scattered radiance from the
// camera to a view depth and the transmittance over it, for the composite over opaque
// surfaces and for blended surfaces in the forward pass. The includer defines
// FROXEL_INTEGRATED_BINDING.
#ifndef CANDELA_FROXEL_LOOKUP_GLSL
#define CANDELA_FROXEL_LOOKUP_GLSL

#include "common/froxel_grid.glsl"

layout(std430, binding = FROXEL_INTEGRATED_BINDING) readonly buffer FroxelIntegrated {
    FroxelGrid froxelParams;
    vec4 froxelIntegrated[];
};

// View depth (m) of slice boundary b: 0 for b = 0 (the first slice reaches back to the
// camera), then exponential from the near plane to the far distance.
float froxelBoundaryDepth(float b, float slices, float near, float far) {
    if (b <= 0.0) return 0.0;
    return near * pow(far / near, b / slices);
}

// Continuous slice coordinate of view depth d: linear in the first slice, exponential after.
float froxelSliceCoordinate(float d, float slices, float near, float far) {
    float first = froxelBoundaryDepth(1.0, slices, near, far);
    if (d < first) return d / first;
    return clamp(slices * log(d / near) / log(far / near), 1.0, slices);
}

uint froxelIndexOf(uvec3 f, uvec3 grid) {
    return (f.z * grid.y + f.y) * grid.x + f.x;
}

// (radiance, transmittance) from the camera to slice boundary b of column c.
vec4 froxelBoundary(uvec2 c, int b) {
    if (b <= 0) return vec4(0.0, 0.0, 0.0, 1.0);
    return froxelIntegrated[froxelIndexOf(uvec3(c, uint(b - 1)), froxelParams.grid.xyz)];
}

// The same with the transmittance as optical depth (-ln T), which is what varies smoothly
// (linearly in distance for a uniform medium) between columns and boundaries.
vec4 froxelDepthBoundary(uvec2 c, int b) {
    vec4 v = froxelBoundary(c, b);
    return vec4(v.rgb, -log(max(v.a, 1e-30)));
}

vec4 froxelColumn(uvec2 c, float s) {
    int b = int(floor(s));
    return mix(froxelDepthBoundary(c, b),
               froxelDepthBoundary(c, min(b + 1, int(froxelParams.grid.z))), s - float(b));
}

// The medium between the camera and view depth `viewDepth` at window position `fragCoord`
// (pixels) of an image `size`: bilinear across columns, linear between slice boundaries
// (the transmittance as optical depth).
// (0, 1), no medium, when the frame has no froxels.
vec4 froxelsAt(vec2 fragCoord, vec2 size, float viewDepth) {
    if (froxelParams.grid.w == 0u) return vec4(0.0, 0.0, 0.0, 1.0);
    uvec3 grid = froxelParams.grid.xyz;
    float d = min(viewDepth, froxelParams.range.y);
    float s = froxelSliceCoordinate(d, float(grid.z), froxelParams.range.x, froxelParams.range.y);
    // Column centres; within half a froxel of the image border the nearest two columns are
    // extrapolated (the ray's length through the medium keeps growing toward the corners).
    vec2 p = fragCoord / size * vec2(grid.xy) - 0.5;
    uvec2 c0 = uvec2(clamp(floor(p), vec2(0.0), max(vec2(grid.xy) - 2.0, vec2(0.0))));
    uvec2 c1 = min(c0 + 1u, grid.xy - 1u);
    vec2 w = p - vec2(c0);
    vec4 v = mix(mix(froxelColumn(c0, s), froxelColumn(uvec2(c1.x, c0.y), s), w.x),
                 mix(froxelColumn(uvec2(c0.x, c1.y), s), froxelColumn(c1, s), w.x), w.y);
    return vec4(max(v.rgb, vec3(0.0)), exp(-max(v.a, 0.0)));
}

#endif
