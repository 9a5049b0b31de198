// Linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt 2016) for area lights (the shapes of
// Drobot 2014, GPU Pro 5, "Physically Based Area Lights"). A clamped cosine moved by a 3x3 matrix M
// fits the specular lobe (render/ltc/, candela-ltc-fit); its integral over a polygon equals the
// plain cosine's integral over the polygon moved by M^-1, which Lambert's edge formula gives in
// closed form once the polygon is clipped to the horizon. With M^-1 = identity it is the diffuse
// form factor.
// All vectors are in the shading frame: +z the normal, the shading point at the origin.
#ifndef CANDELA_LTC_GLSL
#define CANDELA_LTC_GLSL

#include "math.glsl"

// One edge's vector form factor (times 2 pi) for unit v1, v2: the angle between them times
// their normalised cross product. The angle from atan of the half-chord is accurate at small and
// at large angles alike (acos of the dot product is not near 0).
vec3 ltcEdgeVector(vec3 v1, vec3 v2) {
    vec3 c = cross(v1, v2);
    float sinTheta = length(c);
    float theta = 2.0 * atan(length(v1 - v2), length(v1 + v2));
    return c * (theta / max(sinTheta, 1e-7));
}

// Its z-component: the edge's share of the cosine integral.
float ltcEdgeIntegral(vec3 v1, vec3 v2) {
    return ltcEdgeVector(v1, v2).z;
}

// Sutherland-Hodgman against z >= 0: a convex polygon of `count` vertices (3 or 4) keeps at
// most count + 1. Light from below the horizon never reaches the sum.
int ltcClipToHorizon(vec3 polygon[4], int count, out vec3 clipped[5]) {
    int n = 0;
    for (int i = 0; i < count; ++i) {
        vec3 a = polygon[i];
        vec3 b = polygon[(i + 1) % count];
        if (a.z >= 0.0 && n < 5) clipped[n++] = a;
        if ((a.z >= 0.0) != (b.z >= 0.0) && n < 5) {
            clipped[n++] = mix(a, b, a.z / (a.z - b.z));
        }
    }
    return n;
}

// The vector form factor (times 2 pi) of a convex polygon (3 or 4 vertices, relative to the
// shading point, already moved by M^-1) clipped to the horizon: the sum of its edges' vectors.
// Its z is 2 pi x the cosine lobe's integral; its direction is the polygon's mean direction (by
// solid angle) in the lobe's cosine space, where a textured rect's cell reads its image
// (area_lights.glsl).
// Vertices wind clockwise as seen from the lit side; zero when nothing is above the horizon.
vec3 ltcMovedPolygonVectorSum(vec3 moved[4], int count) {
    vec3 clipped[5];
    int n = ltcClipToHorizon(moved, count, clipped);
    if (n < 3) return vec3(0.0);
    vec3 sum = vec3(0.0);
    vec3 first = safeNormalize(clipped[0]);
    vec3 previous = first;
    for (int i = 1; i < n; ++i) {
        vec3 current = safeNormalize(clipped[i]);
        sum += ltcEdgeVector(previous, current);
        previous = current;
    }
    sum += ltcEdgeVector(previous, first);
    return sum;
}

// The same for the polygon before it is moved, given M^-1.
vec3 ltcPolygonVectorSum(mat3 minv, vec3 polygon[4], int count) {
    vec3 moved[4];
    for (int i = 0; i < count; ++i) moved[i] = minv * polygon[i];
    return ltcMovedPolygonVectorSum(moved, count);
}

// The integral of the cosine lobe moved by M over a convex polygon (3 or 4 vertices, relative
// to the shading point), given M^-1. Vertices wind clockwise as seen from the lit side; the
// polygon's back side receives nothing (one-sided emitters).
float ltcPolygonIntegral(mat3 minv, vec3 polygon[4], int count) {
    return max(ltcPolygonVectorSum(minv, polygon, count).z * (0.5 / PI), 0.0);
}

#endif
