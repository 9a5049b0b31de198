#pragma once
// `--summary FILE.md`: a short human-readable account of a run (per frame: time, lights,
// occupied clusters, culling efficiency), for the demo and for quoting in notes.
#include <filesystem>
#include <string>

#include "candela/runtime/frame_stats.h"

namespace candela::runtime {

// Returns an empty string on success, else a message naming the file.
std::string writeRunSummary(const std::filesystem::path& path, const std::string& scene,
                            double stepSeconds, const FrameStats& stats);

}  // namespace candela::runtime
