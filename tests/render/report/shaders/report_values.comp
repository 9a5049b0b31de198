#version 460
// Evaluates the shared GLSL at inputs chosen by the host for the report's error columns; the
// host compares with its double-precision references.
#extension GL_GOOGLE_include_directive : require

#include "common/brdf.glsl"
#include "common/ibl.glsl"
#include "common/lights.glsl"
#include "area_light_integration.glsl"

layout(local_size_x = 64) in;

// Must match ValueFunction in shader_values.h.
const uint kFresnel = 0u;           // a.x VoH, a.y F0 -> (SG, pow5)
const uint kVisibility = 1u;        // a.x alpha, a.y NoV, a.z NoL -> (Schlick, Smith GGX)
const uint kEnvBrdfApprox = 2u;     // a.x roughness, a.y NoV, a.z F0 -> (approx)
const uint kEnvBrdfMonteCarlo = 3u; // a.x roughness, a.y NoV, a.z F0, a.w samples -> (eq. 8)
const uint kFalloff = 4u;           // a.x distanceSq, a.y invRadius -> (windowed, inverse square)
const uint kGgx = 5u;               // a.x a2, a.y NoH -> (D)
// a.xyz light position, a.w sourceRadius, b.xyz V, b.w sourceLength, c.x roughness, c.yzw
// tube axis -> (representative-point specular)
const uint kAreaLight = 6u;
const uint kVisibilityFast = 7u;    // a.x alpha, a.y NoV, a.z NoL -> (Hammon's fast form, exact)
// As kAreaLight, d the table's M^-1 (00, 02, 20, 22), e.x its magnitude -> (LTC specular over the
// light with unit magnitude, representative-point specular with the height-correlated Smith
// visibility)
const uint kAreaLightLtc = 8u;
// A tube light at a.xyz, radius a.w, length b.w, axis c.yzw, over N = +Z -> (the LTC mode's
// diffuse: the capsule's irradiance, the representative mode's: lineIrradiance), lux per cd
const uint kTubeDiffuse = 9u;

struct Sample {
    vec4 a;
    vec4 b;
    vec4 c;
    vec4 d;
    vec4 e;
};

layout(std430, binding = 0) readonly buffer Samples {
    Sample samples[];
};
layout(std430, binding = 1) writeonly buffer Values {
    vec2 values[];
};

layout(push_constant) uniform Job {
    uint function;
    uint sampleCount;
};

vec2 evaluate(Sample s) {
    switch (function) {
        case kFresnel:
            return vec2(fresnelSchlickSg(vec3(s.a.y), s.a.x).x, fresnelSchlickPow5(vec3(s.a.y), s.a.x).x);
        case kVisibility:
            return vec2(visibilitySmithSchlick(s.a.x, s.a.y, s.a.z),
                        visibilitySmithGgxCorrelated(s.a.x, s.a.y, s.a.z));
        case kEnvBrdfApprox: return vec2(envBrdfApprox(vec3(s.a.z), s.a.x, s.a.y).x, 0.0);
        case kEnvBrdfMonteCarlo: {
            vec2 ab = integrateEnvironmentBrdf(s.a.x, s.a.y, uint(s.a.w));
            return vec2(s.a.z * ab.x + ab.y, 0.0);
        }
        case kFalloff:
            return vec2(attenuationWindow(s.a.x, s.a.y) * inverseSquare(s.a.x), inverseSquare(s.a.x));
        case kGgx: return vec2(distributionGgx(s.a.x, s.a.y), 0.0);
        case kAreaLight:
        case kAreaLightLtc: {
            Light light;
            light.position = s.a.xyz;
            light.invAttenuationRadius = 0.0;
            light.intensity = vec3(1.0);
            // A tube's negative radius asks for the bare segment's LTC (ltcSpecular).
            light.sourceRadius = max(s.a.w, 0.0);
            light.direction = vec3(0.0, 0.0, -1.0);
            light.sourceLength = s.b.w;
            light.tubeAxis = s.c.yzw;
            light.type = kLightPoint;
            light.spotScale = 0.0;
            light.spotOffset = 0.0;
            if (function == kAreaLightLtc) {
                return vec2(ltcSpecular(light, s.b.xyz, s.d, s.a.w < 0.0, s.e.x, s.c.x),
                            representativePointSpecular(light, s.b.xyz, s.c.x, true));
            }
            return vec2(representativePointSpecular(light, s.b.xyz, s.c.x), 0.0);
        }
        case kTubeDiffuse: {
            vec3 halfSegment = s.c.yzw * (0.5 * s.b.w);
            vec3 N = kSurfaceNormal;
            return vec2(PI * ltcTubeIntegrals(mat3(1.0), s.a.xyz - halfSegment, s.a.xyz + halfSegment, s.a.w).y,
                        lineIrradiance(N, s.a.xyz - halfSegment, s.a.xyz + halfSegment));
        }
        case kVisibilityFast:
            return vec2(visibilitySmithGgxCorrelatedFast(s.a.x, s.a.y, s.a.z),
                        visibilitySmithGgxCorrelated(s.a.x, s.a.y, s.a.z));
        default: return vec2(0.0);
    }
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= sampleCount) return;
    values[i] = evaluate(samples[i]);
}
