#version 460
// Evaluates one shared light function (chosen by the push constant) at inputs chosen by the
// CPU, which compares the results with its double-precision references and numerical
// integrations (light_reference.h).
#extension GL_GOOGLE_include_directive : require

#include "common/lights.glsl"
#include "common/ltc.glsl"
#include "common/ltc_disk.glsl"
#include "common/ltc_tube.glsl"

layout(local_size_x = 64) in;

// Must match LightFunction in light_accuracy.h.
const uint kAttenuationWindow = 0u;          // (a.x distanceSq, a.y invRadius)
const uint kInverseSquare = 1u;              // (a.x distanceSq)
const uint kSphereIrradianceFactor = 2u;     // (a.x cosTheta, a.y sinSigmaSq)
const uint kSphereEnergyNormalization = 3u;  // (a.x alpha, a.y sourceRadius, a.z distance)
const uint kTubeEnergyNormalization = 4u;    // (a.x alpha, a.y sourceLength, a.z distance)
const uint kLineIrradiance = 5u;             // (a.xyz N, b.xyz L0, c.xyz L1)
const uint kTubeClosestParameter = 6u;       // (a.xyz L0, b.xyz Ld, c.xyz R)
const uint kSphereRepresentativePoint = 7u;  // (a.xyz L, b.xyz R, c.x sourceRadius)
// evaluateLocalLight at P = 0 with a 1 cd light, infinite attenuation radius:
// a.xyz position, a.w sourceRadius, b.xyz N, b.w sourceLength, c.xyz tubeAxis, d.xyz R,
// d.w alpha -> (diffuse, specular, incident illuminance, |specularL|)
const uint kLocalLight = 8u;
const uint kProduct = 9u;  // a.x * a.y: tells whether the device keeps denormals
// ltcPolygonIntegral of the quad (a.xyz, b.xyz, c.xyz, d.xyz) with M^-1 = rows
// (a.w, 0, b.w), (0, 1, 0), (c.w, 0, d.w), as the table stores it.
const uint kLtcQuad = 10u;
// ltcDiskIntegral with center a.xyz, axisU b.xyz, axisV c.xyz and M^-1 as for kLtcQuad.
const uint kLtcDisk = 11u;
// ltcTubeIntegrals of the capsule around a.xyz..b.xyz of radius c.x, M^-1 as for kLtcQuad:
// (the lobe's integral, the form factor, the lobe's integral times ltcTubeLobeCorrection for the
// table's magnitude c.y, alpha c.z and view d.xyz: the renderer's), per candela.
const uint kLtcTube = 12u;
// Irradiance per unit luminance of a rect or disk light (area_lights.glsl) at P with normal N:
// a.xyz centre, a.w 1 for a disk; b.xyz emitting normal, b.w half width (disk: radius);
// c.xyz axis X, c.w half height; d.xyz P; N = +z.
// -> (exact / "ltc" diffuse, representative diffuse, its unclamped variant, the "ltc" diffuse x
// the constant-intensity diffuse factor: irradiance per unit I_A of a constant-intensity light)
const uint kAreaLightDiffuse = 20u;

struct LightSample {
    vec4 a;
    vec4 b;
    vec4 c;
    vec4 d;
};

layout(std430, binding = 0) readonly buffer Samples {
    LightSample samples[];
};
layout(std430, binding = 1) writeonly buffer Values {
    vec4 values[];
};

layout(push_constant) uniform Job {
    uint function;
    uint sampleCount;
};

vec4 evaluate(LightSample s) {
    switch (function) {
        case kAttenuationWindow: return vec4(attenuationWindow(s.a.x, s.a.y));
        case kInverseSquare: return vec4(inverseSquare(s.a.x));
        case kSphereIrradianceFactor: return vec4(sphereIrradianceFactor(s.a.x, s.a.y));
        case kSphereEnergyNormalization:
            return vec4(sphereEnergyNormalization(s.a.x, s.a.y, s.a.z));
        case kTubeEnergyNormalization: return vec4(tubeEnergyNormalization(s.a.x, s.a.y, s.a.z));
        case kLineIrradiance: return vec4(lineIrradiance(s.a.xyz, s.b.xyz, s.c.xyz));
        case kTubeClosestParameter: return vec4(tubeClosestParameter(s.a.xyz, s.b.xyz, s.c.xyz));
        case kSphereRepresentativePoint:
            return vec4(sphereRepresentativePoint(s.a.xyz, s.b.xyz, s.c.x), 0.0);
        case kLocalLight: {
            Light light;
            light.position = s.a.xyz;
            light.invAttenuationRadius = 0.0;
            light.intensity = vec3(1.0);
            light.sourceRadius = s.a.w;
            light.direction = vec3(0.0, 0.0, -1.0);
            light.sourceLength = s.b.w;
            light.tubeAxis = s.c.xyz;
            light.type = kLightPoint;
            light.spotScale = 0.0;
            light.spotOffset = 0.0;
            LightIncidence o = evaluateLocalLight(light, vec3(0.0), s.b.xyz, s.d.xyz, s.d.w);
            return vec4(o.diffuseIlluminance.x, o.specularIlluminance.x, o.incidentIlluminance.x,
                        length(o.specularL));
        }
        case kProduct: return vec4(s.a.x * s.a.y);
        case kLtcQuad: {
            mat3 minv = mat3(vec3(s.a.w, 0.0, s.c.w), vec3(0.0, 1.0, 0.0), vec3(s.b.w, 0.0, s.d.w));
            vec3 quad[4] = vec3[4](s.a.xyz, s.b.xyz, s.c.xyz, s.d.xyz);
            return vec4(ltcPolygonIntegral(minv, quad, 4));
        }
        case kLtcDisk: {
            mat3 minv = mat3(vec3(s.a.w, 0.0, s.c.w), vec3(0.0, 1.0, 0.0), vec3(s.b.w, 0.0, s.d.w));
            return vec4(ltcDiskIntegral(minv, s.a.xyz, s.b.xyz, s.c.xyz));
        }
        case kLtcTube: {
            mat3 minv = mat3(vec3(s.a.w, 0.0, s.c.w), vec3(0.0, 1.0, 0.0), vec3(s.b.w, 0.0, s.d.w));
            vec2 integrals = ltcTubeIntegrals(minv, s.a.xyz, s.b.xyz, s.c.x);
            float correction = ltcTubeLobeCorrection(minv, s.c.y, s.c.z, s.d.xyz, s.a.xyz, s.b.xyz);
            return vec4(integrals, integrals.x * correction, 0.0);
        }
        case kAreaLightDiffuse: {
            AreaShape shape;
            shape.center = s.a.xyz;
            shape.normal = s.b.xyz;
            shape.axisX = s.c.xyz;
            shape.axisY = cross(s.c.xyz, s.b.xyz);
            shape.isDisk = s.a.w > 0.5;
            shape.halfSize = vec2(s.b.w, s.c.w);
            vec3 N = vec3(0.0, 0.0, 1.0);
            vec3 L;
            return vec4(areaExactDiffuse(shape, s.d.xyz, N),
                        areaRepresentativeDiffuse(shape, s.d.xyz, N, false, L),
                        areaRepresentativeDiffuse(shape, s.d.xyz, N, true, L),
                        areaExactDiffuse(shape, s.d.xyz, N) *
                            constantIntensityDiffuseFactor(shape, s.d.xyz));
        }
        default: return vec4(0.0);
    }
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= sampleCount) return;
    values[i] = evaluate(samples[i]);
}
