#version 460
#extension GL_GOOGLE_include_directive : require
#include "ibl_bindings.h"
// One mip of the environment cube from the mip above: a bilinear tap at the centre of each
// destination texel is the average of the 2x2 source texels it covers.
#include "common/ibl.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(binding = IBL_BINDING_SOURCE) uniform samplerCube source;  // a view of the mip above only
layout(binding = IBL_BINDING_DESTINATION, rgba16f) uniform writeonly image2DArray destination;

layout(push_constant) uniform Push {
    uint faceSize;  // of the destination
} push;

void main() {
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= push.faceSize || id.y >= push.faceSize) return;
    vec3 d = cubeFaceDirection(id.z, (vec2(id.xy) + 0.5) / float(push.faceSize));
    imageStore(destination, ivec3(id), vec4(textureLod(source, d, 0.0).rgb, 1.0));
}
