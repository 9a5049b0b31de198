#version 460
#extension GL_GOOGLE_include_directive : require
#include "atmosphere_bindings.h"
// The sky as an environment cube's first mip (for image-based lighting: the IBL chain then
// filters it as it filters an EXR sky), read from the sky-view table; no sun disc (the sun
// lights the scene as its directional light). Radiance is clamped to fp16's range.
#include "atmosphere_push.glsl"
#include "common/ibl.glsl"

layout(local_size_x = ATMOSPHERE_GROUP_SIZE, local_size_y = ATMOSPHERE_GROUP_SIZE) in;
layout(binding = ATMOSPHERE_BINDING_SKY_VIEW) uniform sampler2D skyView;
layout(binding = ATMOSPHERE_BINDING_DESTINATION, rgba16f) uniform writeonly image2DArray cube;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uint face = push.size.w;
    if (id.x >= face || id.y >= face) return;
    vec3 view = cubeFaceDirection(id.z, (vec2(id.xy) + 0.5) / float(face));
    vec3 radiance =
        skyRadianceFromTable(skyView, push.atmosphere, push.sun.w, normalize(view), push.sun.xyz);
    imageStore(cube, ivec3(id), vec4(min(radiance, vec3(65000.0)), 1.0));
}
