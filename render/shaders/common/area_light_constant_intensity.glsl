// Drobot's (2014, GPU Pro 5, "Physically Based Area Lights") variant for constant-intensity lights
// (rect and disk, `emission` "constantIntensity"): each element of the light radiates the same
// intensity in every direction in front of it, I_A per square metre (cd/m^2 of emitting area,
// Light.intensity), instead of the same luminance. Seen from P the luminance then varies over the
// light, L(x) = I_A / cos theta_o(x) = I_A |x - P| / h (h: P's height above the light's plane).
// Drobot pre-integrates that varying luminance over the light, normalised by the light's area, into
// a diffuse factor and a specular factor (over the specular cone's intersection), and multiplies
// the constant-luminance results at their representative points by them. The pre-integral is
// closed-form here: the integral of the distance to P over an axis-aligned rectangle of the plane
// (a disk's, its equal-area square, as the specular cone already takes it).
#ifndef CANDELA_AREA_LIGHT_CONSTANT_INTENSITY_GLSL
#define CANDELA_AREA_LIGHT_CONSTANT_INTENSITY_GLSL

#include "common/area_light_representative.glsl"

// An antiderivative G(x, y) of sqrt(x^2 + y^2 + h^2) in x and y (d^2 G / dx dy is the
// integrand): x y s / 3 + x (x^2 + 3 h^2) asinh(y / sqrt(x^2 + h^2)) / 6 + the same with x and y
// swapped - h^3 atan(x y / (h s)) / 3, s = sqrt(x^2 + y^2 + h^2). asinh(y / sqrt(x^2 + h^2)) is
// log(y + s) less a function of x alone, which cancels between the corners, and keeps its
// precision for negative y where log(y + s) would not.
float constantIntensityAntiderivative(float x, float y, float h) {
    float s = sqrt(x * x + y * y + h * h);
    float hh = h * h;
    return x * y * s / 3.0 + x * (x * x + 3.0 * hh) * asinh(y / max(sqrt(x * x + hh), 1e-20)) / 6.0 +
           y * (y * y + 3.0 * hh) * asinh(x / max(sqrt(y * y + hh), 1e-20)) / 6.0 -
           hh * h * atan(x * y, h * s) / 3.0;
}

// The mean distance from P to the rectangle [lo, hi] of the light's plane, P at plane
// coordinates q and height h > 0. Where the rectangle is small against the distance (side under
// a tenth of it) the corners' sum cancels in fp32, and the distance to its centre is within
// 0.1 % of the mean.
float areaMeanDistance(vec2 q, float h, vec2 lo, vec2 hi) {
    vec2 a = lo - q;
    vec2 b = hi - q;
    vec2 centre = 0.5 * (a + b);
    float centreDistanceSq = dot(centre, centre) + h * h;
    vec2 extent = b - a;
    if (dot(extent, extent) < 0.01 * centreDistanceSq) return sqrt(centreDistanceSq);
    float integral = constantIntensityAntiderivative(b.x, b.y, h) -
                     constantIntensityAntiderivative(a.x, b.y, h) -
                     constantIntensityAntiderivative(b.x, a.y, h) +
                     constantIntensityAntiderivative(a.x, a.y, h);
    return integral / max(extent.x * extent.y, 1e-30);
}

// The luminance per unit I_A averaged over the rectangle [lo, hi]: (1 / A) integral of |x - P| / h.
float constantIntensityFactor(AreaShape s, vec3 P, vec2 lo, vec2 hi) {
    float h = dot(P - s.center, s.normal);
    if (h <= 0.0) return 0.0;
    return areaMeanDistance(areaPlaneCoords(s, P), h, lo, hi) / h;
}

// The diffuse factor: over the whole shape (a disk as its equal-area square).
float constantIntensityDiffuseFactor(AreaShape s, vec3 P) {
    const float kSquareOfDisc = 0.886226925;  // sqrt(pi) / 2
    vec2 halfSide = s.isDisk ? s.halfSize * kSquareOfDisc : s.halfSize;
    return constantIntensityFactor(s, P, -halfSide, halfSide);
}

// The specular factor: over the specular cone's intersection with the shape
// (areaSpecularConeFootprint); the diffuse factor where the cone misses it (the representative
// specular is 0 there; an LTC lobe may still see the light).
float constantIntensitySpecularFactor(AreaShape s, vec3 P, vec3 R, float alpha) {
    vec2 lo, hi;
    if (!areaSpecularConeFootprint(s, P, R, alpha, lo, hi)) {
        return constantIntensityDiffuseFactor(s, P);
    }
    return constantIntensityFactor(s, P, lo, hi);
}

#endif
