#pragma once
// Resources are singletons that live next to the entities (time, input, the renderer's upload
// state). At most one value per type. Lookups are a vector index, so systems can fetch them
// every frame. Adding or removing a resource is not thread-safe; reading one from parallel
// systems is (the scheduler orders writers through the declared resource accesses).
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <candela/ecs/error.h>

namespace candela::ecs {

namespace detail {
std::uint32_t allocateResourceId() noexcept;
}  // namespace detail

// Always inlined, as componentId: a guard-byte test rather than a call per lookup.
template <class T>
[[gnu::always_inline]] inline std::uint32_t resourceId() noexcept {
    static const std::uint32_t id = detail::allocateResourceId();
    return id;
}

class Resources {
public:
    Resources() = default;
    Resources(const Resources&) = delete;
    Resources& operator=(const Resources&) = delete;
    ~Resources() { clear(); }

    // Creates (or replaces) the resource of type T.
    template <class T, class... Args>
    T& emplace(Args&&... args) {
        static_assert(std::is_same_v<T, std::remove_cvref_t<T>>);
        const std::uint32_t id = resourceId<T>();
        if (id >= slots_.size()) slots_.resize(id + 1);
        Slot& s = slots_[id];
        s.reset();
        T* object = new T(std::forward<Args>(args)...);
        s.object = object;
        s.destroy = [](void* p) noexcept { delete static_cast<T*>(p); };
        s.order = nextOrder_++;
        return *object;
    }

    template <class T>
    T* tryGet() noexcept {
        const std::uint32_t id = resourceId<T>();
        return id < slots_.size() ? static_cast<T*>(slots_[id].object) : nullptr;
    }
    template <class T>
    const T* tryGet() const noexcept {
        const std::uint32_t id = resourceId<T>();
        return id < slots_.size() ? static_cast<const T*>(slots_[id].object) : nullptr;
    }
    // The resource must exist (EcsError MissingResource otherwise; tryGet() to probe).
    template <class T>
    T& get() {
        T* p = tryGet<T>();
        CANDELA_ECS_CHECK(p != nullptr, EcsErrorCode::MissingResource,
                          "resources().get<T>() before emplace<T>()");
        return *p;
    }
    template <class T>
    const T& get() const {
        const T* p = tryGet<T>();
        CANDELA_ECS_CHECK(p != nullptr, EcsErrorCode::MissingResource,
                          "resources().get<T>() before emplace<T>()");
        return *p;
    }
    template <class T>
    bool has() const noexcept {
        return tryGet<T>() != nullptr;
    }
    // Returns the existing resource or creates one from `args`.
    template <class T, class... Args>
    T& getOrEmplace(Args&&... args) {
        if (T* p = tryGet<T>()) return *p;
        return emplace<T>(std::forward<Args>(args)...);
    }
    template <class T>
    bool remove() noexcept {
        const std::uint32_t id = resourceId<T>();
        if (id >= slots_.size() || slots_[id].object == nullptr) return false;
        slots_[id].reset();
        return true;
    }
    // Destroys resources newest first, so a resource may refer to one created before it.
    void clear() noexcept;

private:
    struct Slot {
        void* object = nullptr;
        void (*destroy)(void*) noexcept = nullptr;
        std::uint64_t order = 0;
        void reset() noexcept {
            if (object != nullptr) destroy(object);
            object = nullptr;
        }
    };
    std::vector<Slot> slots_;
    std::uint64_t nextOrder_ = 0;
};

}  // namespace candela::ecs
