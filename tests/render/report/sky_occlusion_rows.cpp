// Rows: sky occlusion (render/README.md "Sky occlusion") against its reference mode (256
// directions) and a CPU ray trace of the same boxes: the floor of a closed room lit by a
// uniform white sky only through a 1 m skylight (tests/render/sky_occlusion_scene.h), with the
// maps' build time and the lighting pass's.
#include <cstdio>
#include <string>

#include "../sky_occlusion_scene.h"
#include "candela/content/render_setting_table.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

void addSkyOcclusionRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const uint32_t size = quick ? 64 : 128;
    GpuContext& gpu = context.harness.context();
    SkyRoom room(gpu, true, size);
    RendererStats referenceStats;
    const CapturedFrame reference = room.render(SkyOcclusionMode::Reference, &referenceStats);
    const SkyRoomError referenceTruth = room.compareInside(reference, 2);
    for (SkyOcclusionMode mode : {SkyOcclusionMode::Off, SkyOcclusionMode::On}) {
        RendererStats stats;
        const CapturedFrame frame = room.render(mode, &stats);
        const SkyRoomError e = room.compareInside(frame, 2, &reference);
        const SkyRoomError truth = room.compareInside(frame, 2);
        char name[96], metric[240], where[160], cost[160];
        std::snprintf(name, sizeof(name), "Sky occlusion %s%s",
                      candela::content::renderSettingName(mode).c_str(),
                      mode == SkyOcclusionMode::On ? " (32 directions, 256-texel maps)" : "");
        std::snprintf(metric, sizeof(metric),
                      "mean |floor sky visibility - reference| (%u px of a closed room's floor, "
                      "1 m skylight, uniform sky, %ux%u)",
                      e.pixels, size, size);
        std::snprintf(where, sizeof(where),
                      "floor mean %.4f vs reference %.4f; vs CPU ray trace %.4f (reference's "
                      "own %.4f)",
                      e.meanRendered, e.meanTruth, truth.meanAbs, referenceTruth.meanAbs);
        std::snprintf(cost, sizeof(cost),
                      "maps (once per caster change) %.2f vs %.2f ms; lighting %.2f vs %.2f ms",
                      stats.skyOcclusionMs, referenceStats.skyOcclusionMs, stats.lightingMs,
                      referenceStats.lightingMs);
        context.report.rows.push_back({name, "--sky-occlusion reference (256 directions)", metric,
                                       e.meanAbs, "abs", where, cost});
    }
}

}  // namespace candela::report
