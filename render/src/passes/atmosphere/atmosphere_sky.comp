#version 460
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_bindings.h"
// The sky behind the scene: every background pixel (reverse-Z depth 0) gets the sky-view
// table's radiance in its direction, plus the sun's disc (its radiance outside the atmosphere
// dimmed by the transmittance towards it) where the pixel looks at the sun and the ground
// does not hide it.
#include "atmosphere_push.glsl"
#include "common/camera.glsl"

layout(local_size_x = ATMOSPHERE_GROUP_SIZE, local_size_y = ATMOSPHERE_GROUP_SIZE) in;
layout(binding = ATMOSPHERE_BINDING_TRANSMITTANCE) uniform sampler2D transmittanceTable;
layout(binding = ATMOSPHERE_BINDING_SKY_VIEW) uniform sampler2D skyView;
layout(binding = ATMOSPHERE_BINDING_DEPTH) uniform sampler2D depthTexture;
layout(binding = ATMOSPHERE_BINDING_HDR, rgba32f) uniform image2D hdr;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    if (texelFetch(depthTexture, pixel, 0).r > 0.0) return;
    AtmosphereParameters a = push.atmosphere;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 nearPoint = camera.inverseViewProjection * vec4(ndc, 1.0, 1.0);
    vec3 view = safeNormalize(nearPoint.xyz / nearPoint.w - camera.cameraPosition.xyz);
    float r = push.sun.w;
    vec3 radiance = skyRadianceFromTable(skyView, a, r, view, push.sun.xyz);
    if (dot(view, push.sun.xyz) >= cos(a.radii.z) && !rayHitsGround(a, r, view.y)) {
        radiance += solarDiscRadiance(a) * transmittanceFromTable(transmittanceTable, a, r, view.y);
    }
    imageStore(hdr, pixel, vec4(radiance, 1.0));
}
