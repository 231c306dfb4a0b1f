// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Tests of IO/vtk.h: the legacy VTK file is parsed back by a small reader
// written here, independent of the writer.

#include <CGAL/Polyvector_fields/IO/vtk.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/properties.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_support.h"

namespace {

using namespace pvf_io_test;
namespace PIO = CGAL::Polyvector_fields::IO;

// ---------------------------------------------------------------------------
// A minimal reader of legacy ASCII VTK unstructured grids with cell data.

struct Vtk_array
{
  std::string kind;    // "VECTORS" or "SCALARS"
  std::string type;    // "double", "int", ...
  std::vector<double> values;
};

struct Vtk_file
{
  std::string title;
  std::vector<double> points;                   // 3 per point
  std::vector<std::vector<std::size_t> > cells;
  std::vector<int> cell_types;
  std::size_t cell_data_count = 0;
  std::vector<std::string> array_names;         // in file order
  std::map<std::string, Vtk_array> arrays;
};

// Returns an empty string on success, else what went wrong.
std::string parse_vtk(const std::string& text, Vtk_file& vtk)
{
  std::istringstream in(text);
  std::string line;
  if(!std::getline(in, line) || line != "# vtk DataFile Version 3.0")
    return "bad version line: " + line;
  if(!std::getline(in, vtk.title) || vtk.title.empty() || vtk.title.size() > 256)
    return "bad title";
  if(!std::getline(in, line) || line != "ASCII")
    return "not ASCII";
  std::string word, type;
  std::size_t n = 0, size = 0;
  if(!(in >> word >> type) || word != "DATASET" || type != "UNSTRUCTURED_GRID")
    return "not an unstructured grid";
  if(!(in >> word >> n >> type) || word != "POINTS" || type != "double")
    return "bad POINTS";
  vtk.points.resize(3 * n);
  for(double& x : vtk.points)
    if(!(in >> x))
      return "short POINTS";
  std::size_t cell_count = 0;
  if(!(in >> word >> cell_count >> size) || word != "CELLS")
    return "bad CELLS";
  std::size_t read_size = 0;
  for(std::size_t i = 0; i < cell_count; ++i)
  {
    std::size_t k = 0;
    if(!(in >> k))
      return "short CELLS";
    std::vector<std::size_t> cell(k);
    for(std::size_t& id : cell)
      if(!(in >> id) || id >= n)
        return "bad point id in CELLS";
    read_size += k + 1;
    vtk.cells.push_back(cell);
  }
  if(read_size != size)
    return "CELLS size mismatch";
  std::size_t type_count = 0;
  if(!(in >> word >> type_count) || word != "CELL_TYPES" || type_count != cell_count)
    return "bad CELL_TYPES";
  vtk.cell_types.resize(type_count);
  for(int& t : vtk.cell_types)
    if(!(in >> t))
      return "short CELL_TYPES";
  if(!(in >> word >> vtk.cell_data_count) || word != "CELL_DATA" || vtk.cell_data_count != cell_count)
    return "bad CELL_DATA";
  while(in >> word)
  {
    Vtk_array array;
    array.kind = word;
    std::string name;
    std::size_t components = 0;
    if(word == "VECTORS")
    {
      if(!(in >> name >> array.type))
        return "bad VECTORS header";
      components = 3;
    }
    else if(word == "SCALARS")
    {
      std::string lookup, table;
      if(!(in >> name >> array.type >> components >> lookup >> table) || components != 1 ||
         lookup != "LOOKUP_TABLE" || table != "default")
        return "bad SCALARS header for " + name;
    }
    else
      return "unknown section " + word;
    if(vtk.arrays.count(name))
      return "array twice: " + name;
    array.values.resize(components * cell_count);
    for(double& x : array.values)
      if(!(in >> x))
        return "short array " + name;
    if(array.type == "int")
      for(double x : array.values)
        if(x != std::floor(x))
          return "non-integer in int array " + name;
    vtk.array_names.push_back(name);
    vtk.arrays[name] = array;
  }
  return "";
}

// ---------------------------------------------------------------------------

template <typename TriangleMesh>
struct Vtk_test : ::testing::Test
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type>::Kernel Kernel;
  typedef typename Kernel::Vector_3 Vector_3;
  typedef PVF::Singularity<vertex_descriptor> Singularity;
};

typedef ::testing::Types<CGAL::Surface_mesh<SC::Point_3>, CGAL::Surface_mesh<EPICK::Point_3>,
                         CGAL::Polyhedron_3<SC>, CGAL::Polyhedron_3<EPICK> >
  Mesh_types;
TYPED_TEST_SUITE(Vtk_test, Mesh_types);

template <typename TriangleMesh>
double min_angle_degrees(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm)
{
  const auto h = halfedge(f, tm);
  const auto vpm = get(CGAL::vertex_point, tm);
  const auto p = { get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)) };
  std::vector<std::array<double, 3> > q;
  for(const auto& x : p)
    q.push_back({ CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()) });
  double smallest = 180;
  for(int i = 0; i < 3; ++i)
  {
    const auto& a = q[i];
    const auto& b = q[(i + 1) % 3];
    const auto& c = q[(i + 2) % 3];
    double dot = 0, lb = 0, lc = 0;
    for(int k = 0; k < 3; ++k)
    {
      dot += (b[k] - a[k]) * (c[k] - a[k]);
      lb += (b[k] - a[k]) * (b[k] - a[k]);
      lc += (c[k] - a[k]) * (c[k] - a[k]);
    }
    smallest = (std::min)(smallest, std::acos(dot / std::sqrt(lb * lc)) * 180 / CGAL_PI);
  }
  return smallest;
}

TYPED_TEST(Vtk_test, ParsesBackOnBumpy)
{
  typedef TypeParam Mesh;
  typedef typename TestFixture::Vector_3 Vector_3;
  typedef typename TestFixture::Singularity Singularity;
  typedef typename TestFixture::vertex_descriptor vertex_descriptor;
  typedef typename TestFixture::face_descriptor face_descriptor;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  const std::vector<vertex_descriptor> vlist(vertices(tm).begin(), vertices(tm).end());
  const std::vector<face_descriptor> flist(faces(tm).begin(), faces(tm).end());
  const std::size_t V = vlist.size(), F = flist.size(), N = 4;
  ASSERT_EQ(V, 1250u);
  ASSERT_EQ(F, 2496u);

  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uniform(-1, 1);
  auto roots = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
  for(face_descriptor f : flist)
  {
    std::vector<Vector_3> u;
    for(std::size_t k = 0; k < N; ++k)
      u.emplace_back(uniform(rng), uniform(rng), uniform(rng));
    put(roots, f, u);
  }
  const std::vector<Singularity> singularities = { { vlist[10], 1 }, { vlist[1249], -1 }, { vlist[500], 2 } };
  PIO::Face_scalar_arrays scalars(2);
  scalars[0].first = "conjugacy_deviation";
  scalars[1].first = "min_angle_degrees";
  for(face_descriptor f : flist)
  {
    scalars[0].second.push_back(std::abs(uniform(rng)) * 1e-4);
    scalars[1].second.push_back(min_angle_degrees(f, tm));
  }
  const std::vector<std::size_t> constrained_ids = { 0, 7, 100, 2495, 1234, 7 };  // 7 twice
  std::vector<face_descriptor> constrained;
  std::vector<bool> flags(F, false);
  for(std::size_t id : constrained_ids)
  {
    constrained.push_back(flist[id]);
    flags[id] = true;
  }

  Scratch_directory dir("vtk");
  const std::string filename = dir.file("bumpy.vtk");
  ASSERT_EQ(PIO::write_VTK(filename, tm, roots, N, singularities, PVF::parameters::face_scalars(scalars, PVF::parameters::constrained_faces(constrained))), Error_code::SUCCESS);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "bumpy.vtk" });
  const std::string text = file_content(filename);

  Vtk_file vtk;
  ASSERT_EQ(parse_vtk(text, vtk), "");
  const std::size_t S = 3, cells = F + S;

  // Points.
  ASSERT_EQ(vtk.points.size(), 3 * V);
  const auto vpm = get(CGAL::vertex_point, tm);
  for(std::size_t i = 0; i < V; ++i)
  {
    const auto& p = get(vpm, vlist[i]);
    ASSERT_EQ(vtk.points[3 * i], CGAL::to_double(p.x()));
    ASSERT_EQ(vtk.points[3 * i + 1], CGAL::to_double(p.y()));
    ASSERT_EQ(vtk.points[3 * i + 2], CGAL::to_double(p.z()));
  }

  // Cells: F triangles (type 5) with the mesh's vertex ids, then S vertex cells (type 1).
  ASSERT_EQ(vtk.cells.size(), cells);
  ASSERT_EQ(std::count(vtk.cell_types.begin(), vtk.cell_types.end(), 5), std::ptrdiff_t(F));
  ASSERT_EQ(std::count(vtk.cell_types.begin(), vtk.cell_types.end(), 1), std::ptrdiff_t(S));
  std::map<vertex_descriptor, std::size_t> vertex_id;
  for(std::size_t i = 0; i < V; ++i)
    vertex_id[vlist[i]] = i;
  for(std::size_t i = 0; i < F; ++i)
  {
    ASSERT_EQ(vtk.cell_types[i], 5);
    const auto h = halfedge(flist[i], tm);
    const std::vector<std::size_t> expected = { vertex_id[source(h, tm)], vertex_id[target(h, tm)],
                                                vertex_id[target(next(h, tm), tm)] };
    ASSERT_EQ(vtk.cells[i], expected);
  }
  for(std::size_t s = 0; s < S; ++s)
  {
    EXPECT_EQ(vtk.cell_types[F + s], 1);
    EXPECT_EQ(vtk.cells[F + s], std::vector<std::size_t>{ vertex_id[singularities[s].vertex] });
  }

  // Arrays, in order, each with one value (or 3) per cell.
  const std::vector<std::string> names = { "root_0", "root_1", "root_2", "root_3", "singularity_index",
                                           "is_constrained", "conjugacy_deviation", "min_angle_degrees" };
  ASSERT_EQ(vtk.array_names, names);
  for(std::size_t k = 0; k < N; ++k)
  {
    const Vtk_array& a = vtk.arrays["root_" + std::to_string(k)];
    EXPECT_EQ(a.kind, "VECTORS");
    EXPECT_EQ(a.type, "double");
    ASSERT_EQ(a.values.size(), 3 * cells);
    for(std::size_t i = 0; i < F; ++i)
    {
      const Vector_3& u = get(roots, flist[i])[k];
      ASSERT_EQ(a.values[3 * i], CGAL::to_double(u.x()));
      ASSERT_EQ(a.values[3 * i + 1], CGAL::to_double(u.y()));
      ASSERT_EQ(a.values[3 * i + 2], CGAL::to_double(u.z()));
    }
    for(std::size_t j = 3 * F; j < 3 * cells; ++j)
      EXPECT_EQ(a.values[j], 0.0);
  }
  const Vtk_array& index = vtk.arrays["singularity_index"];
  EXPECT_EQ(index.kind, "SCALARS");
  EXPECT_EQ(index.type, "double");
  ASSERT_EQ(index.values.size(), cells);
  EXPECT_EQ(std::count(index.values.begin(), index.values.begin() + F, 0.0), std::ptrdiff_t(F));
  EXPECT_EQ(index.values[F], 0.25);
  EXPECT_EQ(index.values[F + 1], -0.25);
  EXPECT_EQ(index.values[F + 2], 0.5);

  const Vtk_array& is_constrained = vtk.arrays["is_constrained"];
  EXPECT_EQ(is_constrained.type, "int");
  ASSERT_EQ(is_constrained.values.size(), cells);
  EXPECT_EQ(std::count(is_constrained.values.begin(), is_constrained.values.end(), 1.0), 5);
  for(std::size_t i = 0; i < cells; ++i)
    EXPECT_EQ(is_constrained.values[i], (i < F && flags[i]) ? 1.0 : 0.0);

  for(const auto& s : scalars)
  {
    const Vtk_array& a = vtk.arrays[s.first];
    EXPECT_EQ(a.type, "double");
    ASSERT_EQ(a.values.size(), cells);
    EXPECT_TRUE(std::equal(s.second.begin(), s.second.end(), a.values.begin())) << s.first;
    EXPECT_EQ(std::count(a.values.begin() + F, a.values.end(), 0.0), std::ptrdiff_t(S));
  }
  // The angles are those of the mesh: positive, below 60 degrees, and the
  // bumpy sphere has no sliver.
  const auto& angles = vtk.arrays["min_angle_degrees"].values;
  EXPECT_GT(*std::min_element(angles.begin(), angles.begin() + F), 1.0);
  EXPECT_LE(*std::max_element(angles.begin(), angles.begin() + F), 60.0 + 1e-9);

  // The flag overload and the stream overload write the same text.
  std::ostringstream os;
  ASSERT_EQ(PIO::write_VTK(os, tm, roots, N, singularities, PVF::parameters::face_scalars(scalars, PVF::parameters::is_constrained(flags))), Error_code::SUCCESS);
  EXPECT_EQ(os.str(), text);

  // Without constraints, without extra arrays.
  std::ostringstream no_constraints, bare;
  ASSERT_EQ(PIO::write_VTK(no_constraints, tm, roots, N, singularities, PVF::parameters::face_scalars(scalars)), Error_code::SUCCESS);
  ASSERT_EQ(PIO::write_VTK(bare, tm, roots, N, std::vector<Singularity>()), Error_code::SUCCESS);
  Vtk_file a, b;
  ASSERT_EQ(parse_vtk(no_constraints.str(), a), "");
  ASSERT_EQ(parse_vtk(bare.str(), b), "");
  EXPECT_EQ(a.array_names, (std::vector<std::string>{ "root_0", "root_1", "root_2", "root_3", "singularity_index",
                                                      "conjugacy_deviation", "min_angle_degrees" }));
  EXPECT_EQ(a.cells.size(), cells);
  EXPECT_EQ(b.array_names,
            (std::vector<std::string>{ "root_0", "root_1", "root_2", "root_3", "singularity_index" }));
  EXPECT_EQ(b.cells.size(), F);
  EXPECT_EQ(b.arrays["singularity_index"].values, std::vector<double>(F, 0.0));
}

TEST(Vtk, VertexPointMapNamedParameter)
{
  typedef CGAL::Surface_mesh<SC::Point_3> Mesh;
  Mesh tm;
  CGAL::make_tetrahedron(SC::Point_3(0, 0, 0), SC::Point_3(1, 0, 0), SC::Point_3(0, 1, 0), SC::Point_3(0, 0, 1), tm);
  auto roots = get(CGAL::dynamic_face_property_t<std::vector<SC::Vector_3> >(), tm);
  for(auto f : faces(tm))
    put(roots, f, std::vector<SC::Vector_3>{ SC::Vector_3(1, 0, 0) });
  auto moved = get(CGAL::dynamic_vertex_property_t<SC::Point_3>(), tm);
  for(auto v : vertices(tm))
    put(moved, v, tm.point(v) + SC::Vector_3(10, 20, 30));

  std::ostringstream os;
  ASSERT_EQ(PIO::write_VTK(os, tm, roots, 1, std::vector<PVF::Singularity<Mesh::Vertex_index> >(),
                           CGAL::parameters::vertex_point_map(moved)),
            Error_code::SUCCESS);
  Vtk_file vtk;
  ASSERT_EQ(parse_vtk(os.str(), vtk), "");
  ASSERT_EQ(vtk.points.size(), 12u);
  std::size_t i = 0;
  for(auto v : vertices(tm))
  {
    EXPECT_EQ(vtk.points[3 * i], tm.point(v).x() + 10);
    EXPECT_EQ(vtk.points[3 * i + 1], tm.point(v).y() + 20);
    EXPECT_EQ(vtk.points[3 * i + 2], tm.point(v).z() + 30);
    ++i;
  }
  EXPECT_EQ(vtk.cells.size(), 4u);
}

TEST(Vtk, BadInputWritesNothing)
{
  typedef CGAL::Polyhedron_3<EPICK> Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef PVF::Singularity<vertex_descriptor> Singularity;
  typedef EPICK::Vector_3 Vector_3;
  const Mesh tm = load_mesh<Mesh>("bumpy.off");
  const Mesh other = load_mesh<Mesh>("bumpy.off");
  const std::vector<vertex_descriptor> vlist(vertices(tm).begin(), vertices(tm).end());
  const std::vector<face_descriptor> flist(faces(tm).begin(), faces(tm).end());
  const std::size_t F = flist.size();
  auto roots = get(CGAL::dynamic_face_property_t<std::vector<Vector_3> >(), tm);
  for(auto f : flist)
    put(roots, f, std::vector<Vector_3>{ Vector_3(1, 0, 0), Vector_3(-1, 0, 0) });
  const std::vector<Singularity> sings = { { vlist[3], 1 } };
  const std::vector<face_descriptor> constrained = { flist[1] };
  const PIO::Face_scalar_arrays good = { { "quality", std::vector<double>(F, 1.0) } };

  Scratch_directory dir("vtk_bad");
  const std::string existing = dir.file("old.vtk");
  std::ofstream(existing) << "old\n";

  auto expect_failure = [&](Error_code expected, std::size_t N, const std::vector<Singularity>& s,
                            const PIO::Face_scalar_arrays& scalars, const std::vector<face_descriptor>& c) {
    std::ostringstream os;
    EXPECT_EQ(PIO::write_VTK(os, tm, roots, N, s, PVF::parameters::face_scalars(scalars, PVF::parameters::constrained_faces(c))), expected);
    EXPECT_TRUE(os.str().empty());
    EXPECT_EQ(PIO::write_VTK(existing, tm, roots, N, s, PVF::parameters::face_scalars(scalars, PVF::parameters::constrained_faces(c))), expected);
    EXPECT_EQ(PIO::write_VTK(dir.file("new.vtk"), tm, roots, N, s, PVF::parameters::face_scalars(scalars, PVF::parameters::constrained_faces(c))), expected);
    EXPECT_EQ(file_content(existing), "old\n");
    EXPECT_EQ(dir.entries(), std::set<std::string>{ "old.vtk" });
  };
  {
    std::ostringstream os;
    ASSERT_EQ(PIO::write_VTK(os, tm, roots, 2, sings, PVF::parameters::face_scalars(good, PVF::parameters::constrained_faces(constrained))), Error_code::SUCCESS);
  }
  expect_failure(Error_code::INVALID_DEGREE, 0, sings, good, constrained);
  expect_failure(Error_code::INCONSISTENT_DEGREE, 3, sings, good, constrained);
  for(const std::string& name : { std::string(), std::string("has space"), std::string("tab\tname"),
                                  std::string("percent%20"), std::string("caf\xc3\xa9"), std::string(201, 'a'),
                                  std::string("root_1"), std::string("singularity_index"),
                                  std::string("is_constrained") })
    expect_failure(Error_code::INVALID_PARAMETER, 2, sings, { { name, std::vector<double>(F, 1.0) } }, constrained);
  expect_failure(Error_code::INVALID_PARAMETER, 2, sings,
                 { { "a", std::vector<double>(F, 1.0) }, { "a", std::vector<double>(F, 2.0) } }, constrained);
  expect_failure(Error_code::INVALID_PARAMETER, 2, sings, { { "short", std::vector<double>(F - 1, 1.0) } },
                 constrained);
  std::vector<double> with_nan(F, 1.0);
  with_nan[F - 1] = std::numeric_limits<double>::quiet_NaN();
  expect_failure(Error_code::NON_FINITE_VALUE, 2, sings, { { "x", with_nan } }, constrained);
  expect_failure(Error_code::INVALID_FACE, 2, sings, good, { flist[0], *CGAL::faces(other).begin() });
  expect_failure(Error_code::INVALID_FACE, 2, sings, good, { face_descriptor() });
  expect_failure(Error_code::INVALID_PARAMETER, 2, { { vlist[3], 0 } }, good, constrained);
  expect_failure(Error_code::INVALID_PARAMETER, 2, { { vlist[3], 1 }, { vlist[3], 1 } }, good, constrained);
  expect_failure(Error_code::INVALID_PARAMETER, 2, { { *CGAL::vertices(other).begin(), 1 } }, good, constrained);

  put(roots, flist[F - 1], std::vector<Vector_3>{ Vector_3(1, 0, 0), Vector_3(0, std::numeric_limits<double>::infinity(), 0) });
  expect_failure(Error_code::NON_FINITE_VALUE, 2, sings, good, constrained);
  put(roots, flist[F - 1], std::vector<Vector_3>{ Vector_3(1, 0, 0) });
  expect_failure(Error_code::INCONSISTENT_DEGREE, 2, sings, good, constrained);
  put(roots, flist[F - 1], std::vector<Vector_3>{ Vector_3(1, 0, 0), Vector_3(-1, 0, 0) });

  // A flag vector of the wrong size.
  std::ostringstream os;
  const std::vector<bool> wrong_size(F + 1, false);
  EXPECT_EQ(PIO::write_VTK(os, tm, roots, 2, sings, PVF::parameters::face_scalars(good, PVF::parameters::is_constrained(wrong_size))),
            Error_code::INVALID_PARAMETER);
  EXPECT_TRUE(os.str().empty());
  // No directory, unwritable stream.
  EXPECT_EQ(PIO::write_VTK(dir.file("missing/x.vtk"), tm, roots, 2, sings), Error_code::CANNOT_OPEN_FILE);
  std::ostringstream broken;
  broken.setstate(std::ios::failbit);
  EXPECT_EQ(PIO::write_VTK(broken, tm, roots, 2, sings), Error_code::CANNOT_OPEN_FILE);
  EXPECT_EQ(dir.entries(), std::set<std::string>{ "old.vtk" });
}

TEST(Vtk, NonTriangleAndEmptyMeshes)
{
  typedef CGAL::Surface_mesh<SC::Point_3> Mesh;
  typedef PVF::Singularity<Mesh::Vertex_index> Singularity;
  Mesh quad;
  CGAL::make_quad(SC::Point_3(0, 0, 0), SC::Point_3(1, 0, 0), SC::Point_3(1, 1, 0), SC::Point_3(0, 1, 0), quad);
  auto roots = get(CGAL::dynamic_face_property_t<std::vector<SC::Vector_3> >(), quad);
  for(auto f : faces(quad))
    put(roots, f, std::vector<SC::Vector_3>{ SC::Vector_3(1, 0, 0) });
  std::ostringstream os;
  EXPECT_EQ(PIO::write_VTK(os, quad, roots, 1, std::vector<Singularity>()), Error_code::NON_TRIANGLE_FACE);
  EXPECT_TRUE(os.str().empty());

  Mesh empty;
  auto empty_roots = get(CGAL::dynamic_face_property_t<std::vector<SC::Vector_3> >(), empty);
  EXPECT_EQ(PIO::write_VTK(os, empty, empty_roots, 1, std::vector<Singularity>()), Error_code::EMPTY_MESH);
  EXPECT_TRUE(os.str().empty());
}

} // namespace
