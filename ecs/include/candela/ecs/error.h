#pragma once
// The ECS reports misuse (stale handles, structural changes while iterating, missing
// components) as EcsError. Debug builds assert first so the debugger stops at the call site;
// release builds throw, so misuse is never silent corruption.
#include <cassert>
#include <stdexcept>

namespace candela::ecs {

enum class EcsErrorCode {
    StaleEntity,                  // the handle's entity was destroyed (or never existed)
    MissingComponent,             // get<T>() on an entity without T
    MissingResource,              // resources().get<T>() with no T emplaced
    StructuralChangeWhileLocked,  // create/destroy/emplace/remove during iteration or a hook
    EntityLimitReached,           // all 2^32-1 slot indices are in use or retired
    GroupConflict,                // a component pool already belongs to another group
};

class EcsError : public std::logic_error {
public:
    EcsError(EcsErrorCode code, const char* what) : std::logic_error(what), code_(code) {}
    EcsErrorCode code() const noexcept { return code_; }

private:
    EcsErrorCode code_;
};

namespace detail {
[[noreturn]] void throwEcsError(EcsErrorCode code, const char* what);
}  // namespace detail

}  // namespace candela::ecs

// Debug: assert (stops in the debugger). Always: throw EcsError if the check fails.
#define CANDELA_ECS_CHECK(condition, code, message)                   \
    do {                                                              \
        if (!(condition)) [[unlikely]] {                              \
            assert(false && (message));                               \
            ::candela::ecs::detail::throwEcsError((code), (message)); \
        }                                                             \
    } while (false)
