// Scattered light along a view ray through the atmosphere (Hillaire 2020 section 4, eq. 1-6,
// and 5.5 eq. 7-10): the sun's light scattered once at each sample (phase-weighted, dimmed by
// the transmittance towards the sun and zero in the planet's shadow), plus the isotropic
// multiple-scattering term from its table (Psi_ms, eq. 10), integrated per step with the
// analytic form of Hillaire's eq. 6 so thick steps stay energy conserving. Samples are spaced
// quadratically (t ~ (i / N)^2), dense near the viewer where a horizontal ray meets the
// densest air. The ground, where the ray ends on it, adds the sun's light it reflects
// (Lambertian albedo).
#include "common/atmosphere.glsl"

struct ScatteringResult {
    vec3 radiance;         // cd/m^2 for the given sun illuminance
    vec3 transmittance;    // along the ray to where it ends
    vec3 multipleAsOne;    // f_ms of eq. 7: scattering integrated with a unit isotropic source
};

ScatteringResult integrateScattering(AtmosphereParameters a, sampler2D transmittanceTable,
                                     sampler2D multipleScatteringTable, bool withMultiple,
                                     vec3 origin, vec3 view, vec3 towardSun, vec3 sunIlluminance,
                                     int steps, bool withGround) {
    ScatteringResult result;
    result.radiance = vec3(0.0);
    result.transmittance = vec3(1.0);
    result.multipleAsOne = vec3(0.0);
    float r = length(origin);
    float mu = dot(origin / r, view);
    float tMax = distanceToBoundary(a, r, mu);
    bool hitsGround = rayHitsGround(a, r, mu);
    float cosTheta = dot(towardSun, view);
    float phaseR = rayleighPhase(cosTheta);
    float phaseM = miePhase(a.mieAbsorption.w, cosTheta);
    const float isotropicPhase = 1.0 / (4.0 * PI);
    vec2 msSize = vec2(textureSize(multipleScatteringTable, 0));
    for (int i = 0; i < steps; ++i) {
        float x0 = float(i) / float(steps), x1 = float(i + 1) / float(steps);
        float t0 = tMax * x0 * x0, t1 = tMax * x1 * x1;
        float dt = t1 - t0;
        float t = t0 + 0.3 * dt;  // Hillaire's sample offset within the step
        vec3 P = origin + t * view;
        float rP = length(P);
        vec3 up = P / rP;
        float muSun = dot(up, towardSun);
        MediumSample m = sampleMedium(a, rP - atmosphereBottom(a));
        vec3 stepTransmittance = exp(-m.extinction * dt);
        vec3 toSun = rayHitsGround(a, rP, muSun)
                         ? vec3(0.0)
                         : transmittanceFromTable(transmittanceTable, a, rP, muSun);
        vec3 inScattered = toSun * (m.scatteringRayleigh * phaseR + m.scatteringMie * phaseM);
        if (withMultiple) {
            vec2 uv = multipleScatteringUv(a, rP, muSun, msSize);
            inScattered += textureLod(multipleScatteringTable, uv, 0.0).rgb * m.scattering;
        }
        inScattered *= sunIlluminance;
        // Eq. 6: integral over the step of S e^(-sigma_t s) ds = S (1 - e^(-sigma_t dt)) / sigma_t.
        vec3 safeExtinction = max(m.extinction, vec3(1e-9));
        vec3 oneMinus = (vec3(1.0) - stepTransmittance) / safeExtinction;
        result.radiance += result.transmittance * inScattered * oneMinus;
        result.multipleAsOne += result.transmittance * m.scattering * isotropicPhase * oneMinus;
        result.transmittance *= stepTransmittance;
    }
    if (withGround && hitsGround) {
        vec3 P = origin + tMax * view;
        float rP = length(P);
        float muSun = dot(P / rP, towardSun);
        vec3 toSun = transmittanceFromTable(transmittanceTable, a, rP, muSun);
        result.radiance += result.transmittance * toSun * sunIlluminance * saturate(muSun) *
                           a.ground.rgb * (1.0 / PI);
    }
    return result;
}
