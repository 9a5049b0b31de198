#version 460
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_bindings.h"
// The sky-view table (Hillaire 2020 section 5.3): the sky's radiance seen from the viewer's
// altitude, per (longitude from the sun, latitude), recomputed every frame (the sun and the
// viewer move). The sun's disc is not in it (the background adds it; image-based lighting
// leaves it to the directional light).
#include "atmosphere_push.glsl"
#include "atmosphere_scattering.glsl"

layout(local_size_x = ATMOSPHERE_GROUP_SIZE, local_size_y = ATMOSPHERE_GROUP_SIZE) in;
layout(binding = ATMOSPHERE_BINDING_TRANSMITTANCE) uniform sampler2D transmittanceTable;
layout(binding = ATMOSPHERE_BINDING_MULTIPLE_SCATTERING) uniform sampler2D multipleTable;
layout(binding = ATMOSPHERE_BINDING_DESTINATION, rgba16f) uniform writeonly image2D table;

void main() {
    uvec2 id = gl_GlobalInvocationID.xy;
    if (id.x >= push.size.x || id.y >= push.size.y) return;
    AtmosphereParameters a = push.atmosphere;
    vec2 size = vec2(push.size.xy);
    float r = push.sun.w;
    float viewZenith, sunLongitude;
    skyViewAngles(a, r, (vec2(id) + 0.5) / size, size, viewZenith, sunLongitude);
    // A frame where the sun lies in the x-y plane at +x: longitude is measured from it.
    float muSun = push.sun.y;
    vec3 towardSun = vec3(sqrt(max(1.0 - muSun * muSun, 0.0)), muSun, 0.0);
    vec3 view = vec3(sin(viewZenith) * cos(sunLongitude), cos(viewZenith),
                     sin(viewZenith) * sin(sunLongitude));
    ScatteringResult result =
        integrateScattering(a, transmittanceTable, multipleTable, true, vec3(0.0, r, 0.0), view,
                            towardSun, solarIlluminance(a), int(push.size.z), true);
    imageStore(table, ivec2(id), vec4(result.radiance, 1.0));
}
