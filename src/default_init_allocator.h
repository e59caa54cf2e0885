// Internal: an allocator whose containers leave new numbers uninitialised.
//
// Why: std::vector<T>(n) and resize(n) zero their new elements with one memset on the calling
// thread, and at millions of rows that memset is the first touch of fresh pages, each of which
// the kernel zeroes again: at 5M faces ~1 GB of the solvers' work vectors, a second or more of
// a two-thread process spent on one thread (docs/performance.md, "sixteenth round"). Vectors
// with this allocator are written row by row by the library's parallel loops instead, so the
// pages are touched on both threads, once. Only for arrays that are written in full before
// they are read.
#pragma once
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace msmesh::detail {

template <class T, class Base = std::allocator<T>>
class DefaultInitAllocator : public Base {
  using Traits = std::allocator_traits<Base>;

 public:
  template <class U>
  struct rebind {  // NOLINT(readability-identifier-naming): the allocator protocol names these
    using other =  // NOLINT(readability-identifier-naming)
        DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };
  using Base::Base;
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>& other) noexcept
      : Base(other) {}

  /// Value-initialisation (vector's resize(n)) becomes default-initialisation: nothing for numbers.
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    Traits::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

/// A vector of numbers whose resize leaves the new ones unset.
template <class T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace msmesh::detail
