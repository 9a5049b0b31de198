#include "renderer_scene_queries.h"

#include <algorithm>
#include <bit>

#include "candela/render/scene_resources.h"
#include "lights/gpu_light_types.h"

namespace candela::render {

uint32_t areaLightPathsOf(const content::Light& light, AreaLightMode renderersDefault) {
    const bool ltc = light.quality == content::AreaLightQuality::Ltc ||
                     (light.quality == content::AreaLightQuality::Default &&
                      renderersDefault == AreaLightMode::Ltc);
    if (light.type == content::LightType::Rect || light.type == content::LightType::Disk) {
        uint32_t paths = ltc ? AREA_PATH_LTC : AREA_PATH_REPRESENTATIVE;
        if (light.type == content::LightType::Rect && light.texture != 0) {
            paths |= AREA_PATH_TEXTURED;
        }
        if (light.emission == content::AreaLightEmission::ConstantIntensity) {
            paths |= AREA_PATH_CONSTANT_INTENSITY;
        }
        return paths;
    }
    // A sphere or tube (NaN sizes are none, as on the GPU).
    const bool sized = light.sourceRadius > 0.0f || light.sourceLength > 0.0f;
    return sized && ltc ? AREA_PATH_PUNCTUAL_LTC : 0u;
}

LightingFeatures featuresOf(const FrameScene& scene, const SceneResources& resources,
                            const RendererOptions& options) {
    LightingFeatures f;
    f.clustered = options.lightCulling == LightCulling::Clustered;
    f.countLightPairs = options.countLightPairs;
    f.brdf = options.brdf;
    f.areaLights = options.areaLights;
    // A power of two up to 16: each cell one texel of a level of the image's 256-texel chain.
    f.areaTextureCells = std::bit_floor(std::clamp(options.areaTextureCells, 1u, 16u));
    f.softShadows = options.softShadows;
    f.hardShadowTapsPerAxis = options.shadowHardTapsPerAxis;
    if (resources.environment()) f.ibl = options.ibl;
    // Occlusion of the sky's light: nothing to occlude without a sky.
    if (f.ibl) f.ao = options.ao;
    f.aoSpecularFromHorizons = options.aoSettings.specular == AoSpecular::HorizonSlice;
    for (const DrawItem& draw : scene.draws) {
        const content::Material& material = resources.material(draw.material);
        if (material.alphaMode != content::AlphaMode::Blend) {
            f.anisotropy |= material.anisotropic();
            f.clearCoat |= material.clearCoated();
        }
        switch (material.shadingModel) {
            case content::ShadingModel::Subsurface:
                f.subsurface = true;
                break;
            case content::ShadingModel::Legacy:
                f.legacyDiffuseSpecular = true;
                break;
            default:
                break;
        }
    }
    f.areaLightPaths = 0;
    for (const LightInstance& l : scene.lights) {
        if (inEveryCluster(l.light)) continue;
        f.sphereLights |= l.light.sourceRadius > 0.0f;
        f.tubeLights |= l.light.sourceLength > 0.0f;
        f.lightTypes |= LightingFeatures::bit(l.light.type);
        f.areaLightPaths |= areaLightPathsOf(l.light, options.areaLights);
    }
    return f;
}

bool hasWireSegments(const FrameScene& scene) {
    return std::any_of(scene.wires.begin(), scene.wires.end(), [](const WireDraw& draw) {
        return draw.wire && draw.wire->segments.size() >= 2;
    });
}

bool scatteringDrawn(const FrameScene& scene, ScatteringMode mode) {
    return scene.atmosphere && mode != ScatteringMode::Off &&
           std::any_of(scene.lights.begin(), scene.lights.end(), [](const LightInstance& l) {
               return l.light.type == content::LightType::Directional;
           });
}

bool hasGlossySurface(const FrameScene& scene, const SceneResources& resources, float cutoff) {
    for (const DrawItem& draw : scene.draws) {
        const content::Material& m = resources.material(draw.material);
        if (m.alphaMode == content::AlphaMode::Blend ||
            m.shadingModel == content::ShadingModel::Unlit) {
            continue;
        }
        if (m.roughnessFactor < cutoff || m.metallicRoughnessTexture.present()) return true;
        for (const content::MaterialLayer& layer : m.layering.layers) {
            if (layer.roughnessFactor < cutoff || layer.metallicRoughnessTexture.present()) {
                return true;
            }
        }
    }
    return false;
}

bool usesMaterialLayers(const FrameScene& scene, const SceneResources& resources) {
    for (const DrawItem& draw : scene.draws) {
        const content::Material& material = resources.material(draw.material);
        if (material.alphaMode != content::AlphaMode::Blend &&
            material.layering.layers.size() > 1) {
            return true;
        }
    }
    return false;
}

}  // namespace candela::render
