#pragma once
// `candela run` and `candela demo`: loads the scene named on the command line and runs it on
// an Application.
#include "candela/runtime/exit_code.h"
#include "run_options.h"

namespace candela::runtime {

// Renders a scene headless or in a window, then captures and writes stats as asked.
int runScene(const RunOptions& options);

}  // namespace candela::runtime
