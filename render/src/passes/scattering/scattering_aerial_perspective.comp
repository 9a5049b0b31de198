#version 460
#extension GL_GOOGLE_include_directive : require
#include "scattering_bindings.h"
// The air in front of blended surfaces and wires (render/README.md "Aerial perspective";
// Hillaire 2020 section 5.4's camera-frustum volume): the opaque frame gets the air from the
// light shafts' per-pixel march (hdr T + L), but blended surfaces are drawn after it, each at
// its own depth. A coarse grid of view rays (columns x rows, push.aerial.xy) is marched once
// per frame through quadratic depth slices (push.aerial.z, view depth far (b / n)^2) in
// push.aerial.w steps per slice, each step lit or not by one lookup in the sun's cascades (as
// the brute-force reference's) and integrated exactly over the step when lit.
//
// Stored per boundary: W = integral of vis(t) exp(-sigma_t t) dt from the camera. The air is
// uniform, so the in-scattered radiance is W times the sun's source for the reader's own view
// direction (no phase function interpolated across columns) and the transmittance
// exp(-sigma_t distance) is exact: a blended pane with nothing shadowing the air in front gets
// exactly what the shafts give an opaque surface there.
#include "scattering_march.glsl"
#include "common/froxel_grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = SCATTERING_BINDING_AERIAL_PERSPECTIVE) buffer FroxelIntegrated {
    FroxelGrid froxelParams;  // the fog's: zeroed here when the frame has none (push.batch.y 0)
    AerialGrid aerialParams;
    vec4 froxelIntegrated[];  // the fog's boundaries, then the air's from push.batch.x
};

// View depth of boundary b: far (b / n)^2.
float boundaryDepth(uint b) {
    float x = float(b) / float(push.aerial.z);
    return push.sun.w * x * x;
}

void main() {
    uvec2 column = gl_GlobalInvocationID.xy;
    uvec3 grid = push.aerial.xyz;
    Light sun = sunLight();
    if (all(equal(column, uvec2(0u)))) {
        if (push.batch.y == 0u) froxelParams = FroxelGrid(uvec4(0u), vec4(0.0));
        aerialParams.grid = uvec4(grid, 1u);
        aerialParams.range = vec4(push.sun.w, float(push.batch.x), push.mie.w, 0.0);
        aerialParams.extinction = vec4(push.extinction.rgb, push.rayleigh.w);
        aerialParams.sunRayleigh = vec4(sun.intensity * push.rayleigh.rgb, 0.0);
        aerialParams.sunMie = vec4(sun.intensity * push.mie.rgb, 0.0);
        aerialParams.towardSun = vec4(-sun.direction, 0.0);
    }
    if (any(greaterThanEqual(column, grid.xy))) return;
    // The column's centre ray, without TAA's jitter (volumetric_view_ray.glsl says why).
    vec2 ndc = (vec2(column) + 0.5) / vec2(grid.xy) * 2.0 - 1.0;
    vec2 shift = 2.0 * camera.jitter.xy / vec2(camera.frameInfo.xy);
    vec4 nearPoint = camera.inverseViewProjection * vec4(ndc + shift, 1.0, 1.0);
    vec3 origin = camera.cameraPosition.xyz;
    vec3 offset = nearPoint.xyz / nearPoint.w - origin;
    float stretch = length(offset) / push.mie.w;  // metres along the ray per metre of depth
    vec3 direction = offset / length(offset);
    bool shadowed = kShadowsEnabled && push.lights.w != 0u;
    // Unit source: W is the source's multiplier (litRun(S, t0, t1) = S W(t0, t1)).
    const vec3 unit = vec3(1.0);
    vec3 W = vec3(0.0);
    uint base = push.batch.x;
    for (uint z = 0u; z < grid.z; ++z) {
        float t0 = boundaryDepth(z) * stretch;
        float t1 = boundaryDepth(z + 1u) * stretch;
        float dt = (t1 - t0) / float(push.aerial.w);
        for (uint i = 0u; i < push.aerial.w; ++i) {
            float a = t0 + float(i) * dt;
            if (!shadowed || sunLightsPoint(sun, origin + direction * (a + 0.5 * dt)))
                W += litRun(unit, a, a + dt);
        }
        froxelIntegrated[base + (z * grid.y + column.y) * grid.x + column.x] = vec4(W, 0.0);
    }
}
