#include "candela/runtime/frame_stats.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "candela/content/atomic_file_write.h"
#include "candela/content/render_setting_table.h"

namespace candela::runtime {

namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

template <class F>
std::vector<double> collect(const std::vector<render::RendererStats>& frames, F field) {
    std::vector<double> out;
    for (const render::RendererStats& f : frames)
        out.push_back(double(field(f)));
    return out;
}

}  // namespace

double cullingEfficiency(const render::RendererStats& frame) {
    return frame.lightEvaluations == 0 ? 0.0
                                       : double(frame.litPairs) / double(frame.lightEvaluations);
}

double FrameStats::frameMsMedian() const {
    return median(frameMs);
}

std::string writeStatsJson(const std::filesystem::path& path, const FrameStats& stats) {
    nlohmann::json json;
    json["frames"] = stats.frameMs.size();
    json["width"] = stats.width;
    json["height"] = stats.height;
    json["device"] = stats.device;
    json["quality"] = stats.quality;
    json["quality_source"] = stats.qualitySource;
    // Each render setting's value: its name, or its number.
    nlohmann::json settings = nlohmann::json::object();
    content::forEachRenderSetting([&](const auto& row) {
        const auto& value = stats.settings.*row.value;
        const std::string text = content::renderSettingText(row, value);
        if (!row.names.empty()) {
            settings[std::string(row.statsName)] = text;
        } else {
            // The number as the command line writes it (0.04, not the float's 0.0399999991).
            settings[std::string(row.statsName)] = nlohmann::json::parse(text);
        }
    });
    json["settings"] = std::move(settings);
    json["render_width"] = stats.renderWidth;
    json["render_height"] = stats.renderHeight;
    json["frame_ms_median"] = stats.frameMsMedian();
    json["validation_messages"] = stats.validationMessages;
    json["features"] = stats.features;
    if (!stats.physics.empty()) {
        std::vector<double> simulate, integration;
        std::uint32_t bodies = 0, active = 0, steps = 0;
        for (const FrameStats::PhysicsFrame& f : stats.physics) {
            simulate.push_back(f.simulateMs);
            integration.push_back(f.integrationMs);
            bodies = std::max(bodies, f.bodies);
            active = std::max(active, f.activeBodies);
            steps += f.steps;
        }
        json["physics"] = {{"frames", stats.physics.size()},
                           {"steps", steps},
                           {"bodies_max", bodies},
                           {"active_bodies_max", active},
                           {"simulate_ms_median", median(simulate)},
                           {"integration_ms_median", median(integration)}};
    }
    if (!stats.audio.empty()) {
        std::vector<double> update, mix;
        std::uint32_t voices = 0, playing = 0;
        for (const FrameStats::AudioFrame& f : stats.audio) {
            update.push_back(f.updateMs);
            mix.push_back(f.mixMs);
            voices = std::max(voices, f.voices);
            playing = std::max(playing, f.playing);
        }
        json["audio"] = {{"frames", stats.audio.size()},
                         {"voices_max", voices},
                         {"playing_max", playing},
                         {"update_ms_median", median(update)},
                         {"mix_ms_median", median(mix)}};
    }
    // Non-finite radiance: the most pixels of one frame with a NaN or Inf channel (0 in a sound
    // run), and the first pass a diagnosis frame found writing one (empty when none ran).
    uint64_t nonFinite = 0;
    std::string nonFiniteSource;
    for (const render::RendererStats& f : stats.frames) {
        nonFinite = std::max(nonFinite, f.nonFinitePixels);
        if (nonFiniteSource.empty()) nonFiniteSource = f.nonFiniteSource;
    }
    json["nonfinite_pixels"] = nonFinite;
    json["nonfinite_source"] = nonFiniteSource;
    // Light culling: counts describe the last frame; times are medians over all frames.
    render::RendererStats last =
        stats.frames.empty() ? render::RendererStats{} : stats.frames.back();
    json["lights"] = last.lights;
    json["lights_rewritten"] = last.lightsRewritten;
    json["clusters"] = last.clusters;
    json["clusters_occupied"] = last.clustersOccupied;
    json["light_cluster_pairs"] = last.lightClusterPairs;
    json["light_assign_ms"] =
        median(collect(stats.frames, [](auto& f) { return f.lightAssignMs; }));
    json["lighting_ms"] = median(collect(stats.frames, [](auto& f) { return f.lightingMs; }));
    json["taa_ms"] = median(collect(stats.frames, [](auto& f) { return f.taaMs; }));
    json["bloom_ms"] = median(collect(stats.frames, [](auto& f) { return f.bloomMs; }));
    // Animation: GPU ms of the skinning pass (0 in frames with no animated draw) and the
    // animated draws it deformed in the last frame.
    json["skinning_ms"] = median(collect(stats.frames, [](auto& f) { return f.skinningMs; }));
    json["deformed_draws"] = last.deformedDraws;
    // Culling (last frame): the scene's draws and those outside the camera's frustum.
    json["draws"] = last.draws;
    json["draws_culled"] = last.drawsCulled;
    // The last frame's metered EV100 (auto exposure; else the camera's) and the one it used.
    json["exposure_ev100"] = last.exposureEv100;
    json["exposure_adapted_ev100"] = last.adaptedEv100;
    json["ao_ms"] = median(collect(stats.frames, [](auto& f) { return f.aoMs; }));
    // Screen-space reflections: GPU ms of their passes (median), and the last frame's mean and
    // most steps per traced ray and the share of traced rays that hit.
    json["ssr_ms"] = median(collect(stats.frames, [](auto& f) { return f.ssrMs; }));
    json["ssr_steps_mean"] = last.ssrStepsMean;
    json["ssr_steps_max"] = last.ssrStepsMax;
    json["ssr_hit_rate"] = last.ssrHitRate;
    json["volumetrics_ms"] = median(collect(stats.frames, [](auto& f) { return f.volumetricsMs; }));
    json["sky_ms"] = median(collect(stats.frames, [](auto& f) { return f.skyMs; }));
    // Sky occlusion: GPU ms of the last build of its maps, and the frames that built them
    // (once per change of the static casters).
    json["sky_occlusion_ms"] = last.skyOcclusionMs;
    json["sky_occlusion_rebuilds"] =
        std::count_if(stats.frames.begin(), stats.frames.end(),
                      [](const render::RendererStats& f) { return f.skyOcclusionRebuilt; });
    json["sky_occlusion_rebuilt"] = last.skyOcclusionRebuilt;
    // Light shafts: GPU ms of their passes (median), and the last frame's rays marched
    // (epipolar samples and unwarp fix-ups, or pixels) and shadow tests taken by them.
    json["scattering_ms"] = median(collect(stats.frames, [](auto& f) { return f.scatteringMs; }));
    json["scattering_samples"] = last.scatteringSamples;
    json["scattering_steps"] = last.scatteringSteps;
    // The air's aerial-perspective grid for blended surfaces and wires: GPU ms (median).
    json["aerial_perspective_ms"] =
        median(collect(stats.frames, [](auto& f) { return f.aerialPerspectiveMs; }));
    json["light_evaluations"] = last.lightEvaluations;
    json["lit_pairs"] = last.litPairs;
    json["light_list_overflows"] = last.lightListOverflows;
    json["light_list_grew"] = last.lightListGrew;
    // Hair's A-buffer (last frame): fragments the fill asked nodes for, those a full pool
    // dropped, and the pool's size.
    json["hair_nodes"] = last.hairNodes;
    json["hair_nodes_dropped"] = last.hairNodesDropped;
    json["hair_node_capacity"] = last.hairNodeCapacity;
    json["culling_efficiency"] = cullingEfficiency(last);
    // Work (render::WorkCounters): each deterministic count's largest value over the run's
    // frames, what the frame budget test (tests/budgets) holds a scene's every view to (the
    // lighting pass's counts from the counted frames: every one unless --stats-work last).
    render::WorkCounters w;
    for (const render::RendererStats& f : stats.frames) {
        const render::WorkCounters& c = f.work;
        w.lightEvaluationsPlain = std::max(w.lightEvaluationsPlain, c.lightEvaluationsPlain);
        w.lightEvaluationsArea = std::max(w.lightEvaluationsArea, c.lightEvaluationsArea);
        w.lightEvaluationsShadowed =
            std::max(w.lightEvaluationsShadowed, c.lightEvaluationsShadowed);
        w.shadowFilterTaps = std::max(w.shadowFilterTaps, c.shadowFilterTaps);
        w.shadowBlockerTaps = std::max(w.shadowBlockerTaps, c.shadowBlockerTaps);
        w.froxelLightEvaluations = std::max(w.froxelLightEvaluations, c.froxelLightEvaluations);
        w.volumeMarchSteps = std::max(w.volumeMarchSteps, c.volumeMarchSteps);
        w.ssrSteps = std::max(w.ssrSteps, c.ssrSteps);
        w.aoSamples = std::max(w.aoSamples, c.aoSamples);
        w.scatteringSteps = std::max(w.scatteringSteps, c.scatteringSteps);
        w.hairFragments = std::max(w.hairFragments, c.hairFragments);
        w.triangles = std::max(w.triangles, c.triangles);
        w.shadowTriangles = std::max(w.shadowTriangles, c.shadowTriangles);
    }
    json["work"] = {{"light_evaluations_plain", w.lightEvaluationsPlain},
                    {"light_evaluations_area", w.lightEvaluationsArea},
                    {"light_evaluations_shadowed", w.lightEvaluationsShadowed},
                    {"shadow_filter_taps", w.shadowFilterTaps},
                    {"shadow_blocker_taps", w.shadowBlockerTaps},
                    {"froxel_light_evaluations", w.froxelLightEvaluations},
                    {"volume_march_steps", w.volumeMarchSteps},
                    {"ssr_steps", w.ssrSteps},
                    {"ao_samples", w.aoSamples},
                    {"scattering_steps", w.scatteringSteps},
                    {"hair_fragments", w.hairFragments},
                    {"triangles", w.triangles},
                    {"shadow_triangles", w.shadowTriangles}};
    // Shadows: GPU ms of the shadow depth pass (median over frames; 0 in frames whose maps
    // were all cached), lights with maps, rendered, cached and kept (over the render budget) maps
    // and atlas use (last frame).
    json["shadow_ms"] = median(collect(stats.frames, [](auto& f) { return f.shadowMs; }));
    json["shadowed_lights"] = last.shadowedLights;
    json["shadow_maps_rendered"] = last.shadowMapsRendered;
    json["shadow_maps_cached"] = last.shadowMapsCached;
    json["shadow_maps_kept"] = last.shadowMapsKept;
    json["shadow_atlas_used"] = last.shadowAtlasUsed;
    json["shadow_caster_draws"] = last.shadowCasterDraws;
    // Frame graph: each pass's median GPU milliseconds (a host pass: CPU) over the frames that
    // ran it, and the last frame's graph; record_ms + compile_ms is the graph's CPU cost.
    std::map<std::string, std::vector<double>> passTimes;
    for (const render::RendererStats& f : stats.frames) {
        for (const auto& [name, ms] : f.passMs)
            passTimes[name].push_back(ms);
    }
    std::vector<double> compileMs;  // over the frames that compiled (the rest reused the graph)
    for (const render::RendererStats& f : stats.frames) {
        if (!f.frameGraph.reused) compileMs.push_back(f.frameGraph.compileMs);
    }
    json["passes"] = nlohmann::json::object();
    for (const render::RendererStats::PassTime& pass : last.passMs) {
        json["passes"][pass.first] = median(passTimes[pass.first]);
    }
    json["frame_graph"] = {
        {"passes", last.frameGraph.passes},
        {"culled_passes", last.frameGraph.culledPasses},
        {"resources", last.frameGraph.resources},
        {"barriers", last.frameGraph.barriers},
        {"transient_bytes", last.frameGraph.transientBytes},
        {"transient_bytes_unaliased", last.frameGraph.transientBytesUnaliased},
        {"record_ms", median(collect(stats.frames, [](auto& f) { return f.frameGraph.recordMs; }))},
        {"compile_ms", compileMs.empty() ? 0.0 : median(compileMs)},
        {"record_compile_ms",
         median(collect(stats.frames,
                        [](auto& f) { return f.frameGraph.recordMs + f.frameGraph.compileMs; }))},
        {"compiled_frames",
         std::count_if(stats.frames.begin(), stats.frames.end(),
                       [](const render::RendererStats& f) { return !f.frameGraph.reused; })}};
    json["pipelines"] = {{"created", last.pipelinesCreated}, {"create_ms", last.pipelineCreateMs}};
    if (!last.brdfLutSource.empty()) {
        json["brdf_lut"] = {{"source", last.brdfLutSource}, {"ms", last.brdfLutMs}};
    }
    if (stats.environment) {
        const render::EnvironmentBuildStats& e = *stats.environment;
        json["environment"] = {{"source", e.source},
                               {"fallback", e.fallback},
                               {"from_cache", e.fromCache},
                               {"read_ms", e.readMs},
                               {"decode_ms", e.decodeMs},
                               {"precompute_ms", e.precomputeMs},
                               {"cache_ms", e.cacheMs},
                               {"cube_face_size", e.cubeFaceSize},
                               {"prefiltered_face_size", e.prefilteredFaceSize},
                               {"prefiltered_mips", e.prefilteredMipCount}};
    }
    return content::writeFileAtomically(path, json.dump(2) + '\n');
}

}  // namespace candela::runtime
