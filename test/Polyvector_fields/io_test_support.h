// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Helpers shared by the IO tests and the fuzz harnesses of the readers:
// bundled data, whole-file reads, scratch folders, and the sentinels (the
// recognisable contents that a failed read must leave as they were).

#ifndef CGAL_POLYVECTOR_FIELDS_IO_TEST_SUPPORT_H
#define CGAL_POLYVECTOR_FIELDS_IO_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Face_constraint.h>
#include <CGAL/Polyvector_fields/Singularity.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/properties.h>

#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef PVF_DATA_DIR
#error "PVF_DATA_DIR (the folder of the bundled meshes) must be given by the build (CMake's pvf_link_package)"
#endif

namespace pvf_io_test {

namespace PVF = CGAL::Polyvector_fields;
namespace fs = std::filesystem;
using PVF::Error_code;

// The two kernels the IO tests read and write with.
typedef CGAL::Simple_cartesian<double> SC;
typedef CGAL::Exact_predicates_inexact_constructions_kernel EPICK;

inline std::string data_file(const std::string& name) { return std::string(PVF_DATA_DIR) + "/" + name; }

template <typename TriangleMesh>
TriangleMesh load_mesh(const std::string& name)
{
  TriangleMesh tm;
  const bool ok = CGAL::IO::read_polygon_mesh(data_file(name), tm);
  if(!ok || num_faces(tm) == 0)
    throw std::runtime_error("cannot read " + name);
  return tm;
}

inline std::string file_content(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class Scratch_directory
{
public:
  explicit Scratch_directory(const std::string& name)
  {
    m_path = std::filesystem::temp_directory_path() / ("pvf_io_test_" + name + "_" + std::to_string(std::random_device()()));
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~Scratch_directory() { std::error_code ec; std::filesystem::remove_all(m_path, ec); }
  std::string file(const std::string& name) const { return (m_path / name).string(); }
  std::set<std::string> entries() const
  {
    std::set<std::string> names;
    for(const auto& entry : std::filesystem::directory_iterator(m_path))
      names.insert(entry.path().filename().string());
    return names;
  }

private:
  std::filesystem::path m_path;
};

// ---------------------------------------------------------------------------
// Sentinels: a reader that fails must leave its outputs as they were, so the
// outputs are filled with these before the read and compared after it. The
// values (a soft weight, non-integer components, a different vector on each
// face, a degree no file gives) are ones that no successful read produces.
// ---------------------------------------------------------------------------

// The degree a reader's `N` is set to before a read.
const std::size_t sentinel_degree = 777;

template <typename TriangleMesh>
struct Sentinel_types
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel::Vector_3 Vector_3;
  typedef CGAL::Polyvector_fields::Face_constraint<face_descriptor, Vector_3> Constraint;
  typedef CGAL::Polyvector_fields::Singularity<vertex_descriptor> Singularity;
};

// Bit for bit, so that -0 and +0 count apart.
template <typename Vector_3>
bool same_bits(const Vector_3& a, const Vector_3& b)
{
  const double x[3] = { double(a.x()), double(a.y()), double(a.z()) };
  const double y[3] = { double(b.x()), double(b.y()), double(b.z()) };
  return std::memcmp(x, y, sizeof x) == 0;
}

// One soft constraint with one vector on the first face.
template <typename TriangleMesh>
std::vector<typename Sentinel_types<TriangleMesh>::Constraint> sentinel_constraints(const TriangleMesh& tm)
{
  typedef typename Sentinel_types<TriangleMesh>::Constraint Constraint;
  typedef typename Sentinel_types<TriangleMesh>::Vector_3 Vector_3;
  return { Constraint{ *faces(tm).begin(), { Vector_3(42, -4.5, 0.125) }, 7.0 } };
}

template <typename TriangleMesh>
bool is_sentinel(const TriangleMesh& tm, const std::vector<typename Sentinel_types<TriangleMesh>::Constraint>& out)
{
  const auto expected = sentinel_constraints(tm);
  return out.size() == 1 && out[0].face == expected[0].face && out[0].vectors.size() == 1 &&
         same_bits(out[0].vectors[0], expected[0].vectors[0]) &&
         std::memcmp(&out[0].weight, &expected[0].weight, sizeof(double)) == 0;
}

// The i-th face (in the order of faces(tm)) gets the one root (i, -1, 99).
template <typename TriangleMesh, typename RootMap>
void fill_sentinel_roots(const TriangleMesh& tm, RootMap roots)
{
  typedef typename Sentinel_types<TriangleMesh>::Vector_3 Vector_3;
  std::size_t i = 0;
  for(auto f : faces(tm))
    put(roots, f, std::vector<Vector_3>{ Vector_3(double(i++), -1, 99) });
}

template <typename TriangleMesh, typename RootMap>
bool has_sentinel_roots(const TriangleMesh& tm, RootMap roots)
{
  typedef typename Sentinel_types<TriangleMesh>::Vector_3 Vector_3;
  std::size_t i = 0;
  for(auto f : faces(tm))
  {
    const std::vector<Vector_3>& u = get(roots, f);
    if(u.size() != 1 || !same_bits(u[0], Vector_3(double(i++), -1, 99)))
      return false;
  }
  return true;
}

// One singularity of index -77/N at the first vertex.
template <typename TriangleMesh>
std::vector<typename Sentinel_types<TriangleMesh>::Singularity> sentinel_singularities(const TriangleMesh& tm)
{
  return { { *vertices(tm).begin(), -77 } };
}

template <typename TriangleMesh>
bool is_sentinel(const TriangleMesh& tm, const std::vector<typename Sentinel_types<TriangleMesh>::Singularity>& out)
{
  return out.size() == 1 && out[0].vertex == *vertices(tm).begin() && out[0].index_numerator == -77;
}

} // namespace pvf_io_test

#endif // CGAL_POLYVECTOR_FIELDS_IO_TEST_SUPPORT_H
