// Small numeric helpers every shader shares.
#ifndef CANDELA_MATH_GLSL
#define CANDELA_MATH_GLSL

const float PI = 3.14159265358979;

float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec3 saturate(vec3 x) { return clamp(x, vec3(0.0), vec3(1.0)); }

// normalize() of a zero vector is NaN; this returns zero instead, so degenerate geometry
// (a light at the shaded point, V == -L) contributes nothing rather than poisoning a pixel.
vec3 safeNormalize(vec3 v) {
    return v * inversesqrt(max(dot(v, v), 1e-30));
}

// Octahedral normal encoding into [0, 1]^2 (Meyer et al. 2010), for the G-buffer.
vec2 octEncode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = n.xy;
    if (n.z < 0.0) p = (1.0 - abs(n.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    return p * 0.5 + 0.5;
}

vec3 octDecode(vec2 e) {
    vec2 f = e * 2.0 - 1.0;
    vec3 n = vec3(f, 1.0 - abs(f.x) - abs(f.y));
    float t = saturate(-n.z);
    n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    return safeNormalize(n);
}

// Orthonormal basis with N as +Z (Frisvad's construction, revised for N.z near -1).
mat3 tangentFrame(vec3 N) {
    float s = N.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + N.z);
    float b = N.x * N.y * a;
    vec3 t = vec3(1.0 + s * N.x * N.x * a, s * b, -s * N.x);
    vec3 bt = vec3(b, s + N.y * N.y * a, -N.y);
    return mat3(t, bt, N);
}

// Where the ray origin + t * direction (direction unit) is inside the sphere: (enter, exit),
// enter >= exit when it misses.
vec2 raySphereSegment(vec3 origin, vec3 direction, vec3 centre, float radius) {
    vec3 oc = origin - centre;
    float b = dot(oc, direction);
    float h = b * b - (dot(oc, oc) - radius * radius);
    if (h <= 0.0) return vec2(1.0, 0.0);
    h = sqrt(h);
    return vec2(-b - h, -b + h);
}

#endif
