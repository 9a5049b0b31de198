#pragma once
// Parent/child links stored as plain data in a HierarchyNode component: an intrusive doubly
// linked list of children plus a depth key (0 for roots). The depth orders transform
// propagation (parents before children) and makes the cycle check cheap: a node can only be
// an ancestor of nodes deeper than itself.
//
// Change links only through these functions; they keep the lists and depths consistent.
// Destroying an entity (or removing its HierarchyNode) detaches it: its children become roots.
#include <cstdint>
#include <vector>

#include <candela/ecs/entity.h>

namespace candela::ecs {

class Registry;

struct HierarchyNode {
    Entity parent = kNullEntity;
    Entity firstChild = kNullEntity;
    Entity lastChild = kNullEntity;
    Entity prevSibling = kNullEntity;
    Entity nextSibling = kNullEntity;
    std::uint32_t depth = 0;
    std::uint32_t childCount = 0;
};

enum class ReparentResult {
    Ok,
    StaleChild,
    StaleParent,
    WouldCreateCycle,  // the new parent is the child itself or one of its descendants
};

// Makes `child` the last child of `parent` (kNullEntity: make it a root). Adds HierarchyNode
// to both as needed, so it is a structural change: not allowed while iterating (use
// CommandBuffer::defer). On any result but Ok nothing changes.
[[nodiscard]] ReparentResult setParent(Registry& registry, Entity child, Entity parent);

// kNullEntity for roots and entities outside any hierarchy.
Entity parentOf(const Registry& registry, Entity e);
std::uint32_t depthOf(const Registry& registry, Entity e);
std::vector<Entity> childrenOf(const Registry& registry, Entity e);
// Every descendant of e, parents before children (e itself excluded).
std::vector<Entity> descendantsOf(const Registry& registry, Entity e);
bool isAncestorOf(const Registry& registry, Entity ancestor, Entity e);

// Destroys e and all its descendants.
void destroyWithDescendants(Registry& registry, Entity e);

// Bumped on every link change; caches derived from the hierarchy compare it.
std::uint64_t hierarchyVersion(const Registry& registry);

}  // namespace candela::ecs
