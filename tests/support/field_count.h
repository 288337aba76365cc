// The number of initializers an aggregate takes in braces: its field count, computed by the
// compiler, so that a test keeping one entry per field fails to compile when a field is
// added without an entry. (A C array field takes one initializer per element: brace
// elision.)
#pragma once

#include <cstddef>
#include <utility>

namespace pathcl::test {

namespace detail {

// Converts to any field type (declared only: used in unevaluated requires-expressions).
struct AnyField {
    template <class T>
    constexpr operator T() const;
};

template <class T, std::size_t... I>
constexpr bool braces_take(std::index_sequence<I...>)
{
    return requires
    {
        T{(void(I), AnyField{})...};
    };
}

} // namespace detail

template <class T, std::size_t N = 0>
constexpr std::size_t initializer_count()
{
    if constexpr (!detail::braces_take<T>(std::make_index_sequence<N + 1>{}))
        return N;
    else
        return initializer_count<T, N + 1>();
}

} // namespace pathcl::test
