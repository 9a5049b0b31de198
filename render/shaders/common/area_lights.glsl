// Rect and disk lights (issue 15): one-sided Lambertian emitters facing the node's -Z
// (Light.direction), luminance L = lumens / (pi area) in Light.intensity. Included by
// lights.glsl after `struct Light`; evaluateAreaLight is evaluateLight's case for both types.
//  - Diffuse, "ltc" mode: the exact form factor with M^-1 = identity: Lambert's edge sum over
//    a rect clipped to the horizon (ltc.glsl), Heitz and Hill's ellipse for a disk
//    (ltc_disk.glsl).
//  - "representative" mode (Drobot 2014, GPU Pro 5, "Physically Based Area Lights"):
//    area_light_representative.glsl.
//  - A textured rect in "ltc" mode: both lobes over the image's cells (areaLtcTexturedIntegral).
//  - Specular, "ltc" mode: the fitted LTC (lights/ltc_table_texture.h) over the same shape,
//    in shaders that bind the table (they define AREA_LIGHT_LTC_MATRIX_BINDING and
//    AREA_LIGHT_LTC_MAGNITUDE_BINDING before including lights.glsl: the lighting and forward
//    passes); elsewhere, and in "representative" mode, Drobot's specular cone.
// The falloff window is measured to the light's centre, so its culling bound (the falloff
// sphere cut by the half-space in front) never changes the image.
#ifndef CANDELA_AREA_LIGHTS_GLSL
#define CANDELA_AREA_LIGHTS_GLSL

#include "common/area_light_constant_intensity.glsl"
#include "common/area_light_representative.glsl"
#include "common/area_light_texture.glsl"
#include "common/ltc.glsl"
#include "common/ltc_area_lights.glsl"
#include "common/ltc_tube.glsl"
#include "common/ltc_disk.glsl"

// Per-light `quality` (Light.spotOffset of area lights, gpu_light.cpp, its low two bits): 0 the
// renderer's default, 1 representative, 2 ltc; plus kAreaEmissionConstantIntensity for a
// constant-intensity emitter.
const uint kAreaQualityDefault = 0u;
const uint kAreaQualityRepresentative = 1u;
const uint kAreaQualityLtc = 2u;
const uint kAreaEmissionConstantIntensity = 4u;

AreaShape areaShapeOf(Light light) {
    AreaShape s;
    s.center = light.position;
    s.normal = light.direction;
    s.axisX = light.tubeAxis;
    s.axisY = cross(light.tubeAxis, light.direction);  // node +Y = +Z x +X, +Z = -direction
    s.isDisk = light.type == LIGHT_TYPE_DISK;
    s.halfSize = s.isDisk ? vec2(light.shape.x) : 0.5 * light.shape;
    return s;
}

// The rect's corners relative to P in the frame `toLocal`, wound so the lit side sees them
// clockwise (ltc.glsl): counter-clockwise about the node's +Z.
void rectPolygon(AreaShape s, vec3 P, mat3 toLocal, out vec3 polygon[4]) {
    vec2 h = s.halfSize;
    polygon[0] = toLocal * (areaPlanePoint(s, vec2(-h.x, -h.y)) - P);
    polygon[1] = toLocal * (areaPlanePoint(s, vec2(h.x, -h.y)) - P);
    polygon[2] = toLocal * (areaPlanePoint(s, vec2(h.x, h.y)) - P);
    polygon[3] = toLocal * (areaPlanePoint(s, vec2(-h.x, h.y)) - P);
}

// The cosine lobe moved by M (given M^-1) integrated over the shape, in the frame `toLocal`
// (+z the normal): Lambert's edge sum for a rect, Heitz and Hill's ellipse for a disk.
float areaShapeIntegral(AreaShape s, vec3 P, mat3 toLocal, mat3 minv) {
    if (s.isDisk) {
        // ltcDiskIntegral emits towards cross(axisU, axisV): Y x X is the emitting normal.
        return ltcDiskIntegral(minv, toLocal * (s.center - P), toLocal * (s.axisY * s.halfSize.x),
                               toLocal * (s.axisX * s.halfSize.x));
    }
    vec3 polygon[4];
    rectPolygon(s, P, toLocal, polygon);
    return ltcPolygonIntegral(minv, polygon, 4);
}

// A textured rect's atlas slot (Light.spotScale = 1 + slot, gpu_light.cpp); 0: untextured, and
// always 0 where the shader binds no atlas.
uint areaTextureSlot(Light light) {
#ifdef AREA_LIGHT_TEXTURED
    if (!areaPathTaken(AREA_PATH_TEXTURED)) return 0u;
    return light.type == LIGHT_TYPE_RECT ? uint(max(light.spotScale, 1.0) + 0.5) - 1u : 0u;
#else
    return 0u;
#endif
}

// A textured rect by LTC: the lobe's integral over the image, split along the atlas's own
// texels. The rect is cut into cells x cells cells (kAreaLightTexture*Cells), each one texel
// of the mip level 256 / cells texels across (aligned: lights/area_light_textures.h's 2 x 2
// box chain), so that texel is the image's exact mean over the cell. Each cell's share of the
// lobe is its own exact polygon integral (the same closed form as the untextured rect: the cell
// moved by M^-1, clipped, Lambert's edge sum; Heitz et al. 2016), so only the image's
// variation inside a cell against the lobe's variation there is approximated:
//  - a lobe wider than half a cell (its reads at or above the cell's children's level): the
//    lobe taken as linear over the cell, its mean point (the cell's vector form factor meets
//    the plane there) off the cell's centre by c gives the cell's four children weights
//    1/2 +- 3c/2 per axis, one bilinear read of the children's level at centre + 0.75 c;
//  - a narrower one: the read of one point (area_light_texture.glsl's two reads for specular,
//    one for diffuse) at its mean point in the cell, kept inside the cell.
// Cells per side against the error (candela-report --section "area light shapes", worst cell on
// steps at 0.35 where no cell edge falls on the image's): specular 4: 5.4 %, 8: 1.9 % (the fit's
// own error 1.0 %), against 8.8 % for the one-point reads over the whole rect; diffuse 4: 0.4 %,
// 8: 0.0 %, against 2.6 % (7.3 % on quadrants): the cosine is wide, half the specular's cells
// are enough for it. Each cell is a polygon integral, so the cells are most of a textured
// rect's cost: the quality presets choose them (RendererOptions::areaTextureCells; 8 at ultra).
// render/README.md.
layout(constant_id = SPEC_AREA_TEXTURE_CELLS) const int kAreaLightTextureSpecularCells = 8;
const int kAreaLightTextureDiffuseCells =
    kAreaLightTextureSpecularCells > 1 ? kAreaLightTextureSpecularCells / 2 : 1;

#ifdef AREA_LIGHT_TEXTURED
// One read of a cell (its -X -Y corner at `cellMin`, one texel of mip `cellLevel`) for a lobe
// whose mean point in the cell is `uv` and whose read wants mip `lod`.
vec3 areaLightTextureCellRead(uint slot, vec2 uv, vec2 cellMin, float cellLevel, float lod) {
    float cell = exp2(cellLevel) / kAreaLightTextureTile;
    if (lod < cellLevel - 1.0) {
        // Half a texel of the read's coarser level in from the cell's edges: no texel of another
        // cell enters (the levels below the cell's are aligned to it).
        float inset = exp2(floor(lod) + 1.0) / (2.0 * kAreaLightTextureTile);
        return areaLightTexture(slot, clamp(uv, cellMin + inset, cellMin + cell - inset), lod);
    }
    vec2 centre = cellMin + 0.5 * cell;
    vec2 offset = clamp(0.75 * (uv - centre), vec2(-0.25 * cell), vec2(0.25 * cell));
    return areaLightTexture(slot, centre + offset, cellLevel - 1.0);
}
#endif

// The lobe (the cosine moved by M, given M^-1) over a textured rect's `polygon` (rectPolygon):
// its integral in `integral`, the image it sees (the integral-weighted mean of its cells) as the
// result. `specular`: the specular lobe's two reads in a narrow lobe's cell.
vec3 areaLtcTexturedIntegral(uint slot, vec3 polygon[4], mat3 minv, bool specular,
                             out float integral) {
    integral = 0.0;
    vec3 p0 = minv * polygon[0];
    vec3 e1 = minv * polygon[1] - p0;  // along the rect's +X (u)
    vec3 e2 = minv * polygon[3] - p0;  // along its +Y (v)
#ifdef AREA_LIGHT_TEXTURED
    vec3 n = cross(e1, e2);
    float area = length(n);
    float offset = dot(n, p0);  // area x the moved plane's distance
    float e11 = dot(e1, e1), e12 = dot(e1, e2), e22 = dot(e2, e2);
    float det = max(e11 * e22 - e12 * e12, 1e-30);
    // The lobe's footprints as area_light_texture.glsl reads them, in the moved rect's units.
    float distance = abs(offset) / max(area, 1e-30);
    float size = sqrt(area);
    float narrowLod =
        areaLightTextureLod(kAreaLightTextureSpecularNarrowFootprint * distance, size, 1.0);
    float wideLod =
        areaLightTextureLod(kAreaLightTextureSpecularWideFootprint * distance, size, 1.0);
    float diffuseLod = areaLightTextureLod(2.0 * distance, size);
    int count = specular ? kAreaLightTextureSpecularCells : kAreaLightTextureDiffuseCells;
    float cells = float(count);
    float cellLevel = log2(kAreaLightTextureTile / cells);
    vec3 weighted = vec3(0.0);
    for (int j = 0; j < count; ++j) {
        for (int i = 0; i < count; ++i) {
            vec2 lo = vec2(i, j) / cells, hi = vec2(i + 1, j + 1) / cells;
            vec3 corners[4];  // wound as rectPolygon's
            corners[0] = p0 + lo.x * e1 + lo.y * e2;
            corners[1] = p0 + hi.x * e1 + lo.y * e2;
            corners[2] = p0 + hi.x * e1 + hi.y * e2;
            corners[3] = p0 + lo.x * e1 + hi.y * e2;
            vec3 sum = ltcMovedPolygonVectorSum(corners, 4);
            float share = max(sum.z * (0.5 / PI), 0.0);
            if (share <= 0.0) continue;  // below the horizon or seen from behind
            // Where the cell's mean direction meets the moved plane, in the rect's (u, v) (M^-1
            // is linear: affine coordinates carry over).
            float approach = dot(n, sum);
            vec3 hit = abs(approach) > 1e-12 * area * length(sum) ? sum * (offset / approach)
                                                                  : corners[0];
            vec3 d = hit - p0;
            vec2 uv = vec2(e22 * dot(d, e1) - e12 * dot(d, e2),
                           e11 * dot(d, e2) - e12 * dot(d, e1)) /
                      det;
            uv = clamp(uv, lo, hi);
            vec3 value;
            if (specular) {
                value = mix(areaLightTextureCellRead(slot, uv, lo, cellLevel, wideLod),
                            areaLightTextureCellRead(slot, uv, lo, cellLevel, narrowLod),
                            kAreaLightTextureSpecularNarrowWeight);
            } else {
                value = areaLightTextureCellRead(slot, uv, lo, cellLevel, diffuseLod);
            }
            weighted += share * value;
            integral += share;
        }
    }
    return weighted / max(integral, 1e-30);
#else
    vec3 moved[4] = vec3[4](p0, p0 + e1, p0 + e1 + e2, p0 + e2);
    integral = max(ltcMovedPolygonVectorSum(moved, 4).z * (0.5 / PI), 0.0);
    return vec3(1.0);
#endif
}

// areaShapeIntegral, and in `texel` what a textured rect (slot > 0) shows the lobe (1 for an
// untextured shape): the integral-weighted mean of its cells (areaLtcTexturedIntegral), whose
// integrals sum to the rect's. `specular`: the specular lobe's reads.
float areaShapeIntegral(AreaShape s, vec3 P, mat3 toLocal, mat3 minv, uint slot, bool specular,
                        out vec3 texel) {
    texel = vec3(1.0);
    if (s.isDisk || slot == 0u) return areaShapeIntegral(s, P, toLocal, minv);
    vec3 polygon[4];
    rectPolygon(s, P, toLocal, polygon);
    float integral;
    texel = areaLtcTexturedIntegral(slot, polygon, minv, specular, integral);
    return integral;
}

// The image at plane coordinates q of a textured rect, filtered over `footprint` metres.
vec3 areaPlaneTexture(AreaShape s, uint slot, vec2 q, float footprint) {
#ifdef AREA_LIGHT_TEXTURED
    if (slot == 0u) return vec3(1.0);
    vec2 uv = clamp(q / max(2.0 * s.halfSize, vec2(1e-12)) + 0.5, vec2(0.0), vec2(1.0));
    return areaLightTexture(slot, uv, areaLightTextureLod(footprint, sqrt(areaShapeArea(s))));
#else
    return vec3(1.0);
#endif
}

// Exact irradiance per unit luminance (pi x the form factor) at P with normal N.
float areaExactDiffuse(AreaShape s, vec3 P, vec3 N) {
    if (dot(P - s.center, s.normal) <= 0.0) return 0.0;  // behind: one-sided
    return PI * areaShapeIntegral(s, P, transpose(tangentFrame(N)), mat3(1.0));
}

// The fitted lobe's integral over the shape, given the table's M^-1 at this roughness and
// view (rows (00, 0, 02), (0, 1, 0), (20, 0, 22) in the frame of N and V's tangent part).
float areaLtcSpecularIntegral(AreaShape s, vec3 P, vec3 N, vec3 V, mat3 minv) {
    if (dot(P - s.center, s.normal) <= 0.0) return 0.0;  // behind: one-sided
    return areaShapeIntegral(s, P, ltcShadingFrame(N, V), minv);
}

#ifdef AREA_LIGHT_LTC_MATRIX_BINDING
layout(binding = AREA_LIGHT_LTC_MATRIX_BINDING) uniform sampler2D ltcMatrixTable;
layout(binding = AREA_LIGHT_LTC_MAGNITUDE_BINDING) uniform sampler2D ltcMagnitudeTable;

// The table's axes (render/ltc/ltc_fit.h): rows roughness 0.02 (brdf.glsl's kMinRoughness) to
// 1, columns cos theta_v = 1 - t^2; texel centres at the fitted cells.
vec2 ltcTableUv(float roughness, float cosView) {
    const float kTableSize = 64.0;
    const float kTableMinRoughness = 0.02;
    float row = (clamp(roughness, kTableMinRoughness, 1.0) - kTableMinRoughness) /
                (1.0 - kTableMinRoughness);
    float column = sqrt(saturate(1.0 - cosView));
    return (vec2(column, row) * (kTableSize - 1.0) + 0.5) / kTableSize;
}

// The specular lobe's integral over the shape by its fitted LTC, per unit luminance, before
// Fresnel: specular = (F0 (n - f) + F90 f) x the result, (n, f) in magnitudeFresnel.
float areaLtcSpecular(AreaShape s, vec3 P, vec3 N, vec3 V, float roughness,
                      out vec2 magnitudeFresnel) {
    vec2 uv = ltcTableUv(roughness, saturate(dot(N, V)));
    magnitudeFresnel = texture(ltcMagnitudeTable, uv).xy;
    return areaLtcSpecularIntegral(s, P, N, V, ltcInverseMatrix(texture(ltcMatrixTable, uv)));
}
#endif

// Representative mode's texture reads (Drobot 2014 gives none; the image at the sample
// point, pre-filtered over the lobe's footprint on the rect): diffuse at the sample along L,
// over twice the height (the cosine's footprint, as in the LTC read); specular at the centre of
// the cone's intersection (along L), over the cone's footprint there (2 t tan alpha).
vec3 areaRepresentativeDiffuseTexture(AreaShape s, uint slot, vec3 P, vec3 L) {
    if (slot == 0u) return vec3(1.0);
    bool hit;
    float t;
    vec2 q = areaPlaneHit(s, P, L, areaPlaneCoords(s, P), hit, t);
    return areaPlaneTexture(s, slot, q, 2.0 * dot(P - s.center, s.normal));
}
vec3 areaRepresentativeSpecularTexture(AreaShape s, uint slot, vec3 P, vec3 L, float alpha) {
    if (slot == 0u) return vec3(1.0);
    bool hit;
    float t;
    vec2 q = areaPlaneHit(s, P, L, areaPlaneCoords(s, P), hit, t);
    return areaPlaneTexture(s, slot, q, 2.0 * t * tan(min(alpha, 1.5)));
}

// `constantIntensity`: Light.intensity is I_A, and each lobe's constant-luminance result is
// scaled by Drobot's pre-integrated factor (area_light_constant_intensity.glsl), in either mode.
LightIncidence evaluateAreaLight(Light light, vec3 P, vec3 N, vec3 R, float alpha,
                                 bool representative, bool constantIntensity) {
    AreaShape s = areaShapeOf(light);
    vec3 toCenter = s.center - P;
    float window = attenuationWindow(dot(toCenter, toCenter), light.invAttenuationRadius);
    vec3 luminance = light.intensity * window;
    uint slot = areaTextureSlot(light);
    // A textured rect's image as each lobe sees it (1 untextured): by LTC over the image's cells
    // (areaLtcTexturedIntegral); in representative mode at the sample point, over the
    // footprint of the cosine (twice the height) or of Drobot's specular cone.
    vec3 diffuseTexel = vec3(1.0);
    vec3 specularTexel = vec3(1.0);
    float height = dot(-toCenter, s.normal);

    LightIncidence o;
    vec3 representativeL;
    float representativeDiffuse = areaRepresentativeDiffuse(s, P, N, false, representativeL);
    o.diffuseL = representativeL;
    float diffuse;
    if (representative) {
        diffuse = representativeDiffuse;
        diffuseTexel = areaRepresentativeDiffuseTexture(s, slot, P, representativeL);
    } else {
        diffuse = height <= 0.0 ? 0.0
                                : PI * areaShapeIntegral(s, P, transpose(tangentFrame(N)),
                                                         mat3(1.0), slot, false, diffuseTexel);
    }
    o.specularLtc = vec2(0.0);
    float specular;
#ifdef AREA_LIGHT_LTC_MATRIX_BINDING
    if (!representative) {
        vec3 V = 2.0 * dot(N, R) * N - R;  // R = reflect(-V, N)
        if (slot == 0u) {
            specular = areaLtcSpecular(s, P, N, V, sqrt(alpha), o.specularLtc);
        } else {
            vec2 uv = ltcTableUv(sqrt(alpha), saturate(dot(N, V)));
            o.specularLtc = texture(ltcMagnitudeTable, uv).xy;
            specular = height <= 0.0 ? 0.0
                                     : areaShapeIntegral(s, P, ltcShadingFrame(N, V),
                                                         ltcInverseMatrix(texture(ltcMatrixTable, uv)),
                                                         slot, true, specularTexel);
        }
        o.specularL = R;
    } else
#endif
    {
        specular = areaRepresentativeSpecular(s, P, N, R, alpha, o.specularL);
        specularTexel = areaRepresentativeSpecularTexture(s, slot, P, o.specularL, alpha);
    }
    float diffuseFactor = 1.0;
    float specularFactor = 1.0;
    if (constantIntensity) {
        diffuseFactor = constantIntensityDiffuseFactor(s, P);
        specularFactor = constantIntensitySpecularFactor(s, P, R, alpha);
    }
    o.diffuseIlluminance = luminance * (diffuse * diffuseFactor) * diffuseTexel;
    o.specularIlluminance = luminance * (specular * specularFactor) * specularTexel;
    // Normal incidence, no surface cosine (wrap and transmission).
    vec3 unused;
    o.incidentIlluminance = luminance * diffuseFactor *
                            areaPointIrradiance(s, P, safeNormalize(toCenter), s.center,
                                                areaShapeArea(s), unused);
    return o;
}

#endif
