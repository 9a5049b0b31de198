// Textured rect lights (issue 15): the emissive image, pre-filtered into a mip chain
// (render/src/lights/area_light_textures.h: one 256 x 256 tile per image, side by side, texels
// scaled to average luminance 1), read at one point of the rect with the mip whose texels match
// the footprint of the lobe there (Heitz et al. 2016, section 5.3). Shaders that bind the atlas
// define AREA_LIGHT_TEXTURE_BINDING before including lights.glsl; elsewhere a textured rect
// shades as untextured (its average).
#ifndef CANDELA_AREA_LIGHT_TEXTURE_GLSL
#define CANDELA_AREA_LIGHT_TEXTURE_GLSL

const float kAreaLightTextureTile = 256.0;   // AreaLightTextures::kTileSize
const float kAreaLightTextureMaxLod = 8.0;   // AreaLightTextures::kMipLevels - 1

// The lobe's footprint on the light (its half-power diameter) spans this many texels of the mip
// read: the lobe's weight is concentrated well inside that diameter, and a trilinear read already
// spreads over about two texels. Chosen from the report's textured-rect rows (a footprint of one
// texel averaged the whole image for a floor 1.2 m under a 1.6 m rect; Heitz et al.'s
// log3(2048 d) is as sharp).
const float kAreaLightTextureTexelsPerFootprint = 8.0;

// The mip for a lobe whose footprint on the light is `footprint` long, the light `size` across.
float areaLightTextureLod(float footprint, float size) {
    float texels = footprint / (max(size, 1e-12) * kAreaLightTextureTexelsPerFootprint) *
                   kAreaLightTextureTile;
    return clamp(log2(max(texels, 1.0)), 0.0, kAreaLightTextureMaxLod);
}

#if defined(AREA_LIGHT_TEXTURE_BINDING)
#define AREA_LIGHT_TEXTURED
layout(binding = AREA_LIGHT_TEXTURE_BINDING) uniform sampler2D areaLightTextures;

// The image of atlas slot `slot` (1 + tile) at `uv` ((0, 0) the rect's -X -Y corner, (1, 1)
// its +X +Y corner) filtered to mip `lod`. The image reads as seen from the lit side (looking
// along the node's +Z): its top row along the +Y edge, its left column along the +X edge. The
// filter stays inside the tile at the coarser of the two mips read, so no other image bleeds in.
vec3 areaLightTexture(uint slot, vec2 uv, float lod) {
    float tiles = float(textureSize(areaLightTextures, 0).x) / kAreaLightTextureTile;
    float margin = 0.5 / (kAreaLightTextureTile * exp2(-ceil(lod)));
    vec2 inTile = clamp(1.0 - uv, vec2(margin), vec2(1.0 - margin));
    vec2 atlasUv = vec2((float(slot - 1u) + inTile.x) / tiles, inTile.y);
    return textureLod(areaLightTextures, atlasUv, lod).rgb;
}
#elif defined(AREA_LIGHT_TEXTURE_FUNCTION)
// The includer (the report's shaders) defines vec3 areaLightTexture(uint slot, vec2 uv,
// float lod) itself, with the same arguments.
#define AREA_LIGHT_TEXTURED
#endif

#endif
