#version 450
// The atlas texel (white with a glyph's coverage as alpha, an image's own colour, or the white
// corner for fills) times the vertex colour; the target holds display-encoded values, blended
// as such.
layout(set = 0, binding = 0) uniform sampler2D atlas;

layout(location = 0) in vec2 inUv;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = inColor * texture(atlas, inUv);
}
