// The medium's density (Fog component: uniform, or thinning with height) and the optical depth
// along a ray in closed form. The includer includes volumetrics_push.glsl first.
#ifndef CANDELA_VOLUMETRIC_DENSITY_GLSL
#define CANDELA_VOLUMETRIC_DENSITY_GLSL

// Relative density at P: 1 everywhere, or thinning with height above the base.
float mediumDensity(vec3 P) {
    if (push.medium.w <= 0.0) return 1.0;
    return exp(min(-push.medium.w * (P.y - push.range.x), 30.0));
}

// Optical depth (extinction integrated, no unit) from origin along the unit direction to
// distance t, in closed form: sigma_t t in a uniform medium, and with the height falloff k
// sigma_t density(origin) (1 - exp(-k dir.y t)) / (k dir.y). The per-light volumes attenuate
// each sample and the surface behind by exp(-this) (the view leg).
float viewOpticalDepth(vec3 origin, vec3 direction, float t) {
    float sigmaT = push.medium.x + push.medium.y;
    float k = push.medium.w;
    if (k <= 0.0) return sigmaT * t;
    float rate = k * direction.y;
    float along = abs(rate * t) < 1e-4 ? t : (1.0 - exp(-rate * t)) / rate;
    return sigmaT * mediumDensity(origin) * along;
}

#endif
