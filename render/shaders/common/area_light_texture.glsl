// Textured rect lights (issue 15): the emissive image, pre-filtered into a mip chain
// (render/src/lights/area_light_textures.h: one 256 x 256 tile per image, side by side, texels
// scaled to average luminance 1), read with the mip whose texels match the footprint of the lobe
// (Heitz et al. 2016, section 5.3): in LTC mode once per cell of the rect (area_lights.glsl), in
// representative mode at one point. Shaders that bind the atlas
// define AREA_LIGHT_TEXTURE_BINDING before including lights.glsl; elsewhere a textured rect
// shades as untextured (its average).
#ifndef CANDELA_AREA_LIGHT_TEXTURE_GLSL
#define CANDELA_AREA_LIGHT_TEXTURE_GLSL

const float kAreaLightTextureTile = 256.0;   // AreaLightTextures::kTileSize
const float kAreaLightTextureMaxLod = 8.0;   // AreaLightTextures::kMipLevels - 1

// The lobe's footprint on the light (its half-power diameter) spans this many texels of the mip
// read: the lobe's weight is concentrated inside that diameter, and a trilinear read already
// spreads over about two texels. 3 puts a floor 0.5 m off the centre of a 1.6 x 1 m red/blue rect
// 1.2 m above it at 1.8 times more of the nearer half's colour (the integral: 2.08; 1 texel: 1.0,
// the whole image averaged; 8: 16); the report's textured-rect rows measure it over a grid.
const float kAreaLightTextureTexelsPerFootprint = 3.0;
// The LTC specular lobe's image: two reads at the lobe's mean point over footprints of 0.46 and
// 1.90 times the plane's distance (in its cosine space), weighted 0.45 and 0.55, where the read
// above spans 2 of them over 3 texels. The lobe's weight on the light's plane is the clamped
// cosine's density there, h^2 / (pi (h^2 + r^2)^2) for a plane at distance h: peaked within h and
// heavy-tailed beyond it, so one box of any width either blurs the peak or misses the tail; a
// sharp and a wide read together stand for both. Fitted by a CPU model of this read on the
// report's grid (the atlas's aligned mip levels in closed form) over five images, steps of
// contrast 3 at 0.2, 0.35, 0.45, 1/2 and 0.62 of the side, so no image's edges are tuned to:
// worst specular cell 7.6 to 9.9 % (9.5 % and 12.0 % on steps at 0.28 and 0.71, not fitted),
// where one read over 1.5 texels of the footprint (the read before) gave 11.0 to 23.8 %
// (render/README.md, "Textured rect lights"). LTC now reads these only inside one of the rect's
// cells where the lobe is narrower than the cell (area_lights.glsl, areaLtcTexturedIntegral);
// the figures above are for the reads over the whole rect.
const float kAreaLightTextureSpecularNarrowFootprint = 0.46;  // x the plane's distance
const float kAreaLightTextureSpecularWideFootprint = 1.90;    // x the plane's distance
const float kAreaLightTextureSpecularNarrowWeight = 0.45;

// The mip for a lobe whose footprint on the light is `footprint` long, the light `size` across,
// read over `texelsPerFootprint` texels of it.
float areaLightTextureLod(float footprint, float size, float texelsPerFootprint) {
    float texels = footprint / (max(size, 1e-12) * texelsPerFootprint) * kAreaLightTextureTile;
    return clamp(log2(max(texels, 1.0)), 0.0, kAreaLightTextureMaxLod);
}
float areaLightTextureLod(float footprint, float size) {
    return areaLightTextureLod(footprint, size, kAreaLightTextureTexelsPerFootprint);
}

#if defined(AREA_LIGHT_TEXTURE_BINDING)
#define AREA_LIGHT_TEXTURED
layout(binding = AREA_LIGHT_TEXTURE_BINDING) uniform sampler2D areaLightTextures;

// One mip level of atlas slot `slot` (1 + tile) at `uv` ((0, 0) the rect's -X -Y corner, (1, 1)
// its +X +Y corner), bilinear, kept half a texel inside the tile so no other image bleeds in.
// The image reads as seen from the lit side (looking along the node's +Z): its top row along the
// +Y edge, its left column along the +X edge.
vec3 areaLightTextureLevel(uint slot, vec2 uv, float level, float tiles) {
    float margin = 0.5 / (kAreaLightTextureTile * exp2(-level));
    vec2 inTile = clamp(1.0 - uv, vec2(margin), vec2(1.0 - margin));
    vec2 atlasUv = vec2((float(slot - 1u) + inTile.x) / tiles, inTile.y);
    return textureLod(areaLightTextures, atlasUv, level).rgb;
}

// Trilinear by hand: each of the two levels with its own margin (one margin for both, the
// coarser's, pinned every read above mip 7 to the tile's centre).
vec3 areaLightTexture(uint slot, vec2 uv, float lod) {
    float tiles = float(textureSize(areaLightTextures, 0).x) / kAreaLightTextureTile;
    float fine = floor(lod);
    vec3 a = areaLightTextureLevel(slot, uv, fine, tiles);
    vec3 b = areaLightTextureLevel(slot, uv, min(fine + 1.0, kAreaLightTextureMaxLod), tiles);
    return mix(a, b, lod - fine);
}
#elif defined(AREA_LIGHT_TEXTURE_FUNCTION)
// The includer (the report's shaders) defines vec3 areaLightTexture(uint slot, vec2 uv,
// float lod) itself, with the same arguments.
#define AREA_LIGHT_TEXTURED
#endif

#endif
