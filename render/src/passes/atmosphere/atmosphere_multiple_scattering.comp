#version 460
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_bindings.h"
// The multiple-scattering table (Hillaire 2020 section 5.5): per texel (altitude, sun zenith
// cosine), the second-order light L_2nd (eq. 5-6, a unit sun) and the transfer f_ms (eq. 7)
// averaged over 64 directions of the sphere with an isotropic phase, then the infinite series
// of higher orders Psi_ms = L_2nd / (1 - f_ms) (eq. 9).
#include "atmosphere_push.glsl"
#include "atmosphere_scattering.glsl"

layout(local_size_x = ATMOSPHERE_GROUP_SIZE, local_size_y = ATMOSPHERE_GROUP_SIZE) in;
layout(binding = ATMOSPHERE_BINDING_TRANSMITTANCE) uniform sampler2D transmittanceTable;
layout(binding = ATMOSPHERE_BINDING_DESTINATION, rgba16f) uniform writeonly image2D table;

const int kDirections = 64;

void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    if (id.x >= push.size.x || id.y >= push.size.y) return;
    AtmosphereParameters a = push.atmosphere;
    vec2 uv = vec2(texelCentreToUnit((float(id.x) + 0.5) / float(push.size.x), float(push.size.x)),
                   texelCentreToUnit((float(id.y) + 0.5) / float(push.size.y), float(push.size.y)));
    float muSun = clamp(uv.x * 2.0 - 1.0, -1.0, 1.0);
    // Just inside the shell at both ends, so every ray starts in the air.
    float r = mix(atmosphereBottom(a) + 0.01, atmosphereTop(a) - 0.01, saturate(uv.y));
    vec3 origin = vec3(0.0, r, 0.0);
    vec3 towardSun = vec3(sqrt(max(1.0 - muSun * muSun, 0.0)), muSun, 0.0);
    vec3 secondOrder = vec3(0.0), transfer = vec3(0.0);
    for (int i = 0; i < kDirections; ++i) {
        // A Fibonacci sphere: 64 nearly even directions.
        float z = 1.0 - (2.0 * float(i) + 1.0) / float(kDirections);
        float phi = float(i) * 2.39996323;
        float s = sqrt(max(1.0 - z * z, 0.0));
        vec3 view = vec3(s * cos(phi), z, s * sin(phi));
        ScatteringResult result =
            integrateScattering(a, transmittanceTable, transmittanceTable, false, origin, view,
                                towardSun, vec3(1.0), int(push.size.z), true);
        secondOrder += result.radiance;
        transfer += result.multipleAsOne;
    }
    // Mean over the sphere = integral x isotropic phase (1 / 4 pi) of eq. 5 and 7.
    secondOrder /= float(kDirections);
    transfer /= float(kDirections);
    vec3 psi = secondOrder / max(vec3(1.0) - transfer, vec3(1e-4));
    imageStore(table, ivec2(id), vec4(psi, 1.0));
}
