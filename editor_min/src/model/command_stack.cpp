#include "model/command_stack.h"

namespace candela::editor {

bool CommandStack::execute(EditorScene& scene, std::unique_ptr<EditCommand> command,
                           uint64_t mergeKey) {
    if (!command || !command->apply(scene)) return false;
    undone_.clear();
    undoneRevisions_.clear();
    revision_ = nextRevision_++;
    if (mergeKey != 0 && mergeKey == mergeKey_ && !done_.empty() &&
        done_.back()->absorb(*command)) {
        doneRevisions_.back() = revision_;
        return true;
    }
    done_.push_back(std::move(command));
    doneRevisions_.push_back(revision_);
    mergeKey_ = mergeKey;
    return true;
}

bool CommandStack::undo(EditorScene& scene) {
    if (done_.empty()) return false;
    mergeKey_ = 0;
    done_.back()->revert(scene);
    undone_.push_back(std::move(done_.back()));
    undoneRevisions_.push_back(doneRevisions_.back());
    done_.pop_back();
    doneRevisions_.pop_back();
    revision_ = doneRevisions_.empty() ? 0 : doneRevisions_.back();
    return true;
}

bool CommandStack::redo(EditorScene& scene) {
    if (undone_.empty()) return false;
    mergeKey_ = 0;
    // Redo re-applies what applied before; if the scene moved under it (it cannot through this
    // stack), drop the command rather than record an edit that did not happen.
    if (!undone_.back()->apply(scene)) {
        undone_.pop_back();
        undoneRevisions_.pop_back();
        return false;
    }
    done_.push_back(std::move(undone_.back()));
    doneRevisions_.push_back(undoneRevisions_.back());
    undone_.pop_back();
    undoneRevisions_.pop_back();
    revision_ = doneRevisions_.back();
    return true;
}

void CommandStack::clear() {
    done_.clear();
    undone_.clear();
    doneRevisions_.clear();
    undoneRevisions_.clear();
    mergeKey_ = 0;
    revision_ = 0;
}

}  // namespace candela::editor
