// The per-light volumes' proxy meshes (Vos 2014, GPU Pro 5, "Volumetric Light Effects in Killzone:
// Shadow Fall": each light renders its volume, a sphere for a point light, a cone for a spot, a
// hemisphere for a one-sided rect or disk light), made in the vertex shader from gl_VertexIndex: no
// vertex buffer. Both enclose the volume they stand for (their flat faces lie outside the curved
// surface), so every pixel whose ray meets the volume is covered; the fragment shader then
// marches the ray's exact segment (light_volume.glsl). Triangles wind counter-clockwise seen from
// outside, as glTF's do, so culling back faces draws the near side.
#ifndef CANDELA_LIGHT_PROXY_MESH_GLSL
#define CANDELA_LIGHT_PROXY_MESH_GLSL

#include "common/math.glsl"

// Matches LightProxyKind and the vertex counts in light_proxies.h.
const uint kProxySphere = 0u;
const uint kProxyCone = 1u;
const uint kProxyHemisphere = 2u;
const uint kSphereSegments = 8u;  // around
const uint kSphereRings = 6u;     // pole to pole
const uint kConeSegments = 12u;

// A unit sphere's quad grid, each face pushed out past the sphere: a flat face between
// neighbouring grid points dips to cos(pi / n) of the radius across each of the two directions.
vec3 sphereProxyVertex(uint vertex) {
    const uint corners[6] = uint[6](0u, 1u, 2u, 0u, 2u, 3u);
    uint quad = vertex / 6u;
    uint corner = corners[vertex % 6u];
    uint ring = quad / kSphereSegments + ((corner == 1u || corner == 2u) ? 1u : 0u);
    uint segment = quad % kSphereSegments + ((corner == 2u || corner == 3u) ? 1u : 0u);
    float theta = PI * float(ring) / float(kSphereRings);
    float phi = 2.0 * PI * float(segment) / float(kSphereSegments);
    float outward = 1.0 / (cos(PI / float(kSphereSegments)) * cos(PI / float(kSphereRings)));
    return outward * vec3(sin(theta) * cos(phi), cos(theta), -sin(theta) * sin(phi));
}

// The half of sphereProxyVertex's mesh with y >= 0 (its first kSphereRings / 2 rings of quads:
// the equator ring lies at y = 0), closed by a flat cap in the plane y = 0 (a fan about the
// centre, facing -y). It encloses the half-ball y >= 0: the sphere's polytope cut by that plane.
vec3 hemisphereProxyVertex(uint vertex) {
    const uint kQuadVertices = kSphereSegments * (kSphereRings / 2u) * 6u;
    if (vertex < kQuadVertices) return sphereProxyVertex(vertex);
    uint triangle = (vertex - kQuadVertices) / 3u;
    uint corner = (vertex - kQuadVertices) % 3u;
    if (corner == 0u) return vec3(0.0);
    // Centre, ring k + 1, ring k: counter-clockwise seen from below (-y), outward as the
    // sphere's quads are (the ring runs (cos phi, 0, -sin phi), counter-clockwise from above).
    uint k = triangle + (corner == 1u ? 1u : 0u);
    float phi = 2.0 * PI * float(k) / float(kSphereSegments);
    float outward = 1.0 / (cos(PI / float(kSphereSegments)) * cos(PI / float(kSphereRings)));
    return outward * vec3(cos(phi), 0.0, -sin(phi));
}

// A cone with its apex at the origin along +z, `length` deep and `radius` wide at its flat
// base (the polygon around the base circle): side triangles, then the base cap.
vec3 coneProxyVertex(uint vertex, float length, float radius) {
    uint triangle = vertex / 3u;
    uint corner = vertex % 3u;
    uint segment = triangle % kConeSegments;
    bool cap = triangle >= kConeSegments;
    float around = radius / cos(PI / float(kConeSegments));
    // Side: apex, ring k + 1, ring k; cap: centre, ring k, ring k + 1 (both outward).
    if (corner == 0u) return cap ? vec3(0.0, 0.0, length) : vec3(0.0);
    uint k = segment + ((corner == 1u) != cap ? 1u : 0u);
    float phi = 2.0 * PI * float(k) / float(kConeSegments);
    return vec3(around * cos(phi), around * sin(phi), length);
}

#endif
