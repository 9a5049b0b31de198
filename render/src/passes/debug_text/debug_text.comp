#version 460
#extension GL_GOOGLE_include_directive : require
#include "debug_text_bindings.h"
// Screen-space debug text over the tonemapped image: one invocation per texel of a glyph's
// cell plus a one-texel border, one z slice per glyph. Inked texels take the glyph's colour,
// border texels next to ink turn black (an outline that reads on any background). Cells of
// neighbouring glyphs overlap only in border texels, which are black either way, so the
// result does not depend on invocation order.

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = DEBUG_TEXT_BINDING_LDR, rgba8) uniform writeonly image2D ldr;

struct Glyph {
    ivec2 origin;  // top-left pixel of the glyph's 5x7 ink
    uint index;    // into font (two words per glyph, see bitmap_font.h)
    uint scale;    // pixels per texel
    vec4 color;    // display values
};

layout(std430, binding = DEBUG_TEXT_BINDING_TEXT) readonly buffer Text {
    uint font[128];  // kFontWords in bitmap_font.h
    Glyph glyphs[];
};

layout(push_constant) uniform Push {
    uint glyphCount;
} push;

bool inked(uint index, int column, int row) {
    if (column < 0 || column >= 5 || row < 0 || row >= 7) return false;
    uint bits = (font[index * 2u + uint(row / 4)] >> (8u * uint(row % 4))) & 0xffu;
    return ((bits >> uint(4 - column)) & 1u) != 0u;
}

void main() {
    uint g = gl_GlobalInvocationID.z;
    if (g >= push.glyphCount) return;
    Glyph glyph = glyphs[g];
    int s = int(glyph.scale);
    ivec2 local = ivec2(gl_GlobalInvocationID.xy);  // in the cell with its border
    if (local.x >= 7 * s || local.y >= 9 * s) return;
    int column = local.x / s - 1;
    int row = local.y / s - 1;
    ivec2 pixel = glyph.origin - ivec2(s) + local;
    if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, imageSize(ldr)))) return;
    if (inked(glyph.index, column, row)) {
        imageStore(ldr, pixel, vec4(glyph.color.rgb, 1.0));
        return;
    }
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            if (inked(glyph.index, column + dx, row + dy)) {
                imageStore(ldr, pixel, vec4(0.0, 0.0, 0.0, 1.0));
                return;
            }
        }
    }
}
