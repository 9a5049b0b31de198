#pragma once
// The spelling of every enum in scene files, shared by the reader and the writer so the two
// cannot drift apart.
#include <array>
#include <string_view>
#include <utility>

#include "candela/content/components/camera.h"
#include "candela/content/components/light.h"
#include "candela/content/light_types.h"
#include "candela/content/material.h"
#include "candela/content/scene_file.h"

namespace candela::content::scene {

inline constexpr std::string_view kFormatName = "candela.scene";

template <typename E, std::size_t N>
using EnumNames = std::array<std::pair<E, std::string_view>, N>;

// From the light type table (content/light_types.h).
inline constexpr EnumNames<LightType, kLightTypeCount> kLightTypes = [] {
    EnumNames<LightType, kLightTypeCount> names{};
    for (std::size_t i = 0; i < kLightTypeCount; ++i)
        names[i] = {kLightTypeTable[i].type, kLightTypeTable[i].name};
    return names;
}();
// An area light's "quality"; absent means the renderer's default (AreaLightQuality::Default).
inline constexpr EnumNames<AreaLightQuality, 2> kAreaLightQualities{
    {{AreaLightQuality::Representative, "representative"}, {AreaLightQuality::Ltc, "ltc"}}};
// A rect or disk light's "emission"; absent means Lambertian.
inline constexpr EnumNames<AreaLightEmission, 2> kAreaLightEmissions{
    {{AreaLightEmission::Lambertian, "lambertian"},
     {AreaLightEmission::ConstantIntensity, "constantIntensity"}}};
inline constexpr EnumNames<Projection, 2> kProjections{
    {{Projection::Perspective, "perspective"}, {Projection::Orthographic, "orthographic"}}};
inline constexpr EnumNames<ExposureMode, 2> kExposureModes{
    {{ExposureMode::Physical, "physical"}, {ExposureMode::Manual, "manual"}}};
inline constexpr EnumNames<ShadingModel, 4> kShadingModels{
    {{ShadingModel::DefaultLit, "defaultLit"},
     {ShadingModel::Subsurface, "subsurface"},
     {ShadingModel::Legacy, "legacy"},
     {ShadingModel::Unlit, "unlit"}}};
inline constexpr EnumNames<AlphaMode, 3> kAlphaModes{
    {{AlphaMode::Opaque, "opaque"}, {AlphaMode::Mask, "mask"}, {AlphaMode::Blend, "blend"}}};
inline constexpr EnumNames<LayerMaskSource, 2> kLayerMaskSources{
    {{LayerMaskSource::Texture, "texture"}, {LayerMaskSource::VertexColor, "vertexColor"}}};
inline constexpr EnumNames<ColorSpace, 2> kColorSpaces{
    {{ColorSpace::Srgb, "srgb"}, {ColorSpace::Linear, "linear"}}};

inline constexpr EnumNames<BodyType, 3> kBodyTypes{{{BodyType::Static, "static"},
                                                    {BodyType::Dynamic, "dynamic"},
                                                    {BodyType::Kinematic, "kinematic"}}};
inline constexpr EnumNames<ColliderShape, 6> kColliderShapes{
    {{ColliderShape::Sphere, "sphere"},
     {ColliderShape::Box, "box"},
     {ColliderShape::Capsule, "capsule"},
     {ColliderShape::Cylinder, "cylinder"},
     {ColliderShape::ConvexHull, "convexHull"},
     {ColliderShape::TriangleMesh, "triangleMesh"}}};

inline constexpr EnumNames<QualityLevel, 4> kQualityLevelNames{{{QualityLevel::Low, "low"},
                                                                {QualityLevel::Medium, "medium"},
                                                                {QualityLevel::High, "high"},
                                                                {QualityLevel::Ultra, "ultra"}}};

template <typename E, std::size_t N>
std::string_view nameOf(const EnumNames<E, N>& names, E value) {
    for (const auto& [v, name] : names) {
        if (v == value) return name;
    }
    return names[0].second;
}

}  // namespace candela::content::scene
