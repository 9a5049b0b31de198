#pragma once
// A stable name for an entity across undo/redo: deleting an entity and undoing the delete makes
// a new ecs::Entity, so edit commands refer to entities by EditorId and look them up.
#include <cstdint>

namespace candela::editor {

struct EditorId {
    std::uint64_t value = 0;  // 0: none
};

}  // namespace candela::editor
