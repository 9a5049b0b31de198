#version 450
// ImGui blends in display-encoded space: the target holds sRGB-encoded values in a UNORM
// format (the tonemap pass encodes), so colours and alpha go through unchanged.
layout(set = 0, binding = 0) uniform sampler2D fontAtlas;

layout(location = 0) in vec2 inUv;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = inColor * texture(fontAtlas, inUv);
}
