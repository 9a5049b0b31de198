#version 460
#extension GL_GOOGLE_include_directive : require
#include "volumetrics_bindings.h"
// Per-light volumes, rasterised (Vos 2014, GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow
// Fall"): one instance per light, its proxy mesh (light_proxy_mesh.glsl) placed over its volume.
// The light's index comes from the instance list (light_proxies.h); push.lights.z says which mesh
// this draw makes.
#include "common/camera.glsl"
#include "common/light_buffer.glsl"
#include "light_proxy_mesh.glsl"
#include "volumetrics_push.glsl"

layout(std430, binding = VOLUMETRICS_BINDING_PROXY_INSTANCES) readonly buffer ProxyInstances {
    uint proxyLights[];
};

layout(location = 0) flat out uint lightIndex;

void main() {
    lightIndex = proxyLights[gl_InstanceIndex];
    Light light = loadLight(lightIndex, push.lights.y);
    float range = 1.0 / light.invAttenuationRadius;  // local lights: a positive range
    vec3 world;
    if (push.lights.z == kProxyCone) {
        // The spot's volume (its range sphere cut by its cone) lies in the cone cut at the
        // range along its axis. light_proxies.cpp sends cones of 70 degrees and wider as spheres.
        float cosOuter = -light.spotOffset / light.spotScale;
        float radius = range * sqrt(max(1.0 - cosOuter * cosOuter, 0.0)) / cosOuter;
        vec3 w = light.direction;
        vec3 helper = abs(w.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 u = normalize(cross(w, helper));
        vec3 v = cross(w, u);  // u, v, w right-handed: the mesh keeps its winding
        vec3 local = coneProxyVertex(uint(gl_VertexIndex), range, radius);
        world = light.position + local.x * u + local.y * v + local.z * w;
    } else if (push.lights.z == kProxyHemisphere) {
        // A rect or disk light emits into the half-space in front of it only (its form factor
        // is zero behind its plane: volumetric_medium.glsl's areaLightIrradiance), so its
        // volume is the half of its range sphere there; the mesh's +y along the light's normal.
        vec3 n = normalize(light.direction);
        vec3 helper = abs(n.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 u = normalize(cross(n, helper));
        vec3 v = cross(u, n);  // u, n, v right-handed, as x, y, z: the mesh keeps its winding
        vec3 local = hemisphereProxyVertex(uint(gl_VertexIndex));
        world = light.position + range * (local.x * u + local.y * n + local.z * v);
    } else {
        world = light.position + range * sphereProxyVertex(uint(gl_VertexIndex));
    }
    // The unjittered projection, as the rays the fragments march (volumetric_view_ray.glsl).
    gl_Position = camera.unjitteredViewProjection * vec4(world, 1.0);
}
