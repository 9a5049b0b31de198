// The atmosphere's optics (issue 16; Hillaire 2020, "A Scalable and Production Ready Sky and
// Atmosphere Rendering Technique", EGSR): the density profiles of air, aerosols and ozone, the
// phase functions, ray-sphere distances, the transmittance integral, and the parameterisations
// of the transmittance, multiple-scattering and sky-view tables. The table shaders
// (passes/atmosphere), the sky background and the stability tests share it.
//
// Units: kilometres and 1/km. Radii of ~6360 km in metres would leave a float ~0.5 m of
// precision in r and ~2e6 m^2 in r^2, which the ray-sphere discriminants cannot afford.
// Positions are planet-centred, +Y up; the scene's origin sits on the ground at the top of the
// planet.
#ifndef CANDELA_ATMOSPHERE_GLSL
#define CANDELA_ATMOSPHERE_GLSL

#include "common/math.glsl"

// What C++ fills (passes/atmosphere/atmosphere_parameters.h, same layout, std140/std430).
struct AtmosphereParameters {
    vec4 rayleigh;       // scattering rgb (1/km), scale height (km)
    vec4 mie;            // scattering rgb (1/km), scale height (km)
    vec4 mieAbsorption;  // absorption rgb (1/km), anisotropy g
    vec4 ozone;          // absorption rgb at the peak (1/km), centre height (km)
    vec4 ground;         // albedo rgb, ozone half width (km)
    vec4 radii;          // bottom radius (km), top radius (km), sun angular radius (rad),
                         // solar illuminance outside the atmosphere (lux)
};

float atmosphereBottom(AtmosphereParameters a) { return a.radii.x; }
float atmosphereTop(AtmosphereParameters a) { return a.radii.y; }

// Density profiles at altitude h (km), relative to sea level.
float rayleighDensity(AtmosphereParameters a, float h) { return exp(-h / a.rayleigh.w); }
float mieDensity(AtmosphereParameters a, float h) { return exp(-h / a.mie.w); }
float ozoneDensity(AtmosphereParameters a, float h) {
    return max(0.0, 1.0 - abs(h - a.ozone.w) / a.ground.w);
}

struct MediumSample {
    vec3 scatteringRayleigh;
    vec3 scatteringMie;
    vec3 scattering;  // both
    vec3 extinction;  // scattering + Mie and ozone absorption
};

MediumSample sampleMedium(AtmosphereParameters a, float h) {
    float dr = rayleighDensity(a, h);
    float dm = mieDensity(a, h);
    float dozone = ozoneDensity(a, h);
    MediumSample m;
    m.scatteringRayleigh = a.rayleigh.rgb * dr;
    m.scatteringMie = a.mie.rgb * dm;
    m.scattering = m.scatteringRayleigh + m.scatteringMie;
    m.extinction = m.scattering + a.mieAbsorption.rgb * dm + a.ozone.rgb * dozone;
    return m;
}

vec3 extinctionAt(AtmosphereParameters a, float h) { return sampleMedium(a, h).extinction; }

// Phase functions (1/sr) of the angle between the light's travel and the view ray reversed:
// cosTheta = dot(toward the sun, view direction).
float rayleighPhase(float cosTheta) {
    return 3.0 / (16.0 * PI) * (1.0 + cosTheta * cosTheta);
}
// Cornette-Shanks (Hillaire 2020 uses it for Mie): Henyey-Greenstein with Rayleigh's
// (1 + cos^2) and normalised.
float miePhase(float g, float cosTheta) {
    float g2 = g * g;
    float k = 3.0 / (8.0 * PI) * (1.0 - g2) / (2.0 + g2);
    return k * (1.0 + cosTheta * cosTheta) / pow(max(1.0 + g2 - 2.0 * g * cosTheta, 1e-6), 1.5);
}

// From radius r with cosine mu of the ray's zenith angle: the distance to the sphere of
// radius R along the ray, the far intersection (for R >= r), or the near one (R < r).
float distanceToSphereExit(float r, float mu, float R) {
    float discriminant = r * r * (mu * mu - 1.0) + R * R;
    return max(-r * mu + sqrt(max(discriminant, 0.0)), 0.0);
}
float distanceToSphereEntry(float r, float mu, float R) {
    float discriminant = r * r * (mu * mu - 1.0) + R * R;
    return max(-r * mu - sqrt(max(discriminant, 0.0)), 0.0);
}
bool rayHitsGround(AtmosphereParameters a, float r, float mu) {
    float rb = atmosphereBottom(a);
    return mu < 0.0 && r * r * (mu * mu - 1.0) + rb * rb >= 0.0;
}
float distanceToTop(AtmosphereParameters a, float r, float mu) {
    return distanceToSphereExit(r, mu, atmosphereTop(a));
}
// Where the ray leaves the atmosphere or meets the ground.
float distanceToBoundary(AtmosphereParameters a, float r, float mu) {
    return rayHitsGround(a, r, mu) ? distanceToSphereEntry(r, mu, atmosphereBottom(a))
                                   : distanceToTop(a, r, mu);
}

// Radius and zenith cosine after travelling t along a ray starting at (r, mu).
float radiusAfter(float r, float mu, float t) {
    return sqrt(max(t * t + 2.0 * r * mu * t + r * r, 0.0));
}

// exp(-integral of extinction) from radius r along zenith cosine mu to the top of the
// atmosphere (ground ignored: the tables' convention; callers test rayHitsGround), midpoint
// rule with `steps` samples in x = sqrt(t / length): the samples crowd where the ray starts,
// low in the densest air, where a slanted ray leaves the Mie layer (1.2 km) within a few
// kilometres: 40 uniform samples were 3.1e-3 off the double integral there, 40 of these are
// 6.7e-4 off at worst (a ray from 99 km down past a 26 km perigee) and the table's 64 are
// 2.3e-4 (AtmosphereTransmittance in the stability tests). What the table stores per texel.
vec3 transmittanceToTop(AtmosphereParameters a, float r, float mu, int steps) {
    float length = distanceToTop(a, r, mu);
    vec3 opticalDepth = vec3(0.0);
    for (int i = 0; i < steps; ++i) {
        float x0 = float(i) / float(steps), x1 = float(i + 1) / float(steps);
        float xm = 0.5 * (x0 + x1);
        float t = length * xm * xm;
        float dt = length * (x1 * x1 - x0 * x0);
        float h = radiusAfter(r, mu, t) - atmosphereBottom(a);
        opticalDepth += extinctionAt(a, h) * dt;
    }
    return exp(-opticalDepth);
}

// ---- The transmittance table (Bruneton 2017's parameterisation, which Hillaire 2020 keeps):
// u maps the distance to the top between its minimum and maximum for r, v maps the distance to
// the horizon, so texels crowd near the horizon and the ground. Texel centres at 0 and 1.
float unitToTexelCentre(float x, float size) { return 0.5 / size + x * (1.0 - 1.0 / size); }
float texelCentreToUnit(float u, float size) { return (u - 0.5 / size) / (1.0 - 1.0 / size); }

vec2 transmittanceUv(AtmosphereParameters a, float r, float mu, vec2 size) {
    float rb = atmosphereBottom(a), rt = atmosphereTop(a);
    float H = sqrt(max(rt * rt - rb * rb, 0.0));
    float rho = sqrt(max(r * r - rb * rb, 0.0));
    float d = distanceToTop(a, r, mu);
    float dMin = rt - r;
    float dMax = rho + H;
    float xMu = (d - dMin) / max(dMax - dMin, 1e-6);
    float xR = rho / H;
    return vec2(unitToTexelCentre(xMu, size.x), unitToTexelCentre(xR, size.y));
}

// The inverse: the (r, mu) a texel stands for.
void transmittanceRadiusMu(AtmosphereParameters a, vec2 uv, vec2 size, out float r,
                           out float mu) {
    float xMu = texelCentreToUnit(uv.x, size.x);
    float xR = texelCentreToUnit(uv.y, size.y);
    float rb = atmosphereBottom(a), rt = atmosphereTop(a);
    float H = sqrt(max(rt * rt - rb * rb, 0.0));
    float rho = H * xR;
    r = sqrt(rho * rho + rb * rb);
    float dMin = rt - r;
    float dMax = rho + H;
    float d = dMin + xMu * (dMax - dMin);
    mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * r * d);
    mu = clamp(mu, -1.0, 1.0);
}

// ---- The multiple-scattering table (Hillaire 2020 section 5.5): u = mu_sun * 0.5 + 0.5,
// v = altitude / atmosphere thickness.
vec2 multipleScatteringUv(AtmosphereParameters a, float r, float muSun, vec2 size) {
    float x = muSun * 0.5 + 0.5;
    float y = (r - atmosphereBottom(a)) / (atmosphereTop(a) - atmosphereBottom(a));
    return vec2(unitToTexelCentre(saturate(x), size.x), unitToTexelCentre(saturate(y), size.y));
}

// ---- The sky-view table (Hillaire 2020 section 5.3): longitude relative to the sun (0..pi,
// the sky is symmetric about the sun's vertical plane) squared towards the sun; latitude split
// at the horizon, each half squared towards it, where the sky changes fastest.
// viewZenith: the view ray's angle from the zenith (0..pi); sunLongitude: its azimuth from the
// sun's (0..pi).
vec2 skyViewUv(AtmosphereParameters a, float r, float viewZenith, float sunLongitude, vec2 size) {
    float rb = atmosphereBottom(a);
    float horizonCos = sqrt(max(r * r - rb * rb, 0.0)) / r;
    float beta = acos(clamp(horizonCos, -1.0, 1.0));  // below the horizontal to the horizon
    float zenithToHorizon = PI - beta;
    float v;
    if (viewZenith < zenithToHorizon) {
        float x = saturate(viewZenith / zenithToHorizon);
        v = 0.5 * (1.0 - sqrt(1.0 - x));
    } else {
        float x = saturate((viewZenith - zenithToHorizon) / beta);
        v = 0.5 + 0.5 * sqrt(x);
    }
    float u = sqrt(saturate(sunLongitude / PI));
    return vec2(unitToTexelCentre(u, size.x), unitToTexelCentre(v, size.y));
}

void skyViewAngles(AtmosphereParameters a, float r, vec2 uv, vec2 size, out float viewZenith,
                   out float sunLongitude) {
    float u = texelCentreToUnit(uv.x, size.x);
    float v = texelCentreToUnit(uv.y, size.y);
    float rb = atmosphereBottom(a);
    float horizonCos = sqrt(max(r * r - rb * rb, 0.0)) / r;
    float beta = acos(clamp(horizonCos, -1.0, 1.0));
    float zenithToHorizon = PI - beta;
    if (v < 0.5) {
        float x = 1.0 - 2.0 * v;
        viewZenith = zenithToHorizon * (1.0 - x * x);
    } else {
        float x = 2.0 * v - 1.0;
        viewZenith = zenithToHorizon + beta * x * x;
    }
    sunLongitude = u * u * PI;
}

// Transmittance from radius r along zenith cosine mu to the top, read from the table.
vec3 transmittanceFromTable(sampler2D table, AtmosphereParameters a, float r, float mu) {
    vec2 size = vec2(textureSize(table, 0));
    return textureLod(table, transmittanceUv(a, r, mu, size), 0.0).rgb;
}

// The sky-view table's radiance for world direction `view` seen from radius r, the sun towards
// `towardSun` (both unit, +Y up).
vec3 skyRadianceFromTable(sampler2D table, AtmosphereParameters a, float r, vec3 view,
                          vec3 towardSun) {
    vec2 size = vec2(textureSize(table, 0));
    float viewZenith = acos(clamp(view.y, -1.0, 1.0));
    vec2 horizontalView = safeNormalize(vec3(view.x, 0.0, view.z)).xz;
    vec2 horizontalSun = safeNormalize(vec3(towardSun.x, 0.0, towardSun.z)).xz;
    float cosLongitude = dot(horizontalView, horizontalSun);
    if (dot(horizontalView, horizontalView) == 0.0 || dot(horizontalSun, horizontalSun) == 0.0)
        cosLongitude = 0.0;
    float sunLongitude = acos(clamp(cosLongitude, -1.0, 1.0));
    return textureLod(table, skyViewUv(a, r, viewZenith, sunLongitude, size), 0.0).rgb;
}

// The sun outside the atmosphere: illuminance (lux) per linear sRGB channel, white.
vec3 solarIlluminance(AtmosphereParameters a) { return vec3(a.radii.w); }
// Its disc's radiance (cd/m^2): the illuminance spread over the disc's solid angle.
vec3 solarDiscRadiance(AtmosphereParameters a) {
    float s = sin(a.radii.z);
    return solarIlluminance(a) / (PI * s * s);
}

#endif
