#include <candela/ecs/hierarchy.h>

#include <candela/ecs/registry.h>

namespace candela::ecs {
namespace {

// Lives in the registry's resources; created with the first link so plain registries pay
// nothing for hierarchy support.
struct HierarchyState {
    std::uint64_t version = 1;
    HookId unlinkHook{};
};

void setSubtreeDepth(Registry& registry, Entity root, std::uint32_t depth) {
    std::vector<Entity> stack{root};
    registry.get<HierarchyNode>(root).depth = depth;
    while (!stack.empty()) {
        const Entity e = stack.back();
        stack.pop_back();
        const HierarchyNode& node = registry.get<HierarchyNode>(e);
        for (Entity c = node.firstChild; !c.isNull();) {
            HierarchyNode& child = registry.get<HierarchyNode>(c);
            child.depth = node.depth + 1;
            if (!child.firstChild.isNull()) stack.push_back(c);
            c = child.nextSibling;
        }
    }
}

// Removes e from its parent's child list (leaves e's own children alone).
void unlinkFromParent(Registry& registry, HierarchyNode& node) {
    if (node.parent.isNull()) return;
    HierarchyNode& parent = registry.get<HierarchyNode>(node.parent);
    if (node.prevSibling.isNull()) {
        parent.firstChild = node.nextSibling;
    } else {
        registry.get<HierarchyNode>(node.prevSibling).nextSibling = node.nextSibling;
    }
    if (node.nextSibling.isNull()) {
        parent.lastChild = node.prevSibling;
    } else {
        registry.get<HierarchyNode>(node.nextSibling).prevSibling = node.prevSibling;
    }
    --parent.childCount;
    node.parent = kNullEntity;
    node.prevSibling = kNullEntity;
    node.nextSibling = kNullEntity;
}

// On-remove hook: a node leaving (destroyed, or its HierarchyNode removed) is cut out of the
// tree; its children become roots.
void detachNode(Registry& registry, Entity e) {
    HierarchyNode& node = registry.get<HierarchyNode>(e);
    unlinkFromParent(registry, node);
    for (Entity c = node.firstChild; !c.isNull();) {
        HierarchyNode& child = registry.get<HierarchyNode>(c);
        const Entity next = child.nextSibling;
        child.parent = kNullEntity;
        child.prevSibling = kNullEntity;
        child.nextSibling = kNullEntity;
        setSubtreeDepth(registry, c, 0);
        c = next;
    }
    node.firstChild = kNullEntity;
    node.lastChild = kNullEntity;
    node.childCount = 0;
    ++registry.resources().get<HierarchyState>().version;
}

HierarchyState& state(Registry& registry) {
    if (HierarchyState* s = registry.resources().tryGet<HierarchyState>()) return *s;
    HierarchyState& s = registry.resources().emplace<HierarchyState>();
    s.unlinkHook = registry.onRemove<HierarchyNode>(detachNode);
    return s;
}

}  // namespace

ReparentResult setParent(Registry& registry, Entity child, Entity parent) {
    if (!registry.valid(child)) return ReparentResult::StaleChild;
    if (!parent.isNull() && !registry.valid(parent)) return ReparentResult::StaleParent;
    if (child == parent || (!parent.isNull() && isAncestorOf(registry, child, parent))) {
        return ReparentResult::WouldCreateCycle;
    }
    HierarchyState& s = state(registry);
    if (parent.isNull()) {
        HierarchyNode* node = registry.tryGet<HierarchyNode>(child);
        if (node == nullptr || node->parent.isNull()) return ReparentResult::Ok;
        unlinkFromParent(registry, *node);
        setSubtreeDepth(registry, child, 0);
        ++s.version;
        return ReparentResult::Ok;
    }
    // Add both nodes first: adding to a pool can reallocate it and invalidate references.
    if (!registry.has<HierarchyNode>(child)) registry.emplace<HierarchyNode>(child);
    if (!registry.has<HierarchyNode>(parent)) registry.emplace<HierarchyNode>(parent);
    HierarchyNode& node = registry.get<HierarchyNode>(child);
    if (node.parent == parent) return ReparentResult::Ok;
    unlinkFromParent(registry, node);

    HierarchyNode& parentNode = registry.get<HierarchyNode>(parent);
    node.parent = parent;
    node.prevSibling = parentNode.lastChild;
    if (parentNode.lastChild.isNull()) {
        parentNode.firstChild = child;
    } else {
        registry.get<HierarchyNode>(parentNode.lastChild).nextSibling = child;
    }
    parentNode.lastChild = child;
    ++parentNode.childCount;
    setSubtreeDepth(registry, child, parentNode.depth + 1);
    ++s.version;
    return ReparentResult::Ok;
}

Entity parentOf(const Registry& registry, Entity e) {
    const HierarchyNode* node = registry.tryGet<HierarchyNode>(e);
    return node ? node->parent : kNullEntity;
}

std::uint32_t depthOf(const Registry& registry, Entity e) {
    const HierarchyNode* node = registry.tryGet<HierarchyNode>(e);
    return node ? node->depth : 0;
}

std::vector<Entity> childrenOf(const Registry& registry, Entity e) {
    std::vector<Entity> out;
    const HierarchyNode* node = registry.tryGet<HierarchyNode>(e);
    if (node == nullptr) return out;
    out.reserve(node->childCount);
    for (Entity c = node->firstChild; !c.isNull(); c = registry.get<HierarchyNode>(c).nextSibling) {
        out.push_back(c);
    }
    return out;
}

std::vector<Entity> descendantsOf(const Registry& registry, Entity e) {
    std::vector<Entity> out = childrenOf(registry, e);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const HierarchyNode& node = registry.get<HierarchyNode>(out[i]);
        for (Entity c = node.firstChild; !c.isNull();
             c = registry.get<HierarchyNode>(c).nextSibling) {
            out.push_back(c);
        }
    }
    return out;
}

bool isAncestorOf(const Registry& registry, Entity ancestor, Entity e) {
    const HierarchyNode* a = registry.tryGet<HierarchyNode>(ancestor);
    const HierarchyNode* node = registry.tryGet<HierarchyNode>(e);
    if (a == nullptr || node == nullptr) return false;
    // Only nodes deeper than `ancestor` can be below it: climb no higher than its depth.
    while (node->depth > a->depth) {
        if (node->parent == ancestor) return true;
        node = &registry.get<HierarchyNode>(node->parent);
    }
    return false;
}

void destroyWithDescendants(Registry& registry, Entity e) {
    if (!registry.valid(e)) return;
    std::vector<Entity> doomed = descendantsOf(registry, e);
    // Children first, so each detach touches as little of the tree as possible.
    for (auto it = doomed.rbegin(); it != doomed.rend(); ++it)
        registry.destroy(*it);
    registry.destroy(e);
}

std::uint64_t hierarchyVersion(const Registry& registry) {
    const HierarchyState* s = registry.resources().tryGet<HierarchyState>();
    return s ? s->version : 0;
}

}  // namespace candela::ecs
