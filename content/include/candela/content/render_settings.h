#pragma once
// The user-facing render settings: one enum per choice, the values a frame renders with
// (RenderSettings) and what a command line or a scene file chose (RenderSettingChoices).
// Vulkan-free: the command line, the scene reader and writer, the editor, --stats and the
// renderer share these types, and render_setting_table.h gives each setting its flag, scene
// key, value names, preset columns and editor widget once. Adding a setting: its member in
// both structs below and its row in the table.
#include <cstdint>
#include <optional>

namespace candela::content {

// The setting enums live in an inline namespace so the renderer can take them all with one
// using-directive (renderer_options.h); content code names them as content::SsrMode.
inline namespace setting_enums {

// The specular BRDF (`--brdf`, "brdf"; render/README.md "BRDF").
enum class BrdfModel : uint8_t {
    // Karis 2013, "Real Shading in Unreal Engine 4", exactly: GGX, Schlick-Smith visibility
    // (k = alpha / 2), single scattering.
    Ue4,
    // GGX with height-correlated Smith visibility and multiple-scattering energy compensation
    // (rough metals keep their energy): the default.
    EnergyConserving,
};

// Antialiasing (`--aa`, "aa"; render/README.md "Antialiasing").
enum class AntiAliasing : uint8_t {
    Off,   // one sample per pixel
    Fxaa,  // post-process, after tonemapping: no history, no jitter
    Taa,   // temporal: jittered projection, history reprojected with the motion vectors
    // Geometry buffer AA (Persson 2011): the G-buffer pass also writes each pixel's offset to
    // the nearest triangle edge, a post-process blends across it by the covered fraction; no
    // history, no jitter.
    Gbaa,
};

// Where a frame's exposure comes from (`--exposure`, "exposure").
enum class FrameExposure : uint8_t {
    Manual,  // the camera's EV100 (aperture, shutter, ISO): the default, and the goldens'
    Auto,    // metered from the frame's luminance histogram and adapted over time
};

// How sphere and tube lights (and the area shapes) are integrated (`--area-lights`,
// "area_lights"; render/README.md "Area lights by linearly transformed cosines").
//   Representative: Karis 2013's representative point (sphere, tube) and Drobot's (GPU Pro 5) most
//                   important point: one direction per light, cheap, wrong for glossy surfaces
//                   near large lights (docs/speed-vs-error.md).
//   Ltc:            linearly transformed cosines (Heitz et al. 2016, Heitz and Hill 2017).
enum class AreaLightMode : uint8_t { Representative, Ltc };

// Occlusion of the sky's light (`--ao`, "ambient_occlusion": {"mode"}; render/README.md
// "Ambient occlusion"). Only with image-based lighting: analytic lights have their own shadows.
enum class AoMode : uint8_t {
    Off,        // no pass in the graph, no AO code in the lighting variant
    Gtao,       // ground-truth-based AO (Jimenez et al. 2016) with bent normals and a denoise
    Reference,  // many rays per pixel marched against the depth buffer: for measurement only
};

// Screen-space reflections (`--ssr`, "ssr"; render/README.md "Screen-space reflections"). They
// replace the environment's split-sum specular where a ray finds the reflected surface on
// screen, in proportion to its confidence.
enum class SsrMode : uint8_t {
    Off,  // no pass in the graph
    Hiz,  // Hi-Z tracing against a nearest-depth pyramid (Uludag, GPU Pro 5, "Hi-Z Screen-Space
          // Cone-Traced Reflections")
    Reference,  // a linear march in small steps at full resolution: for measurement only
};

// Sky occlusion (`--sky-occlusion`, "sky_occlusion"; render/README.md "Sky occlusion"): how much
// of the sky each surface sees past the scene's static geometry, for the sky's diffuse and
// specular light. Screen-space AO adds the small-scale corners on top.
enum class SkyOcclusionMode : uint8_t {
    Off,        // the sky reaches every surface (images as before sky occlusion)
    On,         // 32 depth maps over the sky hemisphere, rendered when the casters change
    Reference,  // 256 directions: for measurement only
};

// Volumetric lighting in a participating medium (`--volumetrics`, "volumetrics";
// render/README.md "Volumetric lighting"; only in frames whose scene has a FogMedium).
enum class VolumetricsMode : uint8_t {
    Off,        // no medium is drawn even if the scene has one
    Volumes,    // Vos, GPU Pro 5, "Volumetric Light Effects in Killzone: Shadow Fall": each light's
                // volume marched at half resolution
    Froxels,    // a view-aligned grid lit from the cluster lists, integrated front to back
    Reference,  // every light, many steps per pixel at full resolution: for measurement only
};

// Light shafts: the sun's light scattered by the atmosphere's air between the camera and the
// surfaces, shadowed by the sun's cascades (`--scattering`, "scattering"; render/README.md
// "Light shafts"; Yusov, GPU Pro 5; only in frames whose scene has an atmosphere).
enum class ScatteringMode : uint8_t {
    Off,
    Epipolar,    // Yusov 2013: epipolar samples, 1D min/max trees per slice, unwarped to pixels
    BruteForce,  // every pixel marched in equal steps through every cascade: the reference
};

// Hair self-shadowing (`--hair-self-shadow`, "hair_self_shadow"; Martin et al., GPU Pro 5,
// TressFX; render/README.md "Hair"): off; from a hair depth map per shadow view, the fibres in
// front estimated from the depth range behind the first hair; or the reference that counts the
// fibres between each shaded fragment and the light exactly (small scenes only).
enum class HairSelfShadow : uint8_t { Off, DepthMap, Reference };

}  // namespace setting_enums

// The values a frame renders with. These defaults are the renderer's plain image (what a
// renderer made by a test draws: no post effects, no medium, full resolution); an
// application's defaults are the table's preset columns (render_setting_table.h).
struct RenderSettings {
    BrdfModel brdf = BrdfModel::EnergyConserving;
    AntiAliasing aa = AntiAliasing::Off;
    // Samples per pixel of the forward (blended) pass: 1 (off), 2, 4 or 8 where the device
    // supports them; composes with `aa`. Frames with blended draws get multisampled HDR,
    // motion and depth targets for that pass only.
    uint32_t msaaSamples = 1;
    // The fraction of each pixel's radiance spread over a wide glare kernel (energy-conserving:
    // the frame's total is unchanged). 0: off.
    float bloomStrength = 0.0f;
    FrameExposure exposure = FrameExposure::Manual;
    float exposureCompensation = 0.0f;  // EV added to the metered exposure (auto only)
    AoMode ao = AoMode::Off;
    SsrMode ssr = SsrMode::Off;
    SkyOcclusionMode skyOcclusion = SkyOcclusionMode::Off;
    VolumetricsMode volumetrics = VolumetricsMode::Off;
    // How `volumes` finds the lights a pixel's ray meets: true, each light's proxy mesh (a
    // sphere, a cone) rasterised into the half-resolution target with additive blending, the
    // fragment marching its light (Vos, GPU Pro 5); false, a compute march over CPU light lists
    // per 8x8 tile (light_bins.h). The same sums (to 1e-7); the lists cost 1.5-3.5x less on
    // lavapipe at 1 to 4,096 lights (render/README.md "Volumetric lighting").
    bool volumeProxies = false;
    // The most plain lights (unshadowed points, spots, spheres, tubes) each 4x4x4 cluster of
    // froxels lights the medium with, the strongest at the cluster kept (light_bins.h
    // capPlainLights); shadowed, area and directional lights are never dropped. 0: every light
    // that reaches it (the reference).
    uint32_t froxelLightCap = 0;
    ScatteringMode scattering = ScatteringMode::Off;
    uint32_t scatteringSlices = 512;   // epipolar lines from the sun to the screen border
    uint32_t scatteringSamples = 256;  // samples along each line
    AreaLightMode areaLights = AreaLightMode::Ltc;
    // A textured rect light by LTC: cells per side of its image the specular lobe is integrated
    // over, each an exact polygon integral (its diffuse takes half as many); 1, 2, 4, 8 or 16.
    // 8 is the reference's error (1.9 % on the worst cell against the fit's own 1.0 %); each
    // halving quarters the cost (area_lights.glsl).
    uint32_t areaTextureCells = 8;
    // Only lights with a shadow map (shadows on, castShadows) get a hair depth map.
    HairSelfShadow hairSelfShadow = HairSelfShadow::DepthMap;
    // The fraction of the output's width and height the scene is rendered at: every pass up to
    // bloom runs at the render size, then upscale.comp filters the radiance up to the output
    // for tonemapping, antialiasing after it and the overlays, so text and UI stay sharp. 1:
    // no upscale pass.
    float renderScale = 1.0f;
    // Levels of detail (content/mesh_lods.h): each view draws a mesh at the coarsest level whose
    // error stays within this many of its pixels (shadow maps: texels). 0: every mesh in full,
    // the reference.
    float lodPixelError = 0.0f;

    bool operator==(const RenderSettings&) const = default;
};

// What one source (the command line, a scene file) chose: unset where it says nothing. The
// command line wins over the scene file, the scene file over the quality preset.
struct RenderSettingChoices {
    std::optional<BrdfModel> brdf;
    std::optional<AntiAliasing> aa;
    std::optional<uint32_t> msaaSamples;
    std::optional<float> bloomStrength;
    std::optional<FrameExposure> exposure;
    std::optional<float> exposureCompensation;
    std::optional<AoMode> ao;
    std::optional<SsrMode> ssr;
    std::optional<SkyOcclusionMode> skyOcclusion;
    std::optional<VolumetricsMode> volumetrics;
    std::optional<bool> volumeProxies;
    std::optional<uint32_t> froxelLightCap;
    std::optional<ScatteringMode> scattering;
    std::optional<uint32_t> scatteringSlices;
    std::optional<uint32_t> scatteringSamples;
    std::optional<AreaLightMode> areaLights;
    std::optional<uint32_t> areaTextureCells;
    std::optional<HairSelfShadow> hairSelfShadow;
    std::optional<float> renderScale;
    std::optional<float> lodPixelError;

    bool operator==(const RenderSettingChoices&) const = default;
};

}  // namespace candela::content
