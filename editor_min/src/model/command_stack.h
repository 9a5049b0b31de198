#pragma once
// Undo/redo as a stack of applied commands and a stack of undone ones. A new edit clears the
// redo stack. Consecutive edits with the same non-zero merge key fold into one undo step until
// closeMerge() (the UI calls it when a widget is released).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/edit_command.h"

namespace candela::editor {

class CommandStack {
public:
    // Applies `command` and records it; false (and nothing recorded) when it did not apply.
    bool execute(EditorScene& scene, std::unique_ptr<EditCommand> command, uint64_t mergeKey = 0);
    bool undo(EditorScene& scene);
    bool redo(EditorScene& scene);
    void closeMerge() { mergeKey_ = 0; }
    void clear();

    bool canUndo() const { return !done_.empty(); }
    bool canRedo() const { return !undone_.empty(); }
    std::string undoLabel() const { return canUndo() ? done_.back()->label() : std::string(); }
    std::string redoLabel() const { return canRedo() ? undone_.back()->label() : std::string(); }
    size_t undoCount() const { return done_.size(); }
    size_t redoCount() const { return undone_.size(); }
    // Changes on every execute/undo/redo that changes the scene; compare to know unsaved edits.
    uint64_t revision() const { return revision_; }

private:
    std::vector<std::unique_ptr<EditCommand>> done_;
    std::vector<std::unique_ptr<EditCommand>> undone_;
    uint64_t mergeKey_ = 0;
    uint64_t revision_ = 0;
    uint64_t nextRevision_ = 1;
    std::vector<uint64_t> doneRevisions_;  // revision after each done_ entry
    std::vector<uint64_t> undoneRevisions_;
};

}  // namespace candela::editor
