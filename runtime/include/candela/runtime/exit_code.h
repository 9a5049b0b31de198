#pragma once
// Exit codes of candela executables (the `candela` CLI and games built on Application).

namespace candela::runtime {

enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1,       // something went wrong at run time (device, file write)
    kExitBadArguments = 2,  // the command line, scene or input script is wrong
    kExitValidation = 3,    // validation was required and the layer reported messages
};

}  // namespace candela::runtime
