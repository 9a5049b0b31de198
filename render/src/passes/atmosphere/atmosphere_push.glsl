// The push block every atmosphere shader reads (atmosphere_pass.cpp's AtmospherePush).
#include "common/atmosphere.glsl"

layout(push_constant) uniform AtmospherePushBlock {
    AtmosphereParameters atmosphere;
    vec4 sun;    // xyz: unit vector towards the sun (world, +Y up); w: the viewer's radius (km)
    uvec4 size;  // x, y: the written image's size; z: ray-marching samples; w: cube face size
} push;
