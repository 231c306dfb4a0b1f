// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_SINGLE_THREADED_BLAS_SCOPE_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_SINGLE_THREADED_BLAS_SCOPE_H

// The Solver_scope of the package's CHOLMOD models (Cholmod_sparse_solver, and
// Eigen's CHOLMOD solvers on real matrices through CGAL::Eigen_solver_traits).

#if defined(__unix__) || defined(__APPLE__)
#  include <dlfcn.h>
#  define CGAL_PVF_HAS_DLSYM 1
#endif

#include <mutex>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// While CHOLMOD factors and solves, OpenBLAS (when it is the BLAS that CHOLMOD
// calls) runs on one thread, for three reasons measured at 640k faces on 2
// cores: its threads bring nothing on these factors of surface meshes, whose
// supernodes are small (4.32 s to factor one degree with 2 threads, 4.28 s
// with 1); when the degrees are factored in parallel, its threads
// oversubscribe the cores and it serialises concurrent callers on its thread
// pool (12.3 s for two degrees in parallel with its threads, 5.2 s with one
// thread each, 8.9 s one degree after the other); and its results depend on
// its number of threads in the last bits, so that a parallel run would not
// be bit-identical to a sequential one. OpenBLAS is looked up at run time,
// so any BLAS may be linked. Its thread count is a process-wide setting:
// scopes alive at the same time in several threads of a program share one
// count of users, the first one in sets one thread and the last one out
// restores the previous count. (This holds for OpenBLAS's pthreads build,
// Debian's libopenblas0-pthread; its OpenMP build takes the count from each
// calling thread's OpenMP setting instead.)
class Single_threaded_blas_scope
{
  typedef void (*Set_threads)(int);
  typedef int (*Get_threads)();

  struct Shared_state
  {
    std::mutex mutex;
    int users = 0;
    int saved = 1;
    bool held = false;  // the count is held at one by the scopes
    Set_threads set = nullptr;
    Get_threads get = nullptr;

    Shared_state()
    {
#ifdef CGAL_PVF_HAS_DLSYM
      set = reinterpret_cast<Set_threads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
      get = reinterpret_cast<Get_threads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
#endif
    }
  };

  static Shared_state& state()
  {
    static Shared_state s;  // OpenBLAS looked up once
    return s;
  }

public:
  Single_threaded_blas_scope()
  {
    Shared_state& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    if(s.users++ > 0 || s.set == nullptr || s.get == nullptr)
      return;
    s.saved = s.get();
    s.held = (s.saved > 1);
    if(s.held)
      s.set(1);
  }
  ~Single_threaded_blas_scope()
  {
    Shared_state& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    if(--s.users == 0 && s.held)
    {
      s.set(s.saved);
      s.held = false;
    }
  }
  Single_threaded_blas_scope(const Single_threaded_blas_scope&) = delete;
  Single_threaded_blas_scope& operator=(const Single_threaded_blas_scope&) = delete;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_SINGLE_THREADED_BLAS_SCOPE_H
