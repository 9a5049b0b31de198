#pragma once
// The editor's top-level window. For now it opens, pumps events and closes.
#include <cstdint>

namespace candela::editor {

// Runs the editor window until it is closed, or for `frames` iterations when non-zero.
// Returns a process exit code; prints a clear message when no display is available.
int runEditorWindow(uint32_t frames);

}  // namespace candela::editor
