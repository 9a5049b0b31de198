#include "frame_stats.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

namespace candela::runtime {

double FrameStats::frameMsMedian() const {
    if (frameMs.empty()) return 0.0;
    std::vector<double> sorted = frameMs;
    std::sort(sorted.begin(), sorted.end());
    size_t mid = sorted.size() / 2;
    return sorted.size() % 2 ? sorted[mid] : 0.5 * (sorted[mid - 1] + sorted[mid]);
}

std::string writeStatsJson(const std::filesystem::path& path, const FrameStats& stats) {
    nlohmann::json json;
    json["frames"] = stats.frameMs.size();
    json["width"] = stats.width;
    json["height"] = stats.height;
    json["device"] = stats.device;
    json["frame_ms_median"] = stats.frameMsMedian();
    json["validation_messages"] = stats.validationMessages;
    json["features"] = stats.features;
    std::ofstream out(path);
    if (!out) return path.string() + ": cannot open for writing";
    out << json.dump(2) << '\n';
    if (!out) return path.string() + ": write failed";
    return {};
}

}  // namespace candela::runtime
