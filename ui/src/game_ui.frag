#version 450
// Glyph coverage (or the atlas's covered corner, for fills) scales the colour's alpha; the
// target holds display-encoded values, blended as such.
layout(set = 0, binding = 0) uniform sampler2D glyphAtlas;

layout(location = 0) in vec2 inUv;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(inColor.rgb, inColor.a * texture(glyphAtlas, inUv).r);
}
