// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_PARALLEL_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_PARALLEL_H

// The package's one way to run independent work in parallel (TBB, when it is
// linked), and its one stopwatch. Every parallel loop of the package goes
// through for_each_range() or invoke_both(), so that the choice between the
// threads and the calling thread is made in one place.

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#  include <tbb/blocked_range.h>
#  include <tbb/enumerable_thread_specific.h>
#  include <tbb/parallel_for.h>
#  include <tbb/parallel_invoke.h>
#endif

#include <chrono>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Whether `T` is one of CGAL's concurrency tags (`Sequential_tag`, `Parallel_tag`,
// `Parallel_if_available_tag`).
template <typename T>
struct Is_concurrency_tag : std::is_convertible<T, CGAL::Sequential_tag> {};

// Calls `range(begin, end)` on consecutive ranges that cover 0 .. n-1 once:
// with `CGAL::Parallel_tag` (and TBB), on several threads, in ranges of about
// `grain` indices; otherwise once on the calling thread. `range` must treat
// each index independently of the others, so that the result does not depend
// on how the indices are split.
template <typename ConcurrencyTag, typename Range>
void for_each_range(std::size_t n, std::size_t grain, const Range& range)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && n > grain)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&range](const tbb::blocked_range<std::size_t>& r) { range(r.begin(), r.end()); });
    return;
  }
#else
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  range(std::size_t(0), n);
}

// Calls `a()` and `b()`: with `CGAL::Parallel_tag` (and TBB) at the same time,
// otherwise one after the other. They must not write the same data.
// for_each_range() with a scratch object per thread: calls
// `range(scratch, begin, end)`, the scratch made by `make()` the first time a
// thread runs a range (one scratch in all when the loop runs on the calling
// thread). For a scratch whose making costs as much as the whole input, such
// as a stamp per vertex of the mesh: one per range would cost n / grain times
// that. `range` must leave the scratch fit for any other range, and treat each
// index independently of the others.
template <typename ConcurrencyTag, typename Make, typename Range>
void for_each_range_with_scratch(std::size_t n, std::size_t grain, const Make& make, const Range& range)
{
  typedef decltype(make()) Scratch;
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && n > grain)
  {
    tbb::enumerable_thread_specific<std::unique_ptr<Scratch> > scratch;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        std::unique_ptr<Scratch>& mine = scratch.local();
                        if(!mine)
                          mine.reset(new Scratch(make()));
                        range(*mine, r.begin(), r.end());
                      });
    return;
  }
#else
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
  (void)grain;
#endif
  Scratch scratch = make();
  range(scratch, std::size_t(0), n);
}

template <typename ConcurrencyTag, typename A, typename B>
void invoke_both(const A& a, const B& b)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    tbb::parallel_invoke(a, b);
    return;
  }
#endif
  a();
  b();
}

// An allocator that leaves the elements of `resize(n)` default-initialised
// (uninitialised for a trivial type), so that a vector is first written, and
// its memory first touched, by the threads that compute it.
template <typename T>
struct Uninitialized_allocator : std::allocator<T>
{
  template <typename U>
  struct rebind { typedef Uninitialized_allocator<U> other; };
  Uninitialized_allocator() = default;
  template <typename U>
  Uninitialized_allocator(const Uninitialized_allocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new(static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// Calls `range(begin, end)` on consecutive ranges that cover 0 .. n-1 once:
// when `parallel` is true (and TBB is linked), on several threads in ranges of
// about `grain` indices; otherwise once on the calling thread. For the classes
// that hold the choice as a value rather than as a concurrency tag.
template <typename Range>
void for_each_range(bool parallel, std::size_t n, std::size_t grain, const Range& range)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel && n > grain)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      [&range](const tbb::blocked_range<std::size_t>& r) { range(r.begin(), r.end()); });
    return;
  }
#else
  (void)parallel;
  (void)grain;
#endif
  range(std::size_t(0), n);
}

// Calls `task(i)` for i in 0 .. n-1, each on a thread of its own when
// `parallel` is true (and TBB is linked): for a few large independent tasks
// (the blocks of a system, the chunks of a matrix).
template <typename Task>
void for_each_index(bool parallel, std::size_t n, const Task& task)
{
  for_each_range(parallel, n, 1, [&task](std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
      task(i);
  });
}

// Seconds since construction.
struct Timer
{
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_PARALLEL_H
