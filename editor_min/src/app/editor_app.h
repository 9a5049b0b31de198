#pragma once
#include "app/editor_options.h"

namespace candela::editor {

// Exit codes, as the candela executable uses them.
enum EditorExit : int {
    kEditorOk = 0,
    kEditorFailure = 1,       // run-time failure: device, a failed script step or save
    kEditorBadArguments = 2,  // bad command line, scene or script file
    kEditorValidation = 3,    // validation messages while validation was required
};

// Opens the window and runs the editor until it is closed, `frames` have run, or the script
// quits.
int runEditor(const EditorOptions& options);

}  // namespace candela::editor
