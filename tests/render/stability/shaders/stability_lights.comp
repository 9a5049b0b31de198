#version 460
// Hard-input grid over the shared light incidence (Karis 2013, "Real Shading in Unreal Engine 4",
// eq. 9-20): evaluateLocalLight for point, spot, sphere and tube lights at distances from 0 to 1e6
// m, radii and lengths from 0 to far beyond the distance, intensities from 0 to 1e9 lm, plus the
// reductions the SPEC demands: zero radius and length bit-identical to the point light, and
// vanishing radius or length within 1e-5 of it. One invocation = one (distance, direction, light,
// view, roughness, type); it loops over every radius, length and tube axis.
#extension GL_GOOGLE_include_directive : require

#include "common/shading_models.glsl"
#include "stability_checks.glsl"

layout(local_size_x = 64) in;

// Every axis entry is a vec4; scalars live in .x. Offsets and counts come in the push constants.
layout(std430, binding = 1) readonly buffer Axes {
    vec4 axisValues[];
};

// Axis order: must match LightAxis in light_stability_tests.cpp.
const uint kAxisDistance = 0u;     // metres from P to the light centre
const uint kAxisDirection = 1u;    // unit direction from P to the light, N = +Z
const uint kAxisLightParams = 2u;  // (candela, 1 / attenuation radius)
const uint kAxisView = 3u;         // unit V
const uint kAxisRoughness = 4u;
const uint kAxisType = 5u;         // 0 point, 1 spot aimed at P, 2 spot aimed away
const uint kAxisRadius = 6u;       // sourceRadius
const uint kAxisLength = 7u;       // sourceLength
const uint kAxisTubeAxis = 8u;     // unit tube axis
const uint kAxisTinyFraction = 9u; // vanishing radius/length as a fraction of the distance
const uint kAxisCount = 10u;

layout(push_constant) uniform Grid {
    uint axisOffset[kAxisCount];
    uint axisCount[kAxisCount];
};

// Record order: must match LightCheck in light_stability_tests.cpp.
const uint kCheckDiffuseIlluminance = 0u;
const uint kCheckSpecularIlluminance = 1u;
const uint kCheckIncidentIlluminance = 2u;
const uint kCheckDiffuseDirection = 3u;   // |diffuseL|^2 in [0, 1]
const uint kCheckSpecularDirection = 4u;  // |specularL|^2 in [0, 1]
const uint kCheckShadedRadiance = 5u;
const uint kCheckPointBitIdentical = 6u;
const uint kCheckVanishingTube = 7u;
const uint kCheckVanishingSphere = 8u;
const uint kCheckDirectional = 9u;
const uint kCheckCount = 10u;

vec4 axis(uint a, uint i) {
    return axisValues[axisOffset[a] + i];
}

// The point light by definition (eq. 9 in metres): windowed inverse square, cosine, spot
// cone; the same for diffuse and specular. Written here, independent of evaluateLocalLight.
LightIncidence pointLightByDefinition(Light light, vec3 P, vec3 N) {
    vec3 toLight = light.position - P;
    float distanceSq = dot(toLight, toLight);
    vec3 L = safeNormalize(toLight);
    vec3 intensity = light.intensity * attenuationWindow(distanceSq, light.invAttenuationRadius);
    if (light.type == kLightSpot) intensity *= spotAttenuation(light, L);
    float illuminancePerIntensity = saturate(dot(N, L)) * inverseSquare(distanceSq);
    LightIncidence o;
    o.diffuseL = L;
    o.specularL = L;
    o.diffuseIlluminance = intensity * illuminancePerIntensity;
    o.specularIlluminance = intensity * illuminancePerIntensity;
    o.incidentIlluminance = intensity * inverseSquare(distanceSq);
    o.specularLtc = vec2(0.0);
    return o;
}

bool bitIdentical(vec3 a, vec3 b) {
    return all(equal(floatBitsToUint(a), floatBitsToUint(b)));
}

bool bitIdentical(LightIncidence a, LightIncidence b) {
    return bitIdentical(a.diffuseL, b.diffuseL) && bitIdentical(a.specularL, b.specularL) &&
           bitIdentical(a.diffuseIlluminance, b.diffuseIlluminance) &&
           bitIdentical(a.specularIlluminance, b.specularIlluminance) &&
           bitIdentical(a.incidentIlluminance, b.incidentIlluminance);
}

// Within 1e-5 of the point light: illuminances relative to the point light's illuminance at
// normal incidence (the natural scale; a cosine near 0 would make a plain relative test
// meaningless), directions absolutely.
bool closeToPoint(LightIncidence a, LightIncidence p) {
    const float tolerance = 1e-5;
    vec3 scale = tolerance * p.incidentIlluminance;
    return all(lessThanEqual(abs(a.diffuseIlluminance - p.diffuseIlluminance), scale)) &&
           all(lessThanEqual(abs(a.specularIlluminance - p.specularIlluminance), scale)) &&
           all(lessThanEqual(abs(a.incidentIlluminance - p.incidentIlluminance), scale)) &&
           all(lessThanEqual(abs(a.diffuseL - p.diffuseL), vec3(tolerance))) &&
           all(lessThanEqual(abs(a.specularL - p.specularL), vec3(tolerance)));
}

void main() {
    uint index = gl_GlobalInvocationID.x;
    uint n[6];
    uint total = 1u;
    for (uint a = 0u; a < 6u; ++a) {
        n[a] = axisCount[a];
        total *= n[a];
    }
    if (index >= total) return;
    uint i[6];
    uint rest = index;
    for (int a = 5; a >= 0; --a) {
        i[a] = rest % n[a];
        rest /= n[a];
    }

    const vec3 P = vec3(0.0);
    const vec3 N = vec3(0.0, 0.0, 1.0);
    float distance = axis(kAxisDistance, i[0]).x;
    vec3 direction = axis(kAxisDirection, i[1]).xyz;
    vec4 params = axis(kAxisLightParams, i[2]);
    vec3 V = axis(kAxisView, i[3]).xyz;
    float roughness = axis(kAxisRoughness, i[4]).x;
    uint type = uint(axis(kAxisType, i[5]).x);
    vec3 R = reflect(-V, N);
    float alpha = alphaFromRoughness(roughness);

    Light light;
    light.position = direction * distance;
    light.invAttenuationRadius = params.y;
    light.intensity = vec3(params.x);
    light.type = type == 0u ? kLightPoint : kLightSpot;
    light.direction = type == 1u ? -direction : direction;
    const float cosInner = 0.93969262;  // 20 degrees
    const float cosOuter = 0.86602540;  // 30 degrees
    light.spotScale = 1.0 / (cosInner - cosOuter);
    light.spotOffset = -cosOuter * light.spotScale;

    Surface surface;
    surface.baseColor = vec3(0.8);
    surface.metallic = 0.0;
    surface.roughness = roughness;
    surface.specular = 0.5;
    surface.shadingModel = kShadingDefaultLit;
    surface.customData = vec4(0.0);
    // The energy-conserving BRDF's compensation beyond its largest: E_ss's floor in the LUT is
    // 0.307 (roughness 1, NoV 1); 0.1 leaves margin.
    surface.directionalAlbedo = 0.1;

    Tally t[kCheckCount];
    for (uint c = 0u; c < kCheckCount; ++c) t[c] = newTally();

    uint radiusCount = axisCount[kAxisRadius];
    uint lengthCount = axisCount[kAxisLength];
    uint tubeAxisCount = axisCount[kAxisTubeAxis];
    for (uint r = 0u; r < radiusCount; ++r) {
        for (uint l = 0u; l < lengthCount; ++l) {
            for (uint x = 0u; x < tubeAxisCount; ++x) {
                uint caseIndex = ((index * radiusCount + r) * lengthCount + l) * tubeAxisCount + x;
                light.sourceRadius = axis(kAxisRadius, r).x;
                light.sourceLength = axis(kAxisLength, l).x;
                light.tubeAxis = axis(kAxisTubeAxis, x).xyz;
                LightIncidence inc = evaluateLocalLight(light, P, N, R, alpha);
                tally3(t[kCheckDiffuseIlluminance], inc.diffuseIlluminance, 0.0,
                       kNoUpperBound, caseIndex);
                tally3(t[kCheckSpecularIlluminance], inc.specularIlluminance, 0.0,
                       kNoUpperBound, caseIndex);
                tally3(t[kCheckIncidentIlluminance], inc.incidentIlluminance, 0.0,
                       kNoUpperBound, caseIndex);
                tally(t[kCheckDiffuseDirection], dot(inc.diffuseL, inc.diffuseL), 0.0, 1.00001,
                      caseIndex);
                tally(t[kCheckSpecularDirection], dot(inc.specularL, inc.specularL), 0.0,
                      1.00001, caseIndex);
                tally3(t[kCheckShadedRadiance], shadeSurface(surface, N, V, inc), 0.0,
                       kNoUpperBound, caseIndex);
            }
        }
    }

    // Reductions, for every light/geometry of this invocation.
    light.sourceRadius = 0.0;
    light.sourceLength = 0.0;
    LightIncidence point = evaluateLocalLight(light, P, N, R, alpha);
    tallyCondition(t[kCheckPointBitIdentical],
                   bitIdentical(point, pointLightByDefinition(light, P, N)), index);
    uint tinyCount = axisCount[kAxisTinyFraction];
    for (uint k = 0u; k < tinyCount; ++k) {
        vec4 tiny = axis(kAxisTinyFraction, k);  // x: fraction of the distance, y: absolute
        float size = max(tiny.x * distance, tiny.y);
        if (size > 1e-9 * distance) continue;  // only sizes that vanish against the distance
        uint caseIndex = index * tinyCount + k;
        for (uint x = 0u; x < tubeAxisCount; ++x) {
            Light tube = light;
            tube.sourceLength = size;
            tube.tubeAxis = axis(kAxisTubeAxis, x).xyz;
            tallyCondition(t[kCheckVanishingTube],
                           closeToPoint(evaluateLocalLight(tube, P, N, R, alpha), point),
                           caseIndex * tubeAxisCount + x);
        }
        Light sphere = light;
        sphere.sourceRadius = size;
        tallyCondition(t[kCheckVanishingSphere],
                       closeToPoint(evaluateLocalLight(sphere, P, N, R, alpha), point), caseIndex);
    }

    Light sun = light;
    sun.type = kLightDirectional;
    sun.direction = -direction;
    sun.intensity = vec3(params.x);
    LightIncidence daylight = evaluateDirectionalLight(sun, N);
    tally3(t[kCheckDirectional], daylight.diffuseIlluminance, 0.0, kNoUpperBound, index);
    tally3(t[kCheckDirectional], shadeSurface(surface, N, V, daylight), 0.0, kNoUpperBound,
           index);

    for (uint c = 0u; c < kCheckCount; ++c) flushTally(c, t[c]);
}
