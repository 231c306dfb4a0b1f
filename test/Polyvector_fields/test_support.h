// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Helpers on fields and complex numbers shared by the tests: random complex
// numbers, the relative difference of two coefficient arrays, a field
// designed with a given solver and concurrency tag, and OpenBLAS's thread
// count. (Meshes are in
// test_meshes.h, the helpers of the IO tests in io_test_support.h.)

#ifndef CGAL_POLYVECTOR_FIELDS_TEST_SUPPORT_H
#define CGAL_POLYVECTOR_FIELDS_TEST_SUPPORT_H

#include <CGAL/Polyvector_fields/Polyvector_field_designer.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#if defined(__unix__) || defined(__APPLE__)
#  include <dlfcn.h>
#endif

#include <algorithm>
#include <complex>
#include <cstddef>
#include <random>
#include <vector>

namespace pvf_test {

// x + iy with x and y independent, normally distributed, of standard deviation `scale`.
inline std::complex<double> random_complex(std::mt19937_64& rng, double scale = 1.)
{
  std::normal_distribution<double> normal(0., 1.);
  const double x = normal(rng);
  const double y = normal(rng);
  return scale * std::complex<double>(x, y);
}

// max |a - b| / max |a| (max |a - b| when a is zero); the sizes must agree.
inline double relative_difference(const std::vector<std::complex<double> >& a,
                                  const std::vector<std::complex<double> >& b)
{
  EXPECT_EQ(a.size(), b.size());
  double difference = 0, size = 0;
  for(std::size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    difference = (std::max)(difference, std::abs(a[i] - b[i]));
    size = (std::max)(size, std::abs(a[i]));
  }
  return size > 0 ? difference / size : difference;
}

// The coefficients (the designer's coefficient_array()) of the field designed
// on `tm` with `constraints` by a Polyvector_field_designer with the solver
// type `Solver` and the concurrency tag `ConcurrencyTag`; with `solver`, that
// solver object is given to the designer (named parameter
// sparse_linear_solver), otherwise the designer makes its own. Every step must
// succeed (else the test fails). `degrees_solved`, when given, receives the
// number of coefficient degrees that were solved.
template <typename Solver, typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename Constraint>
std::vector<std::complex<double> > designed_coefficients(const TriangleMesh& tm, std::size_t N, bool sign_symmetric,
                                                         const std::vector<Constraint>& constraints,
                                                         const Solver* solver = nullptr,
                                                         std::size_t* degrees_solved = nullptr)
{
  namespace PVF = CGAL::Polyvector_fields;
  auto design = [&](const auto& np) {
    PVF::Polyvector_field_designer<TriangleMesh, CGAL::Default, CGAL::Default, Solver, ConcurrencyTag> designer(tm, N, np);
    EXPECT_EQ(designer.status(), PVF::Error_code::SUCCESS);
    EXPECT_EQ(designer.add_constraints(constraints), PVF::Error_code::SUCCESS);
    EXPECT_EQ(designer.solve(boost::dummy_property_map()), PVF::Error_code::SUCCESS);
    if(degrees_solved != nullptr)
      *degrees_solved = designer.statistics().number_of_degrees_solved;
    return designer.coefficient_array();
  };
  if(solver != nullptr)
    return design(PVF::parameters::sign_symmetric(sign_symmetric, CGAL::parameters::sparse_linear_solver(*solver)));
  return design(PVF::parameters::sign_symmetric(sign_symmetric));
}

// OpenBLAS's thread count, looked up at run time as the package does: both
// functions are null when the BLAS is not OpenBLAS (or there is no dlsym).
struct Openblas_threads
{
  typedef int (*Get)();
  typedef void (*Set)(int);
  Get get = nullptr;
  Set set = nullptr;

  Openblas_threads()
  {
#if defined(__unix__) || defined(__APPLE__)
    get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
#endif
  }
  // Sets two threads and gives the count before in `original`; false when
  // OpenBLAS is not there or does not allow two threads.
  bool set_two(int& original) const
  {
    if(get == nullptr || set == nullptr)
      return false;
    original = get();
    set(2);
    if(get() == 2)
      return true;
    set(original);
    return false;
  }
};

} // namespace pvf_test

#endif // CGAL_POLYVECTOR_FIELDS_TEST_SUPPORT_H
