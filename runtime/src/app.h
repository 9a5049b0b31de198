#pragma once
#include "run_options.h"

namespace candela::runtime {

// Exit codes of the candela executable.
enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1,       // something went wrong at run time (device, file write)
    kExitBadArguments = 2,  // the command line or the scene is wrong
    kExitValidation = 3,    // validation was required and the layer reported messages
};

// Renders a scene headless or in a window, then captures and writes stats as asked.
int runScene(const RunOptions& options);

}  // namespace candela::runtime
