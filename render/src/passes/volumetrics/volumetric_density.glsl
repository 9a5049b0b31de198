// The medium's density (Fog component: uniform, or thinning with height, everywhere or only in
// its box) and the optical depth along a ray in closed form. Every volumetrics mode reads the
// medium through these, so all agree on where it is. The includer includes
// volumetrics_push.glsl first.
#ifndef CANDELA_VOLUMETRIC_DENSITY_GLSL
#define CANDELA_VOLUMETRIC_DENSITY_GLSL

bool mediumBounded() {
    return push.boundsMin.w > 0.0;
}

// Relative density at P: 1 everywhere, or thinning with height above the base; 0 outside the
// medium's box when it has one.
float mediumDensity(vec3 P) {
    if (mediumBounded() &&
        (any(lessThan(P, push.boundsMin.xyz)) || any(greaterThan(P, push.boundsMax.xyz)))) {
        return 0.0;
    }
    if (push.medium.w <= 0.0) return 1.0;
    return exp(min(-push.medium.w * (P.y - push.range.x), 30.0));
}

// The part [t0, t1] of the ray origin + direction t, t in [0, far], inside the medium's box
// (slab test); t0 > t1 when the ray misses it. Unbounded: [0, far].
vec2 mediumSpan(vec3 origin, vec3 direction, float far) {
    if (!mediumBounded()) return vec2(0.0, far);
    vec3 inverse = 1.0 / direction;  // IEEE infinities for axis-parallel rays
    vec3 a = (push.boundsMin.xyz - origin) * inverse;
    vec3 b = (push.boundsMax.xyz - origin) * inverse;
    vec3 near3 = min(a, b);
    vec3 far3 = max(a, b);
    float t0 = max(max(near3.x, near3.y), max(near3.z, 0.0));
    float t1 = min(min(far3.x, far3.y), min(far3.z, far));
    return vec2(t0, t1);
}

// Optical depth (extinction integrated, no unit) along the unit direction from `entry` over
// `length` metres of the medium as if it had no box, in closed form: sigma_t length in a uniform
// medium, and with the height falloff k
// sigma_t (density(entry) - density(exit)) / (k dir.y).
// Both densities are taken from their exponents, each capped as mediumDensity caps it: a ray
// that dives below the base under a steep falloff would otherwise overflow exp() to infinity
// and turn the transmittance's 0 into NaN further on.
float opticalDepthInside(vec3 entry, vec3 direction, float metres) {
    float sigmaT = push.medium.x + push.medium.y;
    float k = push.medium.w;
    if (k <= 0.0) return sigmaT * metres;
    float rate = k * direction.y;
    float entryExponent = -k * (entry.y - push.range.x);
    if (abs(rate * metres) < 1e-4) return sigmaT * exp(min(entryExponent, 30.0)) * metres;
    float exitExponent = entryExponent - rate * metres;
    return sigmaT * (exp(min(entryExponent, 30.0)) - exp(min(exitExponent, 30.0))) / rate;
}

// Optical depth from origin along the unit direction to distance t: of the ray's part inside
// the medium's box when it has one. The per-light volumes attenuate each sample and the
// surface behind by exp(-this) (the view leg).
float viewOpticalDepth(vec3 origin, vec3 direction, float t) {
    vec2 span = mediumSpan(origin, direction, t);
    if (!(span.x < span.y)) return 0.0;
    return opticalDepthInside(origin + direction * span.x, direction, span.y - span.x);
}

#endif
