// An allocator whose construct() without arguments default-initializes: a vector of a
// trivially constructible type is resized without its elements being written, so that
// the threads that fill it are the first to write (and fault in) its pages, rather than
// one thread zeroing them all first. The eight-wide light tree of a million lights is
// 125 MB, whose zeroing by std::vector took 75-100 ms on one core.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace pathcl {

template <class T, class Base = std::allocator<T>>
class DefaultInitAllocator : public Base {
public:
    using Base::Base;
    DefaultInitAllocator() = default;

    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
    };

    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>)
    {
        ::new (static_cast<void*>(p)) U;
    }

    template <class U, class... Args>
    void construct(U* p, Args&&... args)
    {
        std::allocator_traits<Base>::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
    }
};

// A vector whose resize leaves new elements of a trivially constructible type unwritten.
template <class T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace pathcl
