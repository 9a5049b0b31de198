#pragma once
// Query building blocks shared by Registry and View: the type lists a view is declared with,
// and the per-registry cache of tables that match a query.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <candela/ecs/component_type.h>

namespace candela::ecs {

class Archetype;

template <class... Ts>
struct TypeList {};

// Components an entity must NOT have to be visited: registry.view<A>(exclude<B, C>).
template <class... Ts>
struct Exclude {
    using AsTypeList = TypeList<Ts...>;
};
template <class... Ts>
inline constexpr Exclude<Ts...> exclude{};

namespace detail {

std::uint32_t allocateQueryId() noexcept;

// One id per distinct (include, exclude) set, const-ness ignored.
template <class Include, class ExcludeList>
std::uint32_t queryId() noexcept {
    static const std::uint32_t id = allocateQueryId();
    return id;
}

// Tables matching one query, extended lazily as new tables appear.
struct QueryCache {
    std::vector<ComponentId> include;
    std::vector<ComponentId> exclude;
    std::vector<Archetype*> tables;
    std::vector<std::uint32_t> columns;  // tables.size() x include.size(): column per include
    std::atomic<std::size_t> tablesSeen{0};
};

}  // namespace detail
}  // namespace candela::ecs
