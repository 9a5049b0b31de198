// The structure-of-arrays light buffer (render/src/lights/gpu_light_buffer.h): five vec4
// streams of `capacity` lights each. A shader that includes this declares LIGHT_BUFFER_BINDING.
#ifndef CANDELA_LIGHT_BUFFER_GLSL
#define CANDELA_LIGHT_BUFFER_GLSL

#include "common/lights.glsl"
#include "common/shared_bindings.h"

layout(std430, binding = LIGHT_BUFFER_BINDING) readonly buffer LightData { vec4 lightData[]; };

Light loadLight(uint index, uint capacity) {
    vec4 s0 = lightData[index];
    vec4 s1 = lightData[capacity + index];
    vec4 s2 = lightData[2u * capacity + index];
    vec4 s3 = lightData[3u * capacity + index];
    vec4 s4 = lightData[4u * capacity + index];
    Light light;
    light.position = s0.xyz;
    light.invAttenuationRadius = s0.w;
    light.intensity = s1.rgb;
    light.sourceRadius = s1.w;
    light.direction = s2.xyz;
    light.sourceLength = s2.w;
    light.tubeAxis = s3.xyz;
    light.type = uint(s3.w);
    light.spotScale = s4.x;
    light.spotOffset = s4.y;
    light.shape = s4.zw;
    return light;
}

// Only the type (stream 3's w): what a walk by light class tests.
uint loadLightType(uint index, uint capacity) {
    return uint(lightData[3u * capacity + index].w);
}

#endif
