#pragma once
// Records structural changes (create, destroy, add, remove, or any deferred call) to apply
// later at a defined point, typically a scheduler sync point. Use one buffer per thread:
// recording is not synchronised, but create() is, so buffers on several threads can hand out
// new entity handles at once.
//
// apply() runs the commands in the order they were recorded, exactly as if the same calls were
// made on the registry at that moment. So, on one entity:
//   add then remove   -> the component is absent; on-add and on-remove each fire once.
//   remove then add   -> the component is present with the added value.
//   destroy then add  -> the entity stays destroyed; the add is skipped (counted in
//                        ApplyResult::skipped), as is any command aimed at a dead entity.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include <candela/ecs/registry.h>

namespace candela::ecs {

class CommandBuffer {
public:
    struct ApplyResult {
        std::size_t applied = 0;
        std::size_t skipped = 0;  // aimed at an entity that was dead when its turn came
    };

    explicit CommandBuffer(Registry& registry) : registry_(&registry) {}
    ~CommandBuffer() { clear(); }
    CommandBuffer(CommandBuffer&& other) noexcept;
    CommandBuffer& operator=(CommandBuffer&& other) noexcept;
    CommandBuffer(const CommandBuffer&) = delete;
    CommandBuffer& operator=(const CommandBuffer&) = delete;

    // A handle usable right away in later commands (of this buffer, or of buffers applied
    // after it); the entity exists once apply() runs.
    Entity create();
    void destroy(Entity e) { record(Kind::Destroy, e, nullptr, nullptr, nullptr); }
    template <Component T, class... Args>
    void emplace(Entity e, Args&&... args);
    template <Component T>
    void remove(Entity e);
    // Any other deferred work, e.g. [=](Registry& r) { (void)setParent(r, child, parent); }.
    void defer(std::function<void(Registry&)> fn);

    // Applies and clears. Must run where structural changes are allowed (not while iterating).
    ApplyResult apply();
    // Drops all commands. Handles from create() that were never applied are released, unless
    // the registry's structure is locked (inside a parallel stage), where they stay reserved.
    void clear() noexcept;

    bool empty() const noexcept { return commands_.empty(); }
    std::size_t size() const noexcept { return commands_.size(); }
    Registry& registry() const noexcept { return *registry_; }

private:
    enum class Kind : std::uint8_t { Create, Destroy, Component, Deferred };
    using Run = void (*)(Registry&, Entity, void* payload);
    using Dispose = void (*)(void* payload) noexcept;
    struct Command {
        Kind kind;
        Entity entity;
        Run run;
        Dispose dispose;  // destroys the payload if the command never ran
        void* payload;
    };

    void record(Kind kind, Entity e, Run run, Dispose dispose, void* payload) {
        commands_.push_back(Command{kind, e, run, dispose, payload});
    }
    // Payloads live in fixed blocks that never move, so non-trivial types are safe.
    void* allocatePayload(std::size_t size, std::size_t alignment);

    static constexpr std::size_t kBlockSize = 16 * 1024;
    static constexpr std::size_t kBlockAlignment = 64;
    struct BlockDeleter {
        void operator()(std::byte* p) const noexcept {
            ::operator delete(p, std::align_val_t(kBlockAlignment));
        }
    };
    using Block = std::unique_ptr<std::byte, BlockDeleter>;

    Registry* registry_;
    std::vector<Command> commands_;
    std::vector<Block> blocks_;       // standard blocks, reused after clear()
    std::vector<Block> largeBlocks_;  // one per oversized payload, freed on clear()
    std::size_t block_ = 0;           // current standard block
    std::size_t offset_ = 0;          // bytes used in it
};

template <Component T, class... Args>
void CommandBuffer::emplace(Entity e, Args&&... args) {
    static_assert(alignof(T) <= kBlockAlignment, "over-aligned component");
    void* payload = allocatePayload(sizeof(T), alignof(T));
    ::new (payload) T(detail::makeComponent<T>(std::forward<Args>(args)...));
    record(
        Kind::Component, e,
        [](Registry& r, Entity target, void* p) {
            struct EndsValue {  // the payload dies even if emplace throws
                T* value;
                ~EndsValue() { value->~T(); }
            } guard{static_cast<T*>(p)};
            r.emplace<T>(target, std::move(*guard.value));
        },
        [](void* p) noexcept { static_cast<T*>(p)->~T(); }, payload);
}

template <Component T>
void CommandBuffer::remove(Entity e) {
    record(
        Kind::Component, e, [](Registry& r, Entity target, void*) { r.remove<T>(target); }, nullptr,
        nullptr);
}

}  // namespace candela::ecs
