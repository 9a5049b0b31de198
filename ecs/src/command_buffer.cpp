#include <candela/ecs/command_buffer.h>

namespace candela::ecs {

CommandBuffer::CommandBuffer(CommandBuffer&& other) noexcept
    : registry_(other.registry_),
      commands_(std::move(other.commands_)),
      blocks_(std::move(other.blocks_)),
      largeBlocks_(std::move(other.largeBlocks_)),
      block_(other.block_),
      offset_(other.offset_) {
    other.commands_.clear();
    other.block_ = 0;
    other.offset_ = 0;
}

CommandBuffer& CommandBuffer::operator=(CommandBuffer&& other) noexcept {
    if (this != &other) {
        clear();
        registry_ = other.registry_;
        commands_ = std::move(other.commands_);
        blocks_ = std::move(other.blocks_);
        largeBlocks_ = std::move(other.largeBlocks_);
        block_ = other.block_;
        offset_ = other.offset_;
        other.commands_.clear();
        other.block_ = 0;
        other.offset_ = 0;
    }
    return *this;
}

Entity CommandBuffer::create() {
    const Entity e = registry_->reserve();
    record(Kind::Create, e, nullptr, nullptr, nullptr);
    return e;
}

void CommandBuffer::defer(std::function<void(Registry&)> fn) {
    using Fn = std::function<void(Registry&)>;
    void* payload = allocatePayload(sizeof(Fn), alignof(Fn));
    ::new (payload) Fn(std::move(fn));
    record(
        Kind::Deferred, kNullEntity,
        [](Registry& r, Entity, void* p) {
            Fn& call = *static_cast<Fn*>(p);
            Fn local = std::move(call);
            call.~Fn();
            local(r);
        },
        [](void* p) noexcept { static_cast<Fn*>(p)->~Fn(); }, payload);
}

void* CommandBuffer::allocatePayload(std::size_t size, std::size_t alignment) {
    auto newBlock = [](std::size_t bytes) {
        return Block(
            static_cast<std::byte*>(::operator new(bytes, std::align_val_t(kBlockAlignment))));
    };
    if (size > kBlockSize / 4) {
        largeBlocks_.push_back(newBlock(size));
        return largeBlocks_.back().get();
    }
    offset_ = (offset_ + alignment - 1) / alignment * alignment;
    if (blocks_.empty() || offset_ + size > kBlockSize) {
        if (!blocks_.empty()) ++block_;
        if (block_ == blocks_.size()) blocks_.push_back(newBlock(kBlockSize));
        offset_ = 0;
    }
    void* p = blocks_[block_].get() + offset_;
    offset_ += size;
    return p;
}

CommandBuffer::ApplyResult CommandBuffer::apply() {
    ApplyResult result;
    Registry& r = *registry_;
    // Fail before consuming anything, rather than halfway through.
    CANDELA_ECS_CHECK(commands_.empty() || !r.structureLocked(),
                      EcsErrorCode::StructuralChangeWhileLocked,
                      "CommandBuffer::apply() while iterating or inside a hook");
    // Index loop: a deferred call may record into this same buffer; those run too.
    for (std::size_t i = 0; i < commands_.size(); ++i) {
        Command& c = commands_[i];
        const Command command = c;
        c.payload = nullptr;  // consumed, whatever happens next
        c.kind = Kind::Deferred;
        switch (command.kind) {
            case Kind::Create:
                r.createReserved(command.entity);
                ++result.applied;
                break;
            case Kind::Destroy:
                if (r.valid(command.entity)) {
                    r.destroy(command.entity);
                    ++result.applied;
                } else {
                    ++result.skipped;
                }
                break;
            case Kind::Component:
                if (r.valid(command.entity)) {
                    command.run(r, command.entity, command.payload);
                    ++result.applied;
                } else {
                    if (command.dispose) command.dispose(command.payload);
                    ++result.skipped;
                }
                break;
            case Kind::Deferred:
                command.run(r, command.entity, command.payload);
                ++result.applied;
                break;
        }
    }
    commands_.clear();
    clear();
    return result;
}

void CommandBuffer::clear() noexcept {
    for (const Command& c : commands_) {
        if (c.kind == Kind::Create) {
            if (!registry_->structureLocked()) registry_->releaseReserved(c.entity);
        } else if (c.payload != nullptr && c.dispose != nullptr) {
            c.dispose(c.payload);
        }
    }
    commands_.clear();
    largeBlocks_.clear();
    block_ = 0;
    offset_ = 0;
}

}  // namespace candela::ecs
