#pragma once
// The type lists a view is declared with: registry.view<A, const B>(exclude<C>).
namespace candela::ecs {

template <class... Ts>
struct TypeList {};

// Components an entity must NOT have to be visited: registry.view<A>(exclude<B, C>).
template <class... Ts>
struct Exclude {
    using AsTypeList = TypeList<Ts...>;
};
template <class... Ts>
inline constexpr Exclude<Ts...> exclude{};

}  // namespace candela::ecs
