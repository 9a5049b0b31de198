#pragma once
// `candela run` and `candela demo`: loads the scene named on the command line and runs it on
// an Application.
#include <memory>
#include <vector>

#include "candela/runtime/application.h"
#include "candela/runtime/exit_code.h"
#include "run_options.h"

namespace candela::runtime {

// Renders a scene headless or in a window, then captures and writes stats as asked. `layers`
// draw over the frames (the demo's stats overlay).
int runScene(const RunOptions& options, std::vector<std::shared_ptr<FrameLayer>> layers = {});

}  // namespace candela::runtime
