// The segment of a view ray inside a light's volume (Vos 2014, GPU Pro 5, "Volumetric Light Effects
// in Killzone: Shadow Fall": each light renders its volume, a sphere for a point light, a cone for
// a spot, the whole screen for the sun). The per-light volumes march only that segment.
#ifndef CANDELA_LIGHT_VOLUME_GLSL
#define CANDELA_LIGHT_VOLUME_GLSL

#include "common/lights.glsl"

// Whether P is inside the spot's cone (apex at the light, half-angle acos(cosOuter)).
bool insideCone(Light light, float cosOuter, vec3 P) {
    vec3 d = P - light.position;
    float along = dot(d, light.direction);
    return along >= 0.0 && along * along >= cosOuter * cosOuter * dot(d, d);
}

// The ray's segment inside a spot's volume: its range sphere cut by its cone. A cone of
// half-angle under 90 degrees is convex, and so is its intersection with the sphere, so the
// segment is one interval: the sphere's chord split at the ray's crossings of the cone
// surface, keeping the pieces whose midpoints are inside.
vec2 raySpotSegment(Light light, vec3 origin, vec3 direction, vec2 chord) {
    // spotAttenuation is zero where cos(angle) * spotScale + spotOffset <= 0.
    float cosOuter = light.spotScale > 0.0 ? -light.spotOffset / light.spotScale : -1.0;
    if (cosOuter <= 0.0) return chord;  // a cone of 90 degrees or more: the sphere bounds it
    vec3 v = origin - light.position;
    float dn = dot(direction, light.direction);
    float vn = dot(v, light.direction);
    float c2 = cosOuter * cosOuter;
    // (vn + t dn)^2 - c2 |v + t d|^2 = 0
    float a = dn * dn - c2;
    float b = 2.0 * (dn * vn - c2 * dot(v, direction));
    float c = vn * vn - c2 * dot(v, v);
    float cuts[4] = float[4](chord.x, chord.y, chord.y, chord.y);
    if (abs(a) > 1e-8) {
        float h = b * b - 4.0 * a * c;
        if (h > 0.0) {
            h = sqrt(h);
            float r0 = (-b - h) / (2.0 * a), r1 = (-b + h) / (2.0 * a);
            cuts[1] = clamp(min(r0, r1), chord.x, chord.y);
            cuts[2] = clamp(max(r0, r1), chord.x, chord.y);
        }
    } else if (abs(b) > 1e-8) {
        cuts[1] = clamp(-c / b, chord.x, chord.y);
        cuts[2] = cuts[1];
    }
    vec2 inside = vec2(chord.y, chord.x);
    for (int i = 0; i < 3; ++i) {
        if (cuts[i + 1] <= cuts[i]) continue;
        if (insideCone(light, cosOuter, origin + direction * (0.5 * (cuts[i] + cuts[i + 1])))) {
            inside.x = min(inside.x, cuts[i]);
            inside.y = max(inside.y, cuts[i + 1]);
        }
    }
    return inside;
}

// The ray's segment in the light's volume, within [0, farT]; enter >= exit when it misses.
vec2 lightVolumeSegment(Light light, vec3 origin, vec3 direction, float farT) {
    if (light.type == kLightDirectional) return vec2(0.0, farT);
    float radius = light.invAttenuationRadius > 0.0 ? 1.0 / light.invAttenuationRadius : 1e6;
    vec2 chord = raySphereSegment(origin, direction, light.position, radius);
    chord = vec2(max(chord.x, 0.0), min(chord.y, farT));
    if (chord.x >= chord.y) return chord;
    if (light.type == kLightSpot) return raySpotSegment(light, origin, direction, chord);
    return chord;
}

#endif
