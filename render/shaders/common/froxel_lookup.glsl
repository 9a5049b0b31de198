// Reading the integrated froxel buffer: the fog's grid (passes/volumetrics), the in-scattered
// radiance from the camera to a view depth and the transmittance over it, for the composite
// over opaque surfaces and for blended surfaces in the forward pass; and the air's
// aerial-perspective grid (passes/scattering) for blended surfaces and wires. The includer
// defines FROXEL_INTEGRATED_BINDING.
#ifndef CANDELA_FROXEL_LOOKUP_GLSL
#define CANDELA_FROXEL_LOOKUP_GLSL

#include "common/atmosphere.glsl"
#include "common/camera.glsl"
#include "common/froxel_grid.glsl"

layout(std430, binding = FROXEL_INTEGRATED_BINDING) readonly buffer FroxelIntegrated {
    FroxelGrid froxelParams;
    AerialGrid aerialParams;
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

// (radiance, transmittance) from the camera to slice boundary b of column c. `withSun`: with
// the sun's in-scattering where the frame marches it per pixel over the froxels and keeps its
// own boundaries for the readers the march does not reach (grid.w 2, common/froxel_grid.glsl).
vec4 froxelBoundary(uvec2 c, int b, bool withSun) {
    if (b <= 0) return vec4(0.0, 0.0, 0.0, 1.0);
    uvec3 grid = froxelParams.grid.xyz;
    uint index = froxelIndexOf(uvec3(c, uint(b - 1)), grid);
    vec4 v = froxelIntegrated[index];
    if (withSun && froxelParams.grid.w == 2u)
        v.rgb += froxelIntegrated[grid.x * grid.y * grid.z + index].rgb;
    return v;
}

// The same with the transmittance as optical depth (-ln T), which is what varies smoothly
// (linearly in distance for a uniform medium) between columns and boundaries.
vec4 froxelDepthBoundary(uvec2 c, int b, bool withSun) {
    vec4 v = froxelBoundary(c, b, withSun);
    return vec4(v.rgb, -log(max(v.a, 1e-30)));
}

vec4 froxelColumn(uvec2 c, float s, bool withSun) {
    int b = int(floor(s));
    return mix(froxelDepthBoundary(c, b, withSun),
               froxelDepthBoundary(c, min(b + 1, int(froxelParams.grid.z)), withSun),
               s - float(b));
}

// The medium between the camera and view depth `viewDepth` at window position `fragCoord`
// (pixels) of an image `size`: bilinear across columns, linear between slice boundaries
// (the transmittance as optical depth). `withSun`: froxelBoundary's (the opaque frame's
// composite leaves the sun to its per-pixel march; blended surfaces, wires and hair take it).
// (0, 1), no medium, when the frame has no froxels.
vec4 froxelsAt(vec2 fragCoord, vec2 size, float viewDepth, bool withSun) {
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
    vec4 v = mix(mix(froxelColumn(c0, s, withSun), froxelColumn(uvec2(c1.x, c0.y), s, withSun),
                     w.x),
                 mix(froxelColumn(uvec2(c0.x, c1.y), s, withSun), froxelColumn(c1, s, withSun),
                     w.x),
                 w.y);
    return vec4(max(v.rgb, vec3(0.0)), exp(-max(v.a, 0.0)));
}

// The air's grid: slice boundary b of n lies at view depth far (b / n)^2 (fine near the
// camera, where a blended surface's shafts are large on screen). Continuous boundary
// coordinate of view depth d (clamped to the grid).
float aerialSliceCoordinate(float d, float slices, float far) {
    return slices * sqrt(clamp(d / far, 0.0, 1.0));
}

// W (common/froxel_grid.glsl) from the camera to boundary `b` of column `c`; 0 at b = 0.
vec3 aerialBoundary(uvec2 c, int b) {
    if (b <= 0) return vec3(0.0);
    uvec3 grid = aerialParams.grid.xyz;
    uint index = uint(aerialParams.range.y) + froxelIndexOf(uvec3(c, uint(b - 1)), grid);
    return froxelIntegrated[index].rgb;
}

// W at boundary coordinate s, linear in view depth between the boundaries: over a lit slice h
// metres long that errs by about sigma_t h / 8 of the slice's own share (2 % for the last,
// 12 m slice at 400 times clear air's density, far less nearer).
vec3 aerialColumn(uvec2 c, float s) {
    float slices = float(aerialParams.grid.z);
    int b = min(int(floor(s)), int(aerialParams.grid.z) - 1);
    float d0 = float(b) / slices, d1 = float(b + 1) / slices;
    float f = saturate((s * s / (slices * slices) - d0 * d0) / (d1 * d1 - d0 * d0));
    return mix(aerialBoundary(c, b), aerialBoundary(c, b + 1), f);
}

// The sun's in-scattered radiance per unit of W for view direction v (from the camera):
// E_sun (sigma_R p_R + sigma_M p_M), as the light shafts' source.
vec3 aerialSource(vec3 v) {
    float cosTheta = dot(aerialParams.towardSun.xyz, v);
    return aerialParams.sunRayleigh.rgb * rayleighPhase(cosTheta) +
           aerialParams.sunMie.rgb * miePhase(aerialParams.extinction.w, cosTheta);
}

// The air between the camera and a surface point `toSurface` (world offset from the camera)
// at window position `fragCoord` of an image `size`, `viewDepth` metres deep: returns the
// in-scattered radiance, `transmittance` the air's (rgb, exact). W is read bilinearly across
// columns and linearly between boundaries; past the grid's far depth the air is lit (as the
// light shafts' is outside every cascade). No air: (0, 1).
vec3 aerialPerspectiveAt(vec2 fragCoord, vec2 size, float viewDepth, vec3 toSurface,
                         out vec3 transmittance) {
    transmittance = vec3(1.0);
    if (aerialParams.grid.w == 0u) return vec3(0.0);
    vec3 sigma = aerialParams.extinction.rgb;
    float distance = length(toSurface);
    transmittance = exp(-sigma * distance);
    uvec3 grid = aerialParams.grid.xyz;
    float far = aerialParams.range.x;
    float s = aerialSliceCoordinate(viewDepth, float(grid.z), far);
    vec2 p = fragCoord / size * vec2(grid.xy) - 0.5;
    uvec2 c0 = uvec2(clamp(floor(p), vec2(0.0), max(vec2(grid.xy) - 2.0, vec2(0.0))));
    uvec2 c1 = min(c0 + 1u, grid.xy - 1u);
    vec2 w = p - vec2(c0);
    vec3 W = mix(mix(aerialColumn(c0, s), aerialColumn(uvec2(c1.x, c0.y), s), w.x),
                 mix(aerialColumn(uvec2(c0.x, c1.y), s), aerialColumn(c1, s), w.x), w.y);
    W = max(W, vec3(0.0));
    if (viewDepth > far) {
        float tFar = distance * far / viewDepth;
        vec3 tail = (exp(-sigma * tFar) - transmittance) / max(sigma, vec3(1e-12));
        W += mix(tail, vec3(distance - tFar), lessThan(sigma, vec3(1e-9)));
    }
    return aerialSource(toSurface / max(distance, 1e-12)) * W;
}

// The same for a fragment at window position fragCoord.xy, depth fragCoord.z (reverse-Z),
// its world position reconstructed as the deferred passes do.
vec3 aerialPerspectiveAtFragment(vec4 fragCoord, out vec3 transmittance) {
    transmittance = vec3(1.0);
    if (aerialParams.grid.w == 0u) return vec3(0.0);
    vec2 size = vec2(camera.frameInfo.xy);
    vec2 ndc = fragCoord.xy / size * 2.0 - 1.0;
    vec4 world = camera.inverseViewProjection * vec4(ndc, fragCoord.z, 1.0);
    vec3 toSurface = world.xyz / world.w - camera.cameraPosition.xyz;
    float viewDepth = aerialParams.range.z / max(fragCoord.z, 1e-30);
    return aerialPerspectiveAt(fragCoord.xy, size, viewDepth, toSurface, transmittance);
}

// A surface's radiance seen from the camera through what lies in front of it: the fog's froxels
// (attenuated by them, their in-scattering added), then the atmosphere's air (aerial
// perspective), in the order the opaque frame gets them (the fog's composite and the sun's
// march over it, then the light shafts). For a fragment at window position fragCoord.xy and
// reverse-Z depth fragCoord.z; what blended surfaces, wires and hair share, so that at full
// coverage each shows what an opaque surface at its depth would. The sun's in-scattering comes
// from the grid's sun boundaries where the opaque frame marches it per pixel.
vec3 throughMediumAndAir(vec3 radiance, vec4 fragCoord) {
    vec4 medium = froxelsAt(fragCoord.xy, vec2(camera.frameInfo.xy),
                            froxelParams.range.x / max(fragCoord.z, 1e-30), true);
    radiance = radiance * medium.a + medium.rgb;
    vec3 airTransmittance;
    vec3 air = aerialPerspectiveAtFragment(fragCoord, airTransmittance);
    return radiance * airTransmittance + air;
}

#endif
