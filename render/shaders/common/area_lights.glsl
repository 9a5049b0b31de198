// Rect and disk lights (issue 15): one-sided Lambertian emitters facing the node's -Z
// (Light.direction), luminance L = lumens / (pi area) in Light.intensity. Included by
// lights.glsl after `struct Light`; evaluateAreaLight is evaluateLight's case for both types.
//  - Diffuse, "ltc" mode: the exact form factor with M^-1 = identity: Lambert's edge sum over
//    a rect clipped to the horizon (ltc.glsl), Heitz and Hill's ellipse for a disk
//    (ltc_disk.glsl).
//  - "representative" mode (seed 004 section 1): area_light_representative.glsl.
//  - Specular, "ltc" mode: the fitted LTC (lights/ltc_table_texture.h) over the same shape,
//    in shaders that bind the table (they define AREA_LIGHT_LTC_MATRIX_BINDING and
//    AREA_LIGHT_LTC_MAGNITUDE_BINDING before including lights.glsl: the lighting and forward
//    passes); elsewhere, and in "representative" mode, the seed's specular cone.
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
    return light.type == LIGHT_TYPE_RECT ? uint(max(light.spotScale, 1.0) + 0.5) - 1u : 0u;
#else
    return 0u;
#endif
}

// The image a lobe sees on a textured rect, by LTC (Heitz et al. 2016, section 5.3): in the
// lobe's cosine space (the rect moved by M^-1, where the lobe is a plain cosine) the point
// where the rect's mean direction `direction` (ltcPolygonVectorSum) meets it; M^-1 is linear, so
// the moved rect's affine coordinates are the image's uv. The mip from the cosine's footprint
// there against the moved rect's size: for diffuse twice the plane's distance (half the cosine's
// power falls within 45 degrees) over kAreaLightTextureTexelsPerFootprint; for specular the two
// reads of area_light_texture.glsl (a sharp one for the cosine's peak, a wide one for its tail).
vec3 areaLtcTexture(uint slot, vec3 polygon[4], mat3 minv, vec3 direction, bool specular) {
#ifdef AREA_LIGHT_TEXTURED
    vec3 p0 = minv * polygon[0];
    vec3 e1 = minv * polygon[1] - p0;  // along the rect's +X
    vec3 e2 = minv * polygon[3] - p0;  // along its +Y
    vec3 n = cross(e1, e2);
    float area = length(n);
    float offset = dot(n, p0);  // area x the plane's distance
    float approach = dot(n, direction);
    // Nothing above the horizon (direction 0): the integral is 0, any point will do.
    vec3 hit = abs(approach) > 1e-12 * area * length(direction) ? direction * (offset / approach)
                                                                 : p0 + 0.5 * (e1 + e2);
    vec3 d = hit - p0;
    float e11 = dot(e1, e1), e12 = dot(e1, e2), e22 = dot(e2, e2);
    float det = max(e11 * e22 - e12 * e12, 1e-30);
    vec2 uv = vec2(e22 * dot(d, e1) - e12 * dot(d, e2), e11 * dot(d, e2) - e12 * dot(d, e1)) / det;
    uv = clamp(uv, vec2(0.0), vec2(1.0));
    float distance = abs(offset) / max(area, 1e-30);
    float size = sqrt(area);
    if (!specular) {
        return areaLightTexture(slot, uv, areaLightTextureLod(2.0 * distance, size));
    }
    float narrowLod =
        areaLightTextureLod(kAreaLightTextureSpecularNarrowFootprint * distance, size, 1.0);
    float wideLod = areaLightTextureLod(kAreaLightTextureSpecularWideFootprint * distance, size, 1.0);
    vec3 narrow = areaLightTexture(slot, uv, narrowLod);
    vec3 wide = areaLightTexture(slot, uv, wideLod);
    return mix(wide, narrow, kAreaLightTextureSpecularNarrowWeight);
#else
    return vec3(1.0);
#endif
}

// areaShapeIntegral, and in `texel` what a textured rect (slot > 0) shows the lobe (1 for an
// untextured shape): one edge sum gives both. `specular`: the specular lobe's two reads
// (area_light_texture.glsl).
float areaShapeIntegral(AreaShape s, vec3 P, mat3 toLocal, mat3 minv, uint slot, bool specular,
                        out vec3 texel) {
    texel = vec3(1.0);
    if (s.isDisk || slot == 0u) return areaShapeIntegral(s, P, toLocal, minv);
    vec3 polygon[4];
    rectPolygon(s, P, toLocal, polygon);
    vec3 sum = ltcPolygonVectorSum(minv, polygon, 4);
    texel = areaLtcTexture(slot, polygon, minv, sum, specular);
    return max(sum.z * (0.5 / PI), 0.0);
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

// Representative mode's texture reads (seed 004 section 1 gives none; the image at the sample
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
// scaled by the seed's pre-integrated factor (area_light_constant_intensity.glsl), in either mode.
LightIncidence evaluateAreaLight(Light light, vec3 P, vec3 N, vec3 R, float alpha,
                                 bool representative, bool constantIntensity) {
    AreaShape s = areaShapeOf(light);
    vec3 toCenter = s.center - P;
    float window = attenuationWindow(dot(toCenter, toCenter), light.invAttenuationRadius);
    vec3 luminance = light.intensity * window;
    uint slot = areaTextureSlot(light);
    // A textured rect's image as each lobe sees it (1 untextured): by LTC where the lobe's
    // mean direction meets the rect; in representative mode at the sample point, over the
    // footprint of the cosine (twice the height) or of the seed's specular cone.
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
