#version 460
#extension GL_GOOGLE_include_directive : require
// Deferred lighting: reads the G-buffer and every light (brute force until clustered culling
// replaces the list), adds the lit radiance to the HDR target that holds emissive already.
#include "common/camera.glsl"
#include "common/shading_models.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 1) readonly buffer Lights { Light lights[]; };
layout(binding = 2) uniform sampler2D gbufferBaseColor;
layout(binding = 3) uniform sampler2D gbufferNormalRoughMetal;
layout(binding = 4) uniform sampler2D gbufferSpecularModel;
layout(binding = 5) uniform sampler2D gbufferCustomData;
layout(binding = 6) uniform sampler2D gbufferDepth;
layout(binding = 7, rgba32f) uniform image2D hdrRadiance;

Surface decodeSurface(ivec2 pixel, out vec3 N) {
    vec4 gb0 = texelFetch(gbufferBaseColor, pixel, 0);
    vec4 gb1 = texelFetch(gbufferNormalRoughMetal, pixel, 0);
    vec4 gb2 = texelFetch(gbufferSpecularModel, pixel, 0);
    Surface s;
    s.baseColor = gb0.rgb;
    s.roughness = gb1.z;
    s.metallic = gb1.w;
    s.specular = gb2.r;
    s.shadingModel = uint(gb2.g * 255.0 + 0.5);
    s.customData = texelFetch(gbufferCustomData, pixel, 0);
    N = octDecode(gb1.xy);
    return s;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uvec2 size = camera.frameInfo.xy;
    if (pixel.x >= int(size.x) || pixel.y >= int(size.y)) return;
    float depth = texelFetch(gbufferDepth, pixel, 0).r;
    if (depth <= 0.0) return;  // background (reverse-Z: 0 is infinitely far)

    vec3 N;
    Surface s = decodeSurface(pixel, N);
    if (s.shadingModel == kShadingUnlit) return;

    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 world = camera.inverseViewProjection * vec4(ndc, depth, 1.0);
    vec3 P = world.xyz / world.w;
    vec3 V = safeNormalize(camera.cameraPosition.xyz - P);
    vec3 R = reflect(-V, N);
    float alpha = alphaFromRoughness(s.roughness);

    vec3 radiance = vec3(0.0);
    uint lightCount = camera.frameInfo.z;
    for (uint i = 0u; i < lightCount; ++i) {
        Light light = lights[i];
        LightIncidence incidence;
        if (light.type == kLightDirectional) {
            incidence = evaluateDirectionalLight(light, N);
        } else {
            incidence = evaluateLocalLight(light, P, N, R, alpha);
        }
        radiance += shadeSurface(s, N, V, incidence);
    }
    vec4 previous = imageLoad(hdrRadiance, pixel);
    imageStore(hdrRadiance, pixel, vec4(previous.rgb + radiance, 1.0));
}
