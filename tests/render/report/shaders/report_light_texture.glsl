// The report's textured rect image (area_light_shapes_rows.cpp), standing in for the renderer's
// atlas (common/area_light_texture.glsl) where a compute harness binds only buffers: four
// quadrants of luminance (u < 1/2 ? 1.5 : 0.5) x (v < 1/2 ? 1.5 : 0.5), average 1, in the
// rect's (u, v) ((0, 0) its -X -Y corner). Mip `lod` is the pattern box-filtered over one of its
// texels, 2^lod / 256 of the side (the atlas's 256-texel tiles), in closed form: the mean of
// the step over the box.
#ifndef CANDELA_REPORT_LIGHT_TEXTURE_GLSL
#define CANDELA_REPORT_LIGHT_TEXTURE_GLSL

#define AREA_LIGHT_TEXTURE_FUNCTION

// (s < 1/2 ? 1.5 : 0.5) averaged over [s - w/2, s + w/2].
float reportStepFiltered(float s, float width) {
    float below = clamp((0.5 - s) / width + 0.5, 0.0, 1.0);  // share of the box under 1/2
    return 0.5 + below;
}

vec3 areaLightTexture(uint slot, vec2 uv, float lod) {
    float width = exp2(lod) / 256.0;
    return vec3(reportStepFiltered(uv.x, width) * reportStepFiltered(uv.y, width));
}

#endif
