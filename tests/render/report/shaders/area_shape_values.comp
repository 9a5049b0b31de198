#version 460
// Rect and disk lights (render/shaders/common/area_lights.glsl) at host-chosen geometry for the
// report's area-light-shape rows: diffuse and specular per unit luminance, F0 = 1, against the
// host's double-precision integrals over the light (area_shape_reference.h).
#extension GL_GOOGLE_include_directive : require

#include "report_light_texture.glsl"
#include "common/brdf.glsl"
#include "common/lights.glsl"

layout(local_size_x = 64) in;

// Must match AreaShapeSample in area_light_shapes_rows.cpp.
// a.xyz light centre, a.w 1 for a disk; b.xyz V, b.w roughness; c.xyz the light's X axis,
// c.w half width (disk: radius); d.x half height, d.y mode (0 representative, 1 its unclamped
// diffuse, 2 ltc), d.z a textured rect's image (report_light_texture.glsl's slot), d.w 1 for a
// constant-intensity light (values per unit I_A: Drobot's pre-integrated factors applied).
// The surface is at the origin with N = +Z; the light faces it.
struct AreaShapeSample {
    vec4 a;
    vec4 b;
    vec4 c;
    vec4 d;
};

layout(std430, binding = 0) readonly buffer Samples {
    AreaShapeSample samples[];
};
layout(std430, binding = 1) writeonly buffer Values {
    vec2 values[];  // (diffuse irradiance, specular) per unit luminance
};
// The LTC table (render/ltc/ltc_ggx_table.inc), two vec4 per cell: M^-1 (00, 02, 20, 22) and
// (n, f, 0, 0), row = roughness, 64 x 64; read bilinearly as the renderer's sampler does.
layout(std430, binding = 2) readonly buffer Table {
    vec4 table[];
};

layout(push_constant) uniform Job {
    uint unused;
    uint sampleCount;
};

vec4 tableBilinear(float roughness, float cosView, uint part) {
    const float kSize = 64.0;
    float row = (clamp(roughness, 0.02, 1.0) - 0.02) / 0.98 * (kSize - 1.0);
    float column = sqrt(saturate(1.0 - cosView)) * (kSize - 1.0);
    vec2 p = vec2(column, row);
    uvec2 i0 = uvec2(p);
    uvec2 i1 = min(i0 + 1u, uvec2(63u));
    vec2 f = p - vec2(i0);
    vec4 top = mix(table[(i0.y * 64u + i0.x) * 2u + part], table[(i0.y * 64u + i1.x) * 2u + part], f.x);
    vec4 bottom =
        mix(table[(i1.y * 64u + i0.x) * 2u + part], table[(i1.y * 64u + i1.x) * 2u + part], f.x);
    return mix(top, bottom, f.y);
}

// (diffuse, specular) factors of a constant-intensity light, (1, 1) otherwise.
vec2 constantIntensityFactors(AreaShapeSample sample_, AreaShape shape, vec3 P, vec3 R, float alpha) {
    if (sample_.d.w < 0.5) return vec2(1.0);
    return vec2(constantIntensityDiffuseFactor(shape, P),
                constantIntensitySpecularFactor(shape, P, R, alpha));
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= sampleCount) return;
    AreaShapeSample s = samples[i];
    AreaShape shape;
    shape.center = s.a.xyz;
    shape.normal = -normalize(s.a.xyz);
    shape.axisX = s.c.xyz;
    shape.axisY = cross(s.c.xyz, shape.normal);
    shape.isDisk = s.a.w > 0.5;
    shape.halfSize = vec2(s.c.w, s.d.x);
    vec3 N = vec3(0.0, 0.0, 1.0);
    vec3 V = s.b.xyz;
    vec3 R = reflect(-V, N);
    float roughness = s.b.w;
    float alpha = alphaFromRoughness(roughness);
    uint mode = uint(s.d.y);
    vec3 P = vec3(0.0);
    uint slot = uint(s.d.z + 0.5);  // report_light_texture.glsl's image, 0 untextured
    if (mode == 2u) {
        vec3 diffuseTexel, specularTexel;
        float diffuse = PI * areaShapeIntegral(shape, P, transpose(tangentFrame(N)), mat3(1.0),
                                               slot, false, diffuseTexel);
        vec4 nf = tableBilinear(roughness, V.z, 1u);
        mat3 minv = ltcInverseMatrix(tableBilinear(roughness, V.z, 0u));
        float specular = nf.x * areaShapeIntegral(shape, P, ltcShadingFrame(N, V), minv, slot,
                                                  true, specularTexel);
        values[i] = vec2(diffuse * diffuseTexel.x, specular * specularTexel.x) *
                    constantIntensityFactors(s, shape, P, R, alpha);
        return;
    }
    vec3 L;
    float diffuse = areaRepresentativeDiffuse(shape, P, N, mode == 1u, L);
    diffuse *= areaRepresentativeDiffuseTexture(shape, slot, P, L).x;
    float illuminance = areaRepresentativeSpecular(shape, P, N, R, alpha, L);
    illuminance *= areaRepresentativeSpecularTexture(shape, slot, P, L, alpha).x;
    vec3 H = safeNormalize(V + L);
    float NoL = saturate(L.z);
    float specular = distributionGgx(alpha * alpha, saturate(H.z)) *
                     visibilitySmithGgxCorrelated(alpha, saturate(V.z), NoL) * illuminance;
    values[i] = vec2(diffuse, specular) * constantIntensityFactors(s, shape, P, R, alpha);
}
