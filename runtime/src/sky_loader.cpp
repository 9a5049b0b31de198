#include "candela/runtime/sky_loader.h"

#include <cstdio>

#include "candela/content/diagnostics.h"
#include "candela/render/environment.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/scene_resources.h"
#include "candela/runtime/frame_extraction.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

bool SkyLoader::update(const SceneWorld& world, const ExtractedFrame& frame,
                       render::GpuContext& context, render::FrameSubmitter& submitter,
                       render::SceneResources& resources, const char* program) {
    std::optional<std::filesystem::path> wanted = override_;
    if (!wanted && !frame.skyExrPath.empty()) wanted = world.resolveAssetPath(frame.skyExrPath);
    if (wanted == current_) return false;
    current_ = wanted;
    submitter.waitIdle();
    if (!wanted) {
        resources.setEnvironment(nullptr);
        return true;
    }
    content::Diagnostics diagnostics;
    resources.setEnvironment(render::Environment::load(context, *wanted, diagnostics));
    for (const content::Diagnostic& d : diagnostics.messages) {
        std::fprintf(stderr, "%s: %s\n", program, content::formatDiagnostic(d).c_str());
    }
    return true;
}

}  // namespace candela::runtime
