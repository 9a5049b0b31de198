#pragma once
// How the renderer lights a frame, and what it measures.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "candela/content/render_settings.h"
#include "candela/render/auto_exposure.h"

namespace candela::render {

// The user-facing settings' enums are content's (render_settings.h), one type shared by the
// command line, scene files and the renderer.
using namespace content::setting_enums;
using ExposureMode = content::FrameExposure;

enum class LightCulling {
    Clustered,   // per-cluster light lists (the default)
    BruteForce,  // every light at every pixel: the reference clustered output must match
};

// Where clustered lighting builds its per-cluster light lists (render/README.md compares both).
enum class LightAssignmentDevice {
    Auto,  // Gpu on a real GPU, Cpu on a CPU device (lavapipe), where the job system wins
    Cpu,   // job system, after a mid-frame wait for the depth occupancy
    Gpu,   // compute shaders between the occupancy and lighting passes, no wait
};
// How an environment (sky) lights surfaces (Karis 2013 "Real Shading in Unreal Engine 4",
// image-based lighting; Karis 2014 "Physically Based Shading on Mobile").
enum class IblMode {
    SplitSum,   // prefiltered radiance cube x environment BRDF LUT (eq. 7, 8): the default
    Mobile,     // prefiltered cube x EnvBRDFApprox (Karis 2014, mobile), no LUT
    Reference,  // eq. 6 by Monte Carlo per pixel (referenceSamples): for measurement only
};
const char* iblModeName(IblMode mode);  // "split_sum", "mobile", "reference"

// GTAO's temporal accumulation (render/README.md "Ambient occlusion"): last frame's result
// reprojected with the motion vectors and blended with this frame's, whose slice directions
// and step offsets rotate every frame, so a still view converges to many more slices.
enum class AoTemporal {
    WithTaa,  // when the frame has TAA's history (--aa taa): the default
    Always,   // with or without TAA (tests measure AO's own convergence with --aa off)
    Never,
};

// Where GTAO's specular occlusion comes from (render/README.md "Ambient occlusion").
enum class AoSpecular {
    FromVisibility,  // Lagarde and de Rousiers' fit of the visibility alone: the default
    HorizonSlice,    // the horizons of one more slice, the one that holds the reflection vector
};

// Epipolar sampling's parameters (render/README.md "Light shafts" gives why each default).
struct ScatteringSettings {
    // Slices and samples per slice: RenderSettings::scatteringSlices, scatteringSamples.
    uint32_t initialStep = 16;  // every N-th sample is ray-marched first
    // A sample between two initial ones is marched itself when their in-scattering differs by
    // more than this fraction of the larger, or two neighbours' view distances do.
    float refinementThreshold = 0.2f;
    bool minMaxTree = true;          // false: the march steps texel by texel (for measurement)
    uint32_t bruteForceSteps = 512;  // the reference's equal steps per pixel
    // The air's scattering and extinction are the atmosphere's at the camera's altitude times
    // this: at 1 (clear air) shafts tens of metres long scatter ~1e-3 of the sunlit surfaces'
    // radiance and do not show; 50 is a hazy day's aerosol load.
    float densityScale = 50.0f;
    float maxDistance = 200.0f;  // metres marched for the sky (no surface)
    // Measurement: the frame is replaced by the in-scattered radiance alone (no surfaces).
    bool inscatteringOnly = false;
    // The air in front of blended surfaces and wires (render/README.md "Aerial perspective"):
    // a grid of view rays (columns x rows across the image, Hillaire 2020's 32x32) marched
    // once a frame through `aerialSlices` quadratic depth slices out to `aerialFar` metres,
    // `aerialStepsPerSlice` shadow lookups in each; past it the air is lit.
    uint32_t aerialColumns = 32, aerialRows = 32, aerialSlices = 32;
    uint32_t aerialStepsPerSlice = 8;
    float aerialFar = 200.0f;
};

// Wires (Persson, GPU Pro 5, "Wire Antialiasing"; render/README.md "Wires"): Persson's clamp to a
// pixel's radius with the alpha scaled by real / clamped radius and coverage from the distance to
// the centre line, or the naive line a pixel wide at full alpha it replaces (for measurement).
enum class WireMode { Coverage, Naive };

// Hair (Martin et al., GPU Pro 5, TressFX; render/README.md "Hair"): Kajiya-Kay shading, or every
// strand fragment unlit radiance 1 times its coverage (the GPAA measurement: a strand's column sums
// are its width in pixels).
enum class HairShading { Lit, Coverage };

struct VolumetricsSettings {
    // Froxel grid at 1280x720 (scaled with the image, at least 8x8), exponential depth slices
    // from the near plane to `froxelFar` metres.
    uint32_t froxelsX = 160, froxelsY = 90, froxelSlices = 64;
    float froxelFar = 100.0f;
    uint32_t referenceSteps = 256;  // per pixel, uniformly over the ray up to referenceFar
    // Per-light volumes: steps per light along each half-resolution pixel's segment inside
    // the light's volume (the 4x4 dither and the blur make 16 sets of offsets of them).
    uint32_t volumeSteps = 16;
    float referenceFar = 100.0f;  // metres; past it the medium is not drawn (both modes)
};

struct AmbientOcclusionSettings {
    float radius = 1.5f;              // metres the horizon search (and the reference's rays) reach
    float intensity = 1.0f;           // 0: no occlusion, 1: as measured
    uint32_t slices = 4;              // GTAO screen-space directions per pixel
    uint32_t steps = 8;               // GTAO samples per side of a slice
    uint32_t referenceRays = 256;     // per pixel, for each of diffuse and specular
    uint32_t referenceSteps = 24;     // per ray
    float referenceThickness = 1.0f;  // metres behind the depth buffer a surface is solid
    // Jimenez et al.'s multi-bounce fit, which assumes occluders as bright as the surface;
    // off only to measure visibility itself (a black occluder on a white floor).
    bool multiBounce = true;
    AoTemporal temporal = AoTemporal::WithTaa;
    AoSpecular specular = AoSpecular::FromVisibility;
    uint32_t temporalFrames = 16;  // most frames the accumulation averages (1 / n lowest blend)
};

struct SsrSettings {
    // Surfaces at least this rough get no ray (and the confidence fades to 0 from 3/4 of it);
    // a frame with no material under it declares no SSR pass.
    float roughnessCutoff = 0.4f;
    uint32_t maxIterations = 128;       // Hi-Z steps per ray (climb, descend or cross)
    float thickness = 0.5f;             // metres behind a depth-buffer surface that are solid
    float referenceStepPixels = 0.5f;   // the reference march's step along the screen
    uint32_t referenceMaxSteps = 8192;  // the reference march's cap (per ray)
    // The reference's rays per pixel of a rough surface (importance-sampled from its GGX lobe;
    // a mirror traces one).
    uint32_t referenceRays = 64;
    // Cone tracing (Uludag, GPU Pro 5, the cone-tracing pass): circles along the cone weighted by
    // the pre-integrated visibility; off: one pre-convolved read at the hit.
    bool coneTracing = true;
    uint32_t coneSamples = 8;  // most circles along a cone
    // Temporal filtering: last frame's reflection reprojected with the motion vectors, clamped
    // to this frame's neighbourhood (rejecting disoccluded history) and blended by this weight.
    bool temporal = true;
    float temporalBlend = 0.25f;
};

// The atmosphere's tables (render/README.md "Atmosphere"; Hillaire 2020's sizes and sample
// counts, but 64 transmittance samples for 40, which keeps every texel within 1e-3 of the
// exact integral; docs/speed-vs-error.md measures them against a finer reference): texels of the
// transmittance, multiple-scattering and sky-view tables, ray-marching samples for each, and
// the face size of the sky cube that image-based lighting filters.
struct AtmosphereSettings {
    uint32_t transmittanceWidth = 256, transmittanceHeight = 64, transmittanceSteps = 64;
    uint32_t multipleScatteringSize = 32, multipleScatteringSteps = 20;
    uint32_t skyViewWidth = 192, skyViewHeight = 108, skyViewSteps = 30;
    uint32_t cubeFaceSize = 64;
    // The sky cube is re-lit when the sun moved more than this (degrees) since the last.
    float iblUpdateDegrees = 0.1f;
};

// The user-facing settings (content::RenderSettings: antialiasing, AO, SSR, media, render
// scale...; each a row of content/render_setting_table.h) and below them the renderer's own
// parameters. RenderSettings' defaults render a plain image (no post effects, no medium), so
// a renderer made by a test draws only what it asks for; an application's come from the
// quality presets.
struct RendererOptions : content::RenderSettings {
    // Count the scene radiance's non-finite pixels each frame (RendererStats::nonFinitePixels;
    // one pass over the image before tonemapping). Headless runs and --stats turn it on.
    bool checkNonFinite = false;
    LightCulling lightCulling = LightCulling::Clustered;
    LightAssignmentDevice lightAssignment = LightAssignmentDevice::Auto;
    // Device assignment: light index entries of the first frame's list buffer (0: a guess from
    // the light count). Later frames size it from what the previous frame needed.
    uint32_t initialGpuLightListEntries = 0;
    // Cluster tile in pixels and exponential depth slices (<= 64). 16 x 64 keeps culling
    // efficiency under 2 on the floor benchmark at 320x180 and up (render/README.md).
    uint32_t tileSize = 16;
    uint32_t slices = 64;
    // Counts evaluated and lit light-pixel pairs (a shader variant with per-workgroup counters;
    // --stats turns it on).
    bool countLightPairs = false;
    IblMode ibl = IblMode::SplitSum;
    uint32_t referenceSamples = 2048;      // per pixel, for each of specular and diffuse
    float taaMinimumBlend = 1.0f / 16.0f;  // lowest weight of a new sample (taa.comp)
    float taaSharpness = 0.0f;             // 0: no sharpening
    // Tests: copy each frame's motion vectors (gbuffer.motion) to the host, for
    // Renderer::motionVectors().
    bool captureMotionVectors = false;
    // Auto exposure's adaptation; its compensation is RenderSettings::exposureCompensation.
    AutoExposureSettings autoExposure;
    VolumetricsSettings volumetricsSettings;
    WireMode wires = WireMode::Coverage;
    HairShading hairShading = HairShading::Lit;
    // The hair A-buffer's node pool: this many nodes per pixel of the target. Fragments beyond
    // it are dropped (the nearest few of a pixel then may be missing) and counted
    // (RendererStats::hairNodesDropped).
    uint32_t hairNodesPerPixel = 8;
    // The pass settings other than radius and intensity (those are the scene's, per frame).
    AmbientOcclusionSettings aoSettings;
    // Shadows (render/README.md "Shadows"): lights with castShadows get maps when on.
    bool shadows = true;
    uint32_t shadowAtlasSize = 4096;    // largest atlas side, texels (every map is a tile)
    uint32_t shadowCascadeSize = 1024;  // texels per side of each directional cascade
    uint32_t shadowCascades = 4;        // per directional light, 1 to 4
    float shadowDistance = 50.0f;       // metres of view depth the cascades cover
    uint32_t shadowMaxTileSize = 1024;  // largest tile of a local light (per cube face)
    bool shadowCache = true;            // keep maps whose light and casters did not change
    // Frustum culling: the camera's passes record only the draws in its view, each shadow
    // view only the casters in its own. Off (--culling off), every view records every draw:
    // the reference a culled frame must match pixel for pixel.
    bool culling = true;
    // Penumbrae of sphere and tube lights by blocker search (percentage-closer soft shadows);
    // off, every local light's map is filtered as a hard shadow (the quality presets' switch).
    bool softShadows = true;
    // Hard shadows' compare taps per axis: 2, a 3x3-texel tent; 1, one bilinear tap over 2x2
    // texels at a quarter of the cost.
    uint32_t shadowHardTapsPerAxis = 2;
    // Texels of local-light maps re-rendered per frame (0: no limit). Past it, a changed light
    // whose last maps are still in the atlas keeps them for the frame (shadow_maps_kept).
    uint64_t shadowRenderBudget = uint64_t(4) << 20;
    // With skyOcclusion Off: On in frames whose scene has an atmosphere (the default when
    // neither the command line nor the scene file chooses).
    bool skyOcclusionWithAtmosphere = false;
    SsrSettings ssrSettings;
    AtmosphereSettings atmosphere;
    ScatteringSettings scatteringSettings;
};

// The frame graph of the last frame (--stats `frame_graph`).
struct FrameGraphSummary {
    uint32_t passes = 0;  // live
    uint32_t culledPasses = 0;
    uint32_t resources = 0;
    uint32_t barriers = 0;                 // image barriers + global memory barriers
    uint64_t transientBytes = 0;           // the aliased transient pool
    uint64_t transientBytesUnaliased = 0;  // the same transients in separate allocations
    double recordMs = 0.0;                 // CPU: declaring the frame's passes
    double compileMs = 0.0;                // CPU: compiling (0 when the cached graph was reused)
    bool reused = false;                   // the cached compiled graph was used
};

// Deterministic counts of a frame's work (--stats `work`): what the frame budget test
// (tests/budgets) holds each scene to, since times are noisy and counts are not. Zero for a
// feature the frame does not run.
struct WorkCounters {
    // Light-pixel evaluations of the lighting pass by class: plain (point, spot, directional
    // without a map), area (sphere, tube, rect, disk without a map), shadowed (a map).
    uint64_t lightEvaluationsPlain = 0;
    uint64_t lightEvaluationsArea = 0;
    uint64_t lightEvaluationsShadowed = 0;
    uint64_t shadowFilterTaps = 0;        // bilinear compare taps of the shadow filter
    uint64_t shadowBlockerTaps = 0;       // texels the penumbra's blocker search read
    uint64_t froxelLightEvaluations = 0;  // froxel-light pairs the froxel lighting listed
    uint64_t volumeMarchSteps = 0;        // per-light volumes: pixel-light pairs x steps
    uint64_t ssrSteps = 0;                // Hi-Z steps of every traced ray
    uint64_t aoSamples = 0;               // GTAO depth samples (pixels x slices x 2 x steps)
    uint64_t scatteringSteps = 0;         // light shafts' shadow tests
    uint64_t hairFragments = 0;           // strand fragments the A-buffer fill asked for
    // Triangles drawn at their levels of detail: by the camera's passes (G-buffer, forward),
    // and into the shadow maps rendered this frame.
    uint64_t triangles = 0;
    uint64_t shadowTriangles = 0;
};

// Measurements of the last completed frame (--stats fields).
struct RendererStats {
    // With RendererOptions::checkNonFinite: pixels of the frame's scene radiance (before
    // tonemapping) with a NaN or Inf channel. After Renderer::diagnoseNonFiniteNextFrame, the
    // first pass that wrote a non-finite value, its image and the texel count, else empty.
    uint64_t nonFinitePixels = 0;
    std::string nonFiniteSource;
    uint32_t lights = 0;
    uint32_t lightsRewritten = 0;  // light slots uploaded this frame (change detection)
    uint32_t clusters = 0;
    uint32_t clustersOccupied = 0;
    uint64_t lightClusterPairs = 0;
    double lightAssignMs = 0.0;  // CPU: assignment and list upload (not the geometry wait);
                                 // GPU: timestamps around the assignment passes
    double lightingMs = 0.0;     // GPU timestamps around the lighting dispatch
    double aoMs = 0.0;           // GPU timestamps around the ambient occlusion passes
    double volumetricsMs = 0.0;  // GPU timestamps around the volumetric lighting passes
    // GPU timestamps around the atmosphere's passes (--stats sky_ms): its tables, this frame's
    // share of the sky cube's amortised update and the sky background.
    double skyMs = 0.0;
    // Light shafts (--stats scattering_ms, scattering_samples): GPU time of their passes, the
    // rays marched (epipolar: marched samples and unwarp fix-ups; brute force: pixels) and the
    // shadow tests those marches took (min/max tree nodes or steps).
    double scatteringMs = 0.0;
    uint64_t scatteringSamples = 0;
    uint64_t scatteringSteps = 0;
    // The air's grid for blended surfaces and wires (--stats aerial_perspective_ms): GPU time
    // of its pass (0 in frames without an atmosphere, shafts or anything blended).
    double aerialPerspectiveMs = 0.0;
    uint64_t lightEvaluations = 0;  // light-pixel pairs the shader evaluated (countLightPairs)
    uint64_t litPairs = 0;          // ... of which the light reaches the pixel
    // Frames whose list buffer had to grow (the CPU path's first frame always does: it sizes
    // the buffer exactly before lighting, and nothing is dropped).
    uint32_t lightListGrew = 0;
    // Clusters whose device-built list did not fit, so lighting evaluated every light there
    // (slower, never wrong), summed over frames; the CPU path never overflows.
    uint64_t lightListOverflows = 0;
    // Hair (--stats hair_nodes, hair_nodes_dropped, hair_node_capacity): strand fragments the
    // last frame's A-buffer fill asked for, those the full pool dropped, and the pool's size.
    uint64_t hairNodes = 0;
    uint64_t hairNodesDropped = 0;
    uint64_t hairNodeCapacity = 0;
    // The frame graph (--stats `passes`, `frame_graph`): each live pass's GPU milliseconds
    // (a host pass: CPU), in execution order.
    using PassTime = std::pair<std::string, double>;
    std::vector<PassTime> passMs;
    FrameGraphSummary frameGraph;
    // The environment BRDF LUT (--stats `brdf_lut`): "built", "disk_cache" or "process_cache"
    // (empty until a frame needed it), and the milliseconds it took to build or load.
    std::string brdfLutSource;
    double brdfLutMs = 0.0;
    // Pipelines the device has created since start-up, and the milliseconds that took
    // (--stats `pipelines`): the renderer builds a pass's pipelines when a frame first uses it.
    uint32_t pipelinesCreated = 0;
    double pipelineCreateMs = 0.0;
    double taaMs = 0.0;    // GPU: the TAA resolve and its copy back (--stats taa_ms)
    double bloomMs = 0.0;  // GPU: the bloom pyramid and composite (--stats bloom_ms)

    // Animation: GPU time of the skinning pass (--stats skinning_ms; 0 when there is none) and
    // the animated draws it deformed this frame (--stats deformed_draws).
    double skinningMs = 0.0;
    uint32_t deformedDraws = 0;
    // The scene's draws and those outside the camera's frustum, which no camera pass records
    // (--stats draws, draws_culled; their triangles: WorkCounters).
    uint32_t draws = 0;
    uint32_t drawsCulled = 0;
    // The EV100 metered from the last read histogram (--stats exposure_ev100; auto exposure
    // only, else the camera's), and the adapted EV100 the frame was exposed with.
    float exposureEv100 = 0.0f;
    float adaptedEv100 = 0.0f;
    // Shadows (--stats shadow_*): GPU ms of the shadow depth pass, lights with maps, of which
    // rendered this frame and kept from an earlier one, and the share of atlas texels in use.
    // Kept: changed lights that sampled last frame's maps as the render budget was spent.
    double shadowMs = 0.0;
    // Sky occlusion: GPU ms of the last build of its maps (kept while they are reused), and
    // whether this frame rebuilt them.
    double skyOcclusionMs = 0.0;
    bool skyOcclusionRebuilt = false;
    uint32_t shadowedLights = 0;
    uint32_t shadowMapsRendered = 0;
    uint32_t shadowMapsCached = 0;
    uint32_t shadowMapsKept = 0;
    double shadowAtlasUsed = 0.0;
    uint32_t shadowCasterDraws = 0;  // draws recorded into the maps rendered this frame
    // Screen-space reflections (--stats ssr_*): GPU ms of the Hi-Z, trace and composite
    // passes, the mean and most steps of a traced ray, and the share of traced rays that hit
    // (0 in frames that trace none).
    double ssrMs = 0.0;
    double ssrStepsMean = 0.0;
    uint32_t ssrStepsMax = 0;
    double ssrHitRate = 0.0;
    uint32_t ssrRays = 0;
    WorkCounters work;
};

}  // namespace candela::render
