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

#include "common/area_light_representative.glsl"
#include "common/ltc.glsl"
#include "common/ltc_area_lights.glsl"
#include "common/ltc_disk.glsl"

// Per-light `quality` (Light.spotOffset of area lights, gpu_light.cpp): 0 the renderer's
// default, 1 representative, 2 ltc.
const uint kAreaQualityDefault = 0u;
const uint kAreaQualityRepresentative = 1u;
const uint kAreaQualityLtc = 2u;

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

LightIncidence evaluateAreaLight(Light light, vec3 P, vec3 N, vec3 R, float alpha,
                                 bool representative) {
    AreaShape s = areaShapeOf(light);
    vec3 toCenter = s.center - P;
    float window = attenuationWindow(dot(toCenter, toCenter), light.invAttenuationRadius);
    vec3 luminance = light.intensity * window;

    LightIncidence o;
    vec3 representativeL;
    float representativeDiffuse = areaRepresentativeDiffuse(s, P, N, false, representativeL);
    o.diffuseL = representativeL;
    float diffuse = representative ? representativeDiffuse : areaExactDiffuse(s, P, N);
    o.specularLtc = vec2(0.0);
    float specular;
#ifdef AREA_LIGHT_LTC_MATRIX_BINDING
    if (!representative) {
        vec3 V = 2.0 * dot(N, R) * N - R;  // R = reflect(-V, N)
        specular = areaLtcSpecular(s, P, N, V, sqrt(alpha), o.specularLtc);
        o.specularL = R;
    } else
#endif
    {
        specular = areaRepresentativeSpecular(s, P, N, R, alpha, o.specularL);
    }
    o.diffuseIlluminance = luminance * diffuse;
    o.specularIlluminance = luminance * specular;
    // Normal incidence, no surface cosine (wrap and transmission).
    vec3 unused;
    o.incidentIlluminance = luminance * areaPointIrradiance(s, P, safeNormalize(toCenter), s.center,
                                                            areaShapeArea(s), unused);
    return o;
}

#endif
