#version 460
layout(push_constant) uniform Push {
    vec4 radiance;
} push;
layout(location = 0) out vec4 outRadiance;

void main() {
    outRadiance = vec4(push.radiance.rgb, 1.0);
}
