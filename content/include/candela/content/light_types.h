#pragma once
// The content side of "one place per light type" (render/README.md "Adding a light type"):
// what each LightType is called in scene files and glTF, which Light fields it uses, and how
// every field is named, checked and edited. The scene reader and writer, the glTF importer,
// validateLight and the editor's inspector, property edits and gizmo read these tables instead
// of switching on the type. The render side's table is render/src/lights/gpu_light_types.h.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "candela/content/component_validation.h"
#include "candela/content/components/light.h"
#include "candela/content/light_units.h"

namespace candela::content {

// Every Light field a light type may use, in the order scene files list them.
enum class LightField : std::uint8_t {
    Color,
    Lumens,
    Lux,
    AttenuationRadius,
    SourceRadius,
    SourceLength,
    InnerConeAngle,
    OuterConeAngle,
    Width,
    Height,
    Volumetric,
};

// How validateLight checks a field (the editor's limits follow from it too).
enum class LightFieldRule : std::uint8_t {
    ColorChannels,      // every channel finite and >= 0, capped at `max`
    NonNegative,        // >= 0, capped at `max`
    Positive,           // > 0, capped at `max` (+Inf becomes the cap)
    FiniteNonNegative,  // finite and >= 0, capped at `max` when it is above 0
    ConeAngle,          // radians; inner and outer checked together, for types that use both
};

enum class LightFieldWidget : std::uint8_t { Color, Drag, Angle };

struct LightFieldInfo {
    LightField field;
    const char* name;       // key in scene files, glTF extras and the editor's property edits
    std::string_view unit;  // of the value, in messages ("lm"; empty for colour)
    LightFieldRule rule;
    float max;  // the cap of the capping rules
    // Editor inspector: label, undo label, widget and its drag speed, range and format.
    const char* label;
    const char* undoLabel;
    LightFieldWidget widget;
    float dragSpeed, dragMin, dragMax;
    const char* format;
    bool gltfExtra;  // read from a KHR_lights_punctual light's extras (engine extension)
    // The member: `scalar` for one number, `channels` for colour.
    float Light::*scalar;
    std::array<float, 3> Light::*channels;
};

inline constexpr std::array<LightFieldInfo, 11> kLightFieldTable{{
    {LightField::Color, "color", "", LightFieldRule::ColorChannels, kMaxLightColorChannel, "Colour",
     "Set Light Colour", LightFieldWidget::Color, 0, 0, 0, "", false, nullptr, &Light::color},
    {LightField::Lumens, "lumens", "lm", LightFieldRule::NonNegative, kMaxLumens, "Lumens",
     "Set Lumens", LightFieldWidget::Drag, 10.0f, 0.0f, 1.0e7f, "%.1f lm", false, &Light::lumens,
     nullptr},
    {LightField::Lux, "lux", "lux", LightFieldRule::NonNegative, kMaxLux, "Lux", "Set Lux",
     LightFieldWidget::Drag, 100.0f, 0.0f, 1.0e6f, "%.1f lx", false, &Light::lux, nullptr},
    {LightField::AttenuationRadius, "attenuationRadius", "m", LightFieldRule::Positive,
     kMaxAttenuationRadius, "Attenuation radius", "Set Attenuation Radius", LightFieldWidget::Drag,
     0.05f, 0.01f, 1.0e4f, "%.2f m", false, &Light::attenuationRadius, nullptr},
    {LightField::SourceRadius, "sourceRadius", "m", LightFieldRule::FiniteNonNegative,
     kMaxAreaLightSize, "Source radius", "Set Source Radius", LightFieldWidget::Drag, 0.005f, 0.0f,
     100.0f, "%.3f m", true, &Light::sourceRadius, nullptr},
    {LightField::SourceLength, "sourceLength", "m", LightFieldRule::FiniteNonNegative,
     kMaxAreaLightSize, "Source length", "Set Source Length", LightFieldWidget::Drag, 0.01f, 0.0f,
     100.0f, "%.3f m", true, &Light::sourceLength, nullptr},
    {LightField::InnerConeAngle, "innerConeAngle", "rad", LightFieldRule::ConeAngle, 0,
     "Inner cone", "Set Inner Cone", LightFieldWidget::Angle, 0, 0.0f, 90.0f, "", false,
     &Light::innerConeAngle, nullptr},
    {LightField::OuterConeAngle, "outerConeAngle", "rad", LightFieldRule::ConeAngle, 0,
     "Outer cone", "Set Outer Cone", LightFieldWidget::Angle, 0, 0.0f, 90.0f, "", false,
     &Light::outerConeAngle, nullptr},
    {LightField::Width, "width", "m", LightFieldRule::Positive, kMaxAreaLightSize, "Width",
     "Set Width", LightFieldWidget::Drag, 0.01f, 0.001f, 100.0f, "%.3f m", true, &Light::width,
     nullptr},
    {LightField::Height, "height", "m", LightFieldRule::Positive, kMaxAreaLightSize, "Height",
     "Set Height", LightFieldWidget::Drag, 0.01f, 0.001f, 100.0f, "%.3f m", true, &Light::height,
     nullptr},
    {LightField::Volumetric, "volumetric", "", LightFieldRule::NonNegative, kMaxVolumetricScale,
     "Volumetric", "Set Volumetric Scale", LightFieldWidget::Drag, 0.01f, 0.0f, 100.0f, "%.2f",
     true, &Light::volumetric, nullptr},
}};

using LightFieldSet = std::uint32_t;

constexpr LightFieldSet fieldBit(LightField field) {
    return LightFieldSet(1) << unsigned(field);
}

template <class... Fields>
constexpr LightFieldSet fieldSet(Fields... fields) {
    return (fieldBit(fields) | ...);
}

// Which photometric quantity gives a type's power: luminous power (lumens; intensity
// lm / 4 pi cd, glTF's intensity in cd), illuminance (lux, glTF's intensity in lux), or the
// luminous power of a one-sided Lambertian area emitter (lumens; luminance lm / (pi area),
// glTF's intensity is the on-axis intensity in cd, so lm = pi cd).
enum class LightPower : std::uint8_t { Lumens, Lux, AreaLumens };

// What the editor's gizmo outlines as the light's reach: the falloff sphere, the spot cone out
// to the falloff radius, or the direction light travels. The source's own shape (sphere,
// tube) is outlined from its fields.
// Area lights (rect, disk) outline their emitting shape and its normal.
enum class LightOutline : std::uint8_t { FalloffSphere, Cone, Direction, Rect, Disk };

struct LightTypeInfo {
    LightType type;
    const char* name;      // "type" in scene files
    const char* label;     // the editor's type list
    const char* gltfType;  // KHR_lights_punctual "type"; nullptr: none
    LightPower power;
    LightFieldSet fields;  // what the inspector shows; validateLight checks cones only if used
    LightOutline outline;
    // castShadows when a scene file or glTF light does not say (render/README.md "Shadows").
    bool castsShadowsByDefault;
};

// The key of Light::castShadows in scene files, glTF light extras and the editor's property
// edits. A flag, not a kLightFieldTable row (that table holds numbers and colours).
inline constexpr const char* kCastShadowsKey = "castShadows";

// One row per LightType, in enumerator order (checked below).
inline constexpr std::array<LightTypeInfo, 5> kLightTypeTable{{
    {LightType::Point, "point", "Point", "point", LightPower::Lumens,
     fieldSet(LightField::Color, LightField::Lumens, LightField::AttenuationRadius,
              LightField::SourceRadius, LightField::SourceLength, LightField::Volumetric),
     LightOutline::FalloffSphere, false},
    {LightType::Spot, "spot", "Spot", "spot", LightPower::Lumens,
     fieldSet(LightField::Color, LightField::Lumens, LightField::AttenuationRadius,
              LightField::SourceRadius, LightField::SourceLength, LightField::InnerConeAngle,
              LightField::OuterConeAngle, LightField::Volumetric),
     LightOutline::Cone, false},
    {LightType::Directional, "directional", "Directional", "directional", LightPower::Lux,
     fieldSet(LightField::Color, LightField::Lux, LightField::Volumetric), LightOutline::Direction,
     true},
    // No KHR type: glTF gives these by extras.shape on a point or spot light.
    {LightType::Rect, "rect", "Rectangle", nullptr, LightPower::AreaLumens,
     fieldSet(LightField::Color, LightField::Lumens, LightField::AttenuationRadius,
              LightField::Width, LightField::Height),
     LightOutline::Rect, false},
    {LightType::Disk, "disk", "Disk", nullptr, LightPower::AreaLumens,
     fieldSet(LightField::Color, LightField::Lumens, LightField::AttenuationRadius,
              LightField::SourceRadius),
     LightOutline::Disk, false},
}};

inline constexpr std::size_t kLightTypeCount = kLightTypeTable.size();

// Not a LightType: what lightTypeIndex gives for a value outside the enumerators.
inline constexpr std::size_t kNotALightType = ~std::size_t(0);

// The compile-time check that kLightTypeTable covers every LightType: a new enumerator is a
// -Wswitch error here (warnings are errors) until it gets a case, and with its case the
// static_assert below fails until its row is in the table.
constexpr std::size_t lightTypeIndex(LightType type) {
    switch (type) {
        case LightType::Point:
            return 0;
        case LightType::Spot:
            return 1;
        case LightType::Directional:
            return 2;
        case LightType::Rect:
            return 3;
        case LightType::Disk:
            return 4;
    }
    return kNotALightType;
}

constexpr bool lightTypeTableIsComplete() {
    for (std::size_t i = 0; i < kLightTypeCount; ++i) {
        if (lightTypeIndex(kLightTypeTable[i].type) != i) return false;
    }
    // The enumerators are 0..count-1: the value after the last row is no LightType.
    return lightTypeIndex(LightType(kLightTypeCount)) == kNotALightType;
}
static_assert(lightTypeTableIsComplete(),
              "kLightTypeTable needs one row per LightType, in enumerator order");

constexpr bool lightFieldTableIsComplete() {
    for (std::size_t i = 0; i < kLightFieldTable.size(); ++i) {
        const LightFieldInfo& f = kLightFieldTable[i];
        if (std::size_t(f.field) != i) return false;
        if ((f.scalar == nullptr) == (f.channels == nullptr)) return false;
    }
    return true;
}
static_assert(lightFieldTableIsComplete(),
              "kLightFieldTable needs one row per LightField, in enumerator order, each with "
              "exactly one member");

constexpr const LightTypeInfo& lightTypeInfo(LightType type) {
    return kLightTypeTable[lightTypeIndex(type)];
}

constexpr const LightFieldInfo& lightFieldInfo(LightField field) {
    return kLightFieldTable[std::size_t(field)];
}

constexpr bool usesField(LightType type, LightField field) {
    return (lightTypeInfo(type).fields & fieldBit(field)) != 0;
}

constexpr bool isAreaLight(LightType type) {
    return lightTypeInfo(type).power == LightPower::AreaLumens;
}

// The emitting area of a rect or disk light in m^2 (0 for the other types): luminance is
// lumens / (pi area).
constexpr float emitterArea(const Light& light) {
    switch (lightTypeInfo(light.type).outline) {
        case LightOutline::Rect:
            return light.width * light.height;
        case LightOutline::Disk:
            return 3.14159265f * light.sourceRadius * light.sourceRadius;
        default:
            return 0.0f;
    }
}

}  // namespace candela::content
