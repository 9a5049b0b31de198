// Light-versus-cluster tests for the compute light assignment: the GLSL twin of
// render/src/clustered/light_bounds.cpp (same shapes, same slack), so the GPU and CPU paths
// keep the same lights. Every test is conservative: it may keep a light that adds nothing,
// never drop one that adds something (eq. 9's window reaches zero at attenuationRadius).
// Only assign_lights.comp includes it; it lives in common/ because the shader build tracks
// included files there.
#ifndef CANDELA_LIGHT_CLUSTER_TESTS_GLSL
#define CANDELA_LIGHT_CLUSTER_TESTS_GLSL

#include "common/lights.glsl"

const uint kBoundsSphere = 0u;
const uint kBoundsCapsule = 1u;
const uint kBoundsCone = 2u;
const uint kBoundsHalfSphere = 3u;  // one-sided area lights: sphere cut by the light's plane

struct LightBounds {
    vec3 center;  // bounding sphere, used for the slice and tile ranges
    float radius;
    uint shape;
    vec3 segmentStart;    // capsule: segment; cone: apex
    vec3 segmentEnd;      // capsule: segment end; cone: unit axis; half sphere: normal
    float capsuleRadius;  // capsule: attenuation radius; cone: range
    float coneCos;
    float coneSin;
};

// Float slack added to every distance comparison, relative to the light's size.
float boundsSlack(float radius) {
    return 1e-4 * (1.0 + radius);
}

// Bounds of a local light in view space. The light buffer stores 1 / radius (radius >= 1e-6)
// and the spot cone as scale/offset; both invert to within an ulp, far inside the slack.
LightBounds lightBoundsInView(Light light, mat4 view) {
    LightBounds b;
    float range = 1.0 / light.invAttenuationRadius;
    vec3 position = (view * vec4(light.position, 1.0)).xyz;
    float halfLength = 0.5 * light.sourceLength;
    b.shape = kBoundsSphere;
    b.segmentStart = position;
    b.segmentEnd = vec3(0.0);
    b.capsuleRadius = range;
    b.coneCos = 0.0;
    b.coneSin = 0.0;
    b.center = position;
    b.radius = range;
    if (halfLength > 0.0) {
        vec3 axis = normalize(mat3(view) * light.tubeAxis);
        b.shape = kBoundsCapsule;
        b.segmentStart = position - axis * halfLength;
        b.segmentEnd = position + axis * halfLength;
        b.radius = range + halfLength;
        return b;
    }
    if (lightBoundsKind(light.type) == kLightBoundsHalfSpace) {
        b.shape = kBoundsHalfSphere;
        b.segmentEnd = mat3(view) * light.direction;
        return b;
    }
    float coneCos = clamp(-light.spotOffset / light.spotScale, 0.0, 1.0);
    // Spots narrower than ~80 degrees (cos 1.4 rad) get the cone test, as on the CPU.
    if (lightBoundsKind(light.type) == kLightBoundsCone && coneCos > 0.16996714) {
        vec3 axis = normalize(mat3(view) * light.direction);
        b.shape = kBoundsCone;
        b.segmentEnd = axis;
        b.coneCos = coneCos;
        b.coneSin = sqrt(max(1.0 - coneCos * coneCos, 0.0));
        // Smallest sphere around the cone (apex, axis, range, half-angle).
        if (coneCos * coneCos >= 0.5) {
            b.radius = range / (2.0 * coneCos);
            b.center = position + axis * b.radius;
        } else {
            b.radius = range * b.coneSin;
            b.center = position + axis * (range * coneCos);
        }
    }
    return b;
}

float distanceSqPointBox(vec3 p, vec3 lo, vec3 hi) {
    vec3 d = max(max(lo - p, p - hi), vec3(0.0));
    return dot(d, d);
}

// Minimum distance from segment a..b to the box: convex along the segment, so a ternary
// search converges; the remaining bracket is added back to stay conservative.
float distanceSegmentBox(vec3 a, vec3 b, vec3 lo, vec3 hi) {
    float t0 = 0.0, t1 = 1.0;
    for (int i = 0; i < 24; ++i) {
        float m0 = t0 + (t1 - t0) / 3.0, m1 = t1 - (t1 - t0) / 3.0;
        float f0 = sqrt(distanceSqPointBox(a + (b - a) * m0, lo, hi));
        float f1 = sqrt(distanceSqPointBox(a + (b - a) * m1, lo, hi));
        if (f0 < f1) {
            t1 = m1;
        } else {
            t0 = m0;
        }
    }
    float bracket = length(b - a) * (t1 - t0);
    return max(sqrt(distanceSqPointBox(a + (b - a) * (0.5 * (t0 + t1)), lo, hi)) - bracket, 0.0);
}

// Does the light's bounding sphere, and for a cone the cone, reach the view-space box
// [lo, hi]? Exact for spheres and cones, conservative for capsules; loop-free (the quarter
// tests of assign_lights.comp rely on that).
bool boundingShapeTouchesBox(LightBounds b, vec3 lo, vec3 hi) {
    float r = b.radius + boundsSlack(b.radius);
    if (distanceSqPointBox(b.center, lo, hi) > r * r) return false;
    if (b.shape != kBoundsCone) return true;
    // The box's bounding sphere against the cone (sphere-vs-cone with a flat cap).
    vec3 boxCenter = 0.5 * (lo + hi);
    float boxRadius = 0.5 * length(hi - lo) + boundsSlack(b.radius);
    vec3 v = boxCenter - b.segmentStart;
    float along = dot(v, b.segmentEnd);
    float across = sqrt(max(dot(v, v) - along * along, 0.0));
    if (b.coneCos * across - along * b.coneSin > boxRadius) return false;
    if (along > b.capsuleRadius + boxRadius) return false;
    return along >= -boxRadius;
}

// Does the light reach the view-space box [lo, hi]?
bool lightTouchesBox(LightBounds b, vec3 lo, vec3 hi) {
    if (b.shape == kBoundsCapsule) {
        return distanceSegmentBox(b.segmentStart, b.segmentEnd, lo, hi) <=
               b.capsuleRadius + boundsSlack(b.radius);
    }
    if (b.shape == kBoundsHalfSphere) {
        if (!boundingShapeTouchesBox(b, lo, hi)) return false;
        // The box corner furthest along the normal, against the light's plane.
        vec3 n = b.segmentEnd;
        vec3 corner = vec3(n.x >= 0.0 ? hi.x : lo.x, n.y >= 0.0 ? hi.y : lo.y,
                           n.z >= 0.0 ? hi.z : lo.z);
        return dot(n, corner - b.center) >= -boundsSlack(b.radius);
    }
    return boundingShapeTouchesBox(b, lo, hi);
}

// False when the light lies entirely on the negative side of the plane n.p = 0 (n unit).
bool lightReachesPositiveSide(LightBounds b, vec3 n) {
    if (b.shape == kBoundsCapsule) {
        float nearest = max(dot(n, b.segmentStart), dot(n, b.segmentEnd));
        return nearest >= -(b.capsuleRadius + boundsSlack(b.radius));
    }
    return dot(n, b.center) >= -(b.radius + boundsSlack(b.radius));
}

#endif
