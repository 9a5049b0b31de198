#include "run_summary.h"

#include <cstdio>
#include <sstream>

#include "candela/content/atomic_file_write.h"

namespace candela::runtime {

std::string writeRunSummary(const std::filesystem::path& path, const std::string& scene,
                            double stepSeconds, const FrameStats& stats) {
    // Composed in memory, then written atomically: the summary is whole or not there.
    std::ostringstream out;
    char line[512];
    out << "# " << scene << "\n\n";
    std::snprintf(line, sizeof line,
                  "%zu frames at %ux%u on %s, %.3f s of scene time per frame; median frame "
                  "%.1f ms (CPU wall time including the wait for the device); %u validation "
                  "messages.\n\n",
                  stats.frameMs.size(), stats.width, stats.height, stats.device.c_str(),
                  stepSeconds, stats.frameMsMedian(), stats.validationMessages);
    out << line;
    out << "Culling efficiency: of the light-pixel pairs the clustered shader evaluated, the "
           "share the light actually reaches (1.0 would be perfect culling). Shadows: GPU ms "
           "of the shadow depth pass (shadow_ms) and the lights whose maps were rendered / kept "
           "from an earlier frame.\n\n";
    out << "| frame | scene s | frame ms | lights | clusters occupied | light-cluster pairs "
           "| evaluated pairs | lit pairs | culling efficiency | shadow_ms | shadow maps "
           "rendered / cached |\n";
    out << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (size_t i = 0; i < stats.frames.size() && i < stats.frameMs.size(); ++i) {
        const render::RendererStats& f = stats.frames[i];
        std::snprintf(line, sizeof line,
                      "| %zu | %.2f | %.1f | %u | %u / %u | %llu | %llu | %llu | %.3f | %.2f | "
                      "%u / %u |\n",
                      i, double(i) * stepSeconds, stats.frameMs[i], f.lights, f.clustersOccupied,
                      f.clusters, static_cast<unsigned long long>(f.lightClusterPairs),
                      static_cast<unsigned long long>(f.lightEvaluations),
                      static_cast<unsigned long long>(f.litPairs), cullingEfficiency(f), f.shadowMs,
                      f.shadowMapsRendered, f.shadowMapsCached);
        out << line;
    }
    return content::writeFileAtomically(path, out.str());
}

}  // namespace candela::runtime
