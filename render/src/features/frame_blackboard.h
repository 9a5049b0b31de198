#pragma once
// What the features of one frame hand each other (Filament's FrameGraph blackboard, typed): each
// publishes a plain struct of its own (the scene targets, the lit inputs, the froxels...) and
// later features look it up by type. Cleared at the start of every frame; the handles it holds
// are valid only while that frame is declared.
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace candela::render {

class FrameBlackboard {
public:
    // Publishes `value` (replacing an earlier one of its type) and returns the stored copy.
    template <class T>
    T& put(T value) {
        if (T* existing = find<T>()) return *existing = std::move(value);
        auto stored = std::make_shared<T>(std::move(value));
        T& result = *stored;
        entries_.push_back({key<T>(), std::move(stored)});
        return result;
    }
    // What an earlier feature published, or null.
    template <class T>
    T* find() const {
        for (const Entry& e : entries_) {
            if (e.key == key<T>()) return static_cast<T*>(e.value.get());
        }
        return nullptr;
    }
    // What an earlier feature must have published: a feature order that breaks this is a bug.
    template <class T>
    T& get() const {
        if (T* value = find<T>()) return *value;
        throw std::logic_error(std::string("frame blackboard: nothing published as ") +
                               typeid(T).name());
    }
    void clear() { entries_.clear(); }

private:
    // One address per type, the same in every translation unit (an inline function's static).
    template <class T>
    static const void* key() {
        static const char k = 0;
        return &k;
    }
    struct Entry {
        const void* key;
        std::shared_ptr<void> value;
    };
    std::vector<Entry> entries_;
};

}  // namespace candela::render
