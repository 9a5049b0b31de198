// The report's textured rect images (area_light_shapes_rows.cpp), standing in for the renderer's
// atlas (common/area_light_texture.glsl) where a compute harness binds only buffers. Slot 1: four
// quadrants of luminance (u < 1/2 ? 1.5 : 0.5) x (v < 1/2 ? 1.5 : 0.5); slot 2: the same steps
// (contrast 3, average 1) at 0.35 instead of 1/2, so no mip level's texel edges fall on them. In
// the rect's (u, v) ((0, 0) its -X -Y corner).
// Read as the atlas reads it, in closed form: mip `level` of a 256-texel tile is 256 / 2^level
// texels, each the image's mean over its cell (the 2 x 2 box chain of
// lights/area_light_textures.h), sampled bilinearly with uv kept half a texel inside the tile,
// the two levels around `lod` mixed (trilinear by hand). A box centred on uv instead (the mean
// over [uv - w/2, uv + w/2], the image continued past its edges) was the stand-in before: the
// renderer's coarse levels are aligned cells, not a box that follows uv, and a read tuned on the
// box lost to the one it replaced on the atlas (render/README.md, issue 15).
#ifndef CANDELA_REPORT_LIGHT_TEXTURE_GLSL
#define CANDELA_REPORT_LIGHT_TEXTURE_GLSL

#define AREA_LIGHT_TEXTURE_FUNCTION

const float kReportTextureTile = 256.0;  // AreaLightTextures::kTileSize

// Where slot's steps fall along each axis.
float reportTextureCut(uint slot) {
    return slot == 2u ? 0.35 : 0.5;
}

// The step (3 lo below `cut`, lo above, average 1) averaged over [a, b].
float reportStepMean(float a, float b, float cut) {
    float lo = 1.0 / (1.0 + 2.0 * cut);
    float below = clamp((cut - a) / (b - a), 0.0, 1.0);  // share of the cell under the cut
    return lo * (1.0 + 2.0 * below);
}

// One axis of mip `level`, bilinear between the two nearest texel centres.
float reportStepLevel(float s, float level, float cut) {
    float texels = kReportTextureTile * exp2(-level);
    float width = 1.0 / texels;
    float x = clamp(s, 0.5 * width, 1.0 - 0.5 * width) * texels - 0.5;
    float i0 = floor(x);
    float i1 = min(i0 + 1.0, texels - 1.0);
    float a = reportStepMean(i0 * width, (i0 + 1.0) * width, cut);
    float b = reportStepMean(i1 * width, (i1 + 1.0) * width, cut);
    return mix(a, b, x - i0);
}

vec3 areaLightTexture(uint slot, vec2 uv, float lod) {
    float cut = reportTextureCut(slot);
    float fine = floor(lod);
    float coarse = min(fine + 1.0, 8.0);
    float a = reportStepLevel(uv.x, fine, cut) * reportStepLevel(uv.y, fine, cut);
    float b = reportStepLevel(uv.x, coarse, cut) * reportStepLevel(uv.y, coarse, cut);
    return vec3(mix(a, b, lod - fine));
}

#endif
