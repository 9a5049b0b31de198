#pragma once
// What every section of the report shares: the device harness, the cost timer, the budget,
// and the report being filled.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "../stability/compute_harness.h"
#include "candela/render/environment.h"
#include "report_table.h"
#include "shader_cost.h"

namespace candela::report {

struct Budget {
    bool quick = false;  // the smoke test's tiny budget: coarse grids, few repetitions
    uint32_t iterations(uint32_t full) const { return quick ? std::max(1u, full / 16) : full; }
};

struct ReportContext {
    stability::ComputeHarness& harness;
    ShaderCost& cost;
    Budget budget;
    Report& report;
};

// The sections, one file each.
// The image-based-lighting rows' sky, from the shared assets; loadReportSky throws naming the
// file when it cannot be loaded.
inline constexpr const char* kReportSky = "env/chinese_garden_1k.exr";
std::shared_ptr<const render::Environment> loadReportSky(render::GpuContext& gpu);

void addBrdfRows(ReportContext& context);
void addEnvironmentBrdfRows(ReportContext& context, const std::vector<float>& lut,
                            uint32_t lutSize);
void addAreaLightRows(ReportContext& context);
void addLtcAreaLightRows(ReportContext& context);
void addAreaLightShapeRows(ReportContext& context);
void addFalloffRow(ReportContext& context);
void addSplitSumRow(ReportContext& context);
void addClusteredRow(ReportContext& context);
void addBrdfEnergyRows(ReportContext& context);
void addAntialiasingRows(ReportContext& context);
void addForwardMsaaRows(ReportContext& context);
void addMaterialRows(ReportContext& context);
void addAmbientOcclusionRows(ReportContext& context);
void addSkyOcclusionRows(ReportContext& context);
void addShadowRows(ReportContext& context);
void addAnimationRows(ReportContext& context);
void addSsrRows(ReportContext& context);
void addVolumetricsRows(ReportContext& context);
void addAtmosphereRows(ReportContext& context);
void addScatteringRows(ReportContext& context);
void addWireRows(ReportContext& context);
void addHairRows(ReportContext& context);
void addLevelOfDetailRows(ReportContext& context);

}  // namespace candela::report
