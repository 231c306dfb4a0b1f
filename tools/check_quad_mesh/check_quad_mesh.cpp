// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// check_quad_mesh: an independent check of a quad mesh against the surface it
// was made from.
//
//   check_quad_mesh INPUT QUADS [--sharp-edges DEGREES] [--distance-tolerance T]
//                   [--distance-tolerance-edge F] [--min-area-ratio R]
//                   [--max-hausdorff H] [--max-planarity P]
//
// It uses CGAL only (Surface_mesh, Polygon_mesh_processing, AABB_tree, IO),
// never the package's headers, so that it checks the pipeline with code that
// did not make the output. Each check prints one line
//   name: value (ok | FAIL ... | report)
// and the last line is "summary key=value ...", for scripts/run_corpus.py.
// Exit status: 0 when every check passes, 1 when one fails, 2 when a file
// cannot be read or the command line is wrong.
//
// The reference surface is INPUT read as a polygon soup, repaired (duplicate
// points merged, degenerate and duplicate polygons removed), oriented, made a
// Surface_mesh and triangulated by PMP::triangulate_faces (a fan where that
// fails). A non-planar quad of the input has two triangulations that other
// tools may choose from, so distances are taken to both (its four triangles),
// and a quad over it is folded against its mean (Newell) normal, which neither
// diagonal changes.
//
// QUADS is read as a soup too, and its topology (edges, components, Euler
// characteristic, valences) is computed from the soup itself, so that a
// broken output is described rather than refused.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef K::Triangle_3 Triangle;
typedef K::Segment_3 Segment;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
typedef std::vector<std::size_t> Polygon;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef std::vector<Triangle>::const_iterator Triangle_iterator;
typedef CGAL::AABB_triangle_primitive<K, Triangle_iterator> Triangle_primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Triangle_primitive>> Triangle_tree;
typedef std::vector<Segment>::const_iterator Segment_iterator;
typedef CGAL::AABB_segment_primitive<K, Segment_iterator> Segment_primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Segment_primitive>> Segment_tree;

const char* const usage_text =
    "usage: check_quad_mesh INPUT QUADS [--sharp-edges DEGREES] [--distance-tolerance T]\n"
    "                       [--distance-tolerance-edge F] [--min-area-ratio R] [--max-hausdorff H]\n"
    "                       [--max-planarity P]\n"
    "       check_quad_mesh INPUT --input-only\n"
    "  INPUT, QUADS              meshes (.off, .obj, .ply, .stl); QUADS is checked against INPUT\n"
    "  --sharp-edges DEGREES     also measure how well the quad edges follow the interior input\n"
    "                            edges whose dihedral angle exceeds DEGREES (reported, not a check;\n"
    "                            the boundary edges are always measured)\n"
    "  --distance-tolerance T    a quad vertex may lie T bbox diagonals off the input (default 1e-6)\n"
    "  --distance-tolerance-edge F  instead, F mean quad edge lengths (e.g. 0.05 for planarized meshes)\n"
    "  --min-area-ratio R        fail when quad area / input area < R (default 0: reported only)\n"
    "  --max-hausdorff H         fail when an input vertex or face centroid lies farther than H bbox\n"
    "                            diagonals from the quads (default 0.01)\n"
    "  --max-planarity P         fail when a quad's diagonals are farther apart than P times their\n"
    "                            mean length (default: the planarity is reported only)\n"
    "  --input-only              only read INPUT as the checks do: exit 0 when it makes a surface\n"
    "exit status: 0 valid, 1 invalid, 2 unreadable input or bad command line\n";

struct Options {
  std::string input;
  std::string quads;
  double sharp_degrees = -1;            // < 0: no sharp-edge measure
  double distance_tolerance = 1e-6;     // in bbox diagonals
  double distance_tolerance_edge = -1;  // in mean quad edge lengths; < 0: unused
  double min_area_ratio = 0;
  double max_hausdorff = 0.01;
  double max_planarity = -1;            // < 0: the planarity is reported, not checked
  bool input_only = false;
};

[[noreturn]] void usage_error(const std::string& message)
{
  std::cerr << "check_quad_mesh: " << message << "\n" << usage_text;
  std::exit(2);
}

double parse_number(const std::string& flag, const char* text, double low, double high)
{
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if(end == text || *end != '\0' || !std::isfinite(value) || value < low || value > high) {
    std::ostringstream s;
    s << flag << " expects a number in [" << low << ", " << high << "], not '" << text << "'";
    usage_error(s.str());
  }
  return value;
}

Options parse_options(int argc, char** argv)
{
  Options options;
  std::vector<std::string> positional;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--help" || arg == "-h") {
      std::cout << usage_text;
      std::exit(0);
    }
    if(arg == "--input-only") {
      options.input_only = true;
      continue;
    }
    if(arg.rfind("--", 0) == 0) {
      if(i + 1 >= argc)
        usage_error(arg + " expects a value");
      const char* value = argv[++i];
      if(arg == "--sharp-edges")
        options.sharp_degrees = parse_number(arg, value, 0, 180);
      else if(arg == "--distance-tolerance")
        options.distance_tolerance = parse_number(arg, value, 0, 1);
      else if(arg == "--distance-tolerance-edge")
        options.distance_tolerance_edge = parse_number(arg, value, 0, 100);
      else if(arg == "--min-area-ratio")
        options.min_area_ratio = parse_number(arg, value, 0, 100);
      else if(arg == "--max-hausdorff")
        options.max_hausdorff = parse_number(arg, value, 0, 100);
      else if(arg == "--max-planarity")
        options.max_planarity = parse_number(arg, value, 0, 100);
      else
        usage_error("unknown option " + arg);
    } else {
      positional.push_back(arg);
    }
  }
  if(options.input_only) {
    if(positional.size() != 1)
      usage_error("--input-only expects one mesh, INPUT");
    options.input = positional[0];
    return options;
  }
  if(positional.size() != 2)
    usage_error("expects two meshes, INPUT and QUADS");
  options.input = positional[0];
  options.quads = positional[1];
  return options;
}

[[noreturn]] void unreadable(const std::string& message)
{
  std::cerr << "check_quad_mesh: " << message << std::endl;
  std::exit(2);
}

// Reads a polygon soup; exits with status 2 when the file cannot be read.
void read_soup(const std::string& path, const char* role,
               std::vector<Point>& points, std::vector<Polygon>& polygons)
{
  std::ifstream probe(path);
  if(!probe)
    unreadable(std::string(role) + " '" + path + "' cannot be opened");
  probe.close();
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    unreadable(std::string(role) + " '" + path + "' is not a readable mesh (.off, .obj, .ply, .stl)");
  for(const Polygon& polygon : polygons)
    for(std::size_t v : polygon)
      if(v >= points.size())
        unreadable(std::string(role) + " '" + path + "' has a face with a vertex index out of range");
}

bool is_finite(const Point& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

std::string format(double value)
{
  std::ostringstream s;
  s.precision(6);
  s << value;
  return s.str();
}

// A union-find over 0..n-1.
struct Union_find {
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t i)
  {
    while(parent[i] != i) {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

// ---------------------------------------------------------------------------
// The reference surface
// ---------------------------------------------------------------------------
struct Input_component {
  std::size_t faces = 0, edges = 0, vertices = 0, border_edges = 0;
  double area = 0;
  bool closed() const { return border_edges == 0; }
  long euler() const { return long(vertices) - long(edges) + long(faces); }
};

struct Reference {
  Mesh mesh;                              // triangulated
  std::vector<Triangle> triangles;        // the mesh's triangles, then both splits of each input quad
  // per triangle, the unit normal of the fold test: for the triangles of an
  // input quad, the quad's mean (Newell) normal, so that a quad over a
  // non-planar input quad is not folded or unfolded by the choice of one of
  // its diagonals; for the others, their own
  std::vector<Vector> normals;
  std::vector<std::size_t> component;     // input component of each triangle
  std::vector<Input_component> components;
  Triangle_tree tree;
  double diagonal = 0;
  double area = 0;
  std::size_t polygons_triangulated = 0;
  std::size_t fan_fallbacks = 0;
};

Vector unit_or_zero(const Vector& v)
{
  const double length = std::sqrt(v.squared_length());
  return length > 0 && std::isfinite(length) ? v / length : Vector(0, 0, 0);
}

// Twice the vector area of a polygon (Newell's formula, from its first corner,
// which keeps the digits of a polygon far from the origin): its normal, for a
// planar polygon the normal of its plane.
Vector newell_normal(const std::vector<Point>& corners)
{
  Vector n(0, 0, 0);
  for(std::size_t i = 1; i + 1 < corners.size(); ++i)
    n = n + CGAL::cross_product(corners[i] - corners[0], corners[i + 1] - corners[0]);
  return n;
}

// A visitor of PMP::triangulate_faces(): the triangles of a polygon keep its normal.
struct Polygon_normal_keeper {
  Mesh::Property_map<face_descriptor, Vector>* normal;
  Vector current{0, 0, 0};
  void before_subface_creations(face_descriptor f) { current = (*normal)[f]; }
  void after_subface_created(face_descriptor f) { (*normal)[f] = current; }
  void after_subface_creations() {}
};

// Splits every face of more than three sides that PMP could not triangulate
// into a fan; its triangles keep its `normal`.
void fan_remaining_polygons(Mesh& mesh, Mesh::Property_map<face_descriptor, Vector>& normal, std::size_t& fans)
{
  std::vector<face_descriptor> polygons;
  for(face_descriptor f : faces(mesh))
    if(CGAL::halfedges_around_face(halfedge(f, mesh), mesh).size() > 3)
      polygons.push_back(f);
  for(face_descriptor f : polygons) {
    ++fans;
    // split_face(h, next(next(h))) cuts the triangle of next(h) and
    // next(next(h)) off the face; h keeps the rest.
    const halfedge_descriptor h = halfedge(f, mesh);
    while(CGAL::halfedges_around_face(h, mesh).size() > 3) {
      const halfedge_descriptor cut = CGAL::Euler::split_face(h, next(next(h, mesh), mesh), mesh);
      normal[face(opposite(cut, mesh), mesh)] = normal[f];
      normal[face(cut, mesh)] = normal[f];
    }
  }
}

void build_reference(const std::string& path, Reference& ref)
{
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  read_soup(path, "INPUT", points, polygons);
  for(const Point& p : points)
    if(!is_finite(p))
      unreadable("INPUT '" + path + "' has a vertex with a coordinate that is not a finite number");
  PMP::repair_polygon_soup(points, polygons);
  if(polygons.empty())
    unreadable("INPUT '" + path + "' has no face (after removing degenerate and duplicate faces)");
  PMP::orient_polygon_soup(points, polygons);
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    unreadable("INPUT '" + path + "' cannot be made a polygon mesh: it is not a surface");
  PMP::polygon_soup_to_polygon_mesh(points, polygons, ref.mesh);

  // The mean (Newell) normal of each input quad, kept by the triangles it is
  // split into: the normal of the fold test (see Reference::normals). Zero for
  // the other faces, whose triangles use their own normals.
  auto newell = ref.mesh.add_property_map<face_descriptor, Vector>("f:check_newell", Vector(0, 0, 0)).first;
  for(face_descriptor f : faces(ref.mesh)) {
    const std::size_t sides = CGAL::halfedges_around_face(halfedge(f, ref.mesh), ref.mesh).size();
    if(sides > 3)
      ++ref.polygons_triangulated;
    if(sides != 4)
      continue;
    std::vector<Point> corners;
    for(auto v : CGAL::vertices_around_face(halfedge(f, ref.mesh), ref.mesh))
      corners.push_back(ref.mesh.point(v));
    newell[f] = newell_normal(corners);
  }
  if(!PMP::triangulate_faces(ref.mesh, CGAL::parameters::visitor(Polygon_normal_keeper{&newell})))
    fan_remaining_polygons(ref.mesh, newell, ref.fan_fallbacks);

  // Components and their topology.
  auto fcc = ref.mesh.add_property_map<face_descriptor, std::size_t>("f:check_component", 0).first;
  const std::size_t count = PMP::connected_components(ref.mesh, fcc);
  ref.components.assign(count, Input_component());
  for(face_descriptor f : faces(ref.mesh))
    ++ref.components[fcc[f]].faces;
  for(edge_descriptor e : edges(ref.mesh)) {
    halfedge_descriptor h = halfedge(e, ref.mesh);
    if(is_border(h, ref.mesh))
      h = opposite(h, ref.mesh);
    Input_component& c = ref.components[fcc[face(h, ref.mesh)]];
    ++c.edges;
    if(is_border_edge(h, ref.mesh))
      ++c.border_edges;
  }
  for(auto v : vertices(ref.mesh)) {
    const halfedge_descriptor h = halfedge(v, ref.mesh);
    if(h == halfedge_descriptor())
      continue;  // isolated
    for(halfedge_descriptor g : CGAL::halfedges_around_target(h, ref.mesh))
      if(!is_border(g, ref.mesh)) {
        ++ref.components[fcc[face(g, ref.mesh)]].vertices;
        break;
      }
  }

  // Triangles, normals, area, bounding box.
  CGAL::Bbox_3 box;
  for(auto v : vertices(ref.mesh))
    box += ref.mesh.point(v).bbox();
  ref.diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                           CGAL::square(box.zmax() - box.zmin()));
  std::vector<Vector> face_normal_of_vertex_ring(num_vertices(ref.mesh), Vector(0, 0, 0));
  for(face_descriptor f : faces(ref.mesh)) {
    const halfedge_descriptor h = halfedge(f, ref.mesh);
    const Point& a = ref.mesh.point(source(h, ref.mesh));
    const Point& b = ref.mesh.point(target(h, ref.mesh));
    const Point& c = ref.mesh.point(target(next(h, ref.mesh), ref.mesh));
    const Vector n = CGAL::cross_product(b - a, c - a);
    for(auto v : CGAL::vertices_around_face(h, ref.mesh))
      face_normal_of_vertex_ring[std::size_t(v)] = face_normal_of_vertex_ring[std::size_t(v)] + n;
  }
  for(face_descriptor f : faces(ref.mesh)) {
    const halfedge_descriptor h = halfedge(f, ref.mesh);
    const auto va = source(h, ref.mesh), vb = target(h, ref.mesh), vc = target(next(h, ref.mesh), ref.mesh);
    const Triangle t(ref.mesh.point(va), ref.mesh.point(vb), ref.mesh.point(vc));
    Vector n = unit_or_zero(newell[f]);
    if(n == Vector(0, 0, 0))  // not from an input quad: its own normal
      n = unit_or_zero(CGAL::cross_product(t[1] - t[0], t[2] - t[0]));
    if(n == Vector(0, 0, 0))  // a degenerate triangle: the normal of the faces around it
      n = unit_or_zero(face_normal_of_vertex_ring[std::size_t(va)] + face_normal_of_vertex_ring[std::size_t(vb)] +
                       face_normal_of_vertex_ring[std::size_t(vc)]);
    const double area = std::sqrt(t.squared_area());
    ref.triangles.push_back(t);
    ref.normals.push_back(n);
    ref.component.push_back(fcc[f]);
    ref.components[fcc[f]].area += area;
    ref.area += area;
  }

  // Both splits of every input quad, in the component of the mesh triangle
  // nearest to their centroid.
  std::vector<Triangle> extra;
  std::vector<Vector> extra_normals;  // per input quad
  for(const Polygon& polygon : polygons) {
    if(polygon.size() != 4)
      continue;
    const Point& p0 = points[polygon[0]];
    const Point& p1 = points[polygon[1]];
    const Point& p2 = points[polygon[2]];
    const Point& p3 = points[polygon[3]];
    extra_normals.push_back(unit_or_zero(newell_normal({ p0, p1, p2, p3 })));
    extra.emplace_back(p0, p1, p2);
    extra.emplace_back(p0, p2, p3);
    extra.emplace_back(p1, p2, p3);
    extra.emplace_back(p1, p3, p0);
  }
  if(!extra.empty()) {
    {
      Triangle_tree mesh_tree(ref.triangles.cbegin(), ref.triangles.cend());
      mesh_tree.accelerate_distance_queries();
      for(const Triangle& t : extra) {
        const Point centroid = CGAL::centroid(t[0], t[1], t[2]);
        const std::size_t nearest = std::size_t(mesh_tree.closest_point_and_primitive(centroid).second -
                                                ref.triangles.cbegin());
        const Vector& n = extra_normals[std::size_t(&t - extra.data()) / 4];
        ref.normals.push_back(n == Vector(0, 0, 0) ? ref.normals[nearest] : n);
        ref.component.push_back(ref.component[nearest]);
      }
    }
    ref.triangles.insert(ref.triangles.end(), extra.begin(), extra.end());
  }
  ref.tree.insert(ref.triangles.cbegin(), ref.triangles.cend());
  ref.tree.accelerate_distance_queries();
}

// ---------------------------------------------------------------------------
// The quad mesh, as a soup
// ---------------------------------------------------------------------------
struct Soup_edge {
  std::size_t a, b;                     // a < b
  std::vector<std::size_t> polygons;    // incident polygons
  std::size_t forward = 0, backward = 0;  // traversals a->b and b->a
};

struct Quad_topology {
  std::vector<Soup_edge> edges;
  std::vector<std::vector<std::size_t>> vertex_edges;  // edges of each vertex
  std::vector<std::vector<std::size_t>> vertex_polygons;
  std::size_t non_manifold_edges = 0, inconsistent_edges = 0, repeated_vertex_polygons = 0;
  std::size_t non_manifold_vertices = 0, unreferenced_points = 0;
  std::vector<std::size_t> component;  // of each polygon (faces joined across edges)
  std::size_t component_count = 0;
};

Quad_topology quad_topology(std::size_t point_count, const std::vector<Polygon>& polygons)
{
  Quad_topology topo;
  struct Corner_edge { std::size_t a, b, polygon; bool forward; };
  std::vector<Corner_edge> all;
  for(std::size_t p = 0; p < polygons.size(); ++p) {
    const Polygon& polygon = polygons[p];
    std::set<std::size_t> distinct(polygon.begin(), polygon.end());
    if(distinct.size() != polygon.size())
      ++topo.repeated_vertex_polygons;
    for(std::size_t i = 0; i < polygon.size(); ++i) {
      const std::size_t u = polygon[i], w = polygon[(i + 1) % polygon.size()];
      if(u == w)
        continue;
      all.push_back({std::min(u, w), std::max(u, w), p, u < w});
    }
  }
  std::sort(all.begin(), all.end(), [](const Corner_edge& x, const Corner_edge& y) {
    return std::tie(x.a, x.b, x.polygon) < std::tie(y.a, y.b, y.polygon);
  });
  topo.vertex_edges.assign(point_count, {});
  topo.vertex_polygons.assign(point_count, {});
  for(std::size_t i = 0; i < all.size();) {
    Soup_edge e;
    e.a = all[i].a;
    e.b = all[i].b;
    std::size_t j = i;
    for(; j < all.size() && all[j].a == e.a && all[j].b == e.b; ++j) {
      e.polygons.push_back(all[j].polygon);
      (all[j].forward ? e.forward : e.backward) += 1;
    }
    i = j;
    if(e.polygons.size() > 2)
      ++topo.non_manifold_edges;
    else if(e.forward > 1 || e.backward > 1)
      ++topo.inconsistent_edges;
    topo.vertex_edges[e.a].push_back(topo.edges.size());
    topo.vertex_edges[e.b].push_back(topo.edges.size());
    topo.edges.push_back(std::move(e));
  }
  for(std::size_t p = 0; p < polygons.size(); ++p) {
    std::set<std::size_t> distinct(polygons[p].begin(), polygons[p].end());
    for(std::size_t v : distinct)
      topo.vertex_polygons[v].push_back(p);
  }

  // Components: polygons joined across shared edges.
  Union_find faces_uf(polygons.size());
  for(const Soup_edge& e : topo.edges)
    for(std::size_t k = 1; k < e.polygons.size(); ++k)
      faces_uf.join(e.polygons[0], e.polygons[k]);
  std::map<std::size_t, std::size_t> root_index;
  topo.component.resize(polygons.size());
  for(std::size_t p = 0; p < polygons.size(); ++p) {
    const auto inserted = root_index.emplace(faces_uf.find(p), root_index.size());
    topo.component[p] = inserted.first->second;
  }
  topo.component_count = root_index.size();

  // Non-manifold vertices: the polygons around a vertex form more than one
  // fan (polygons joined across the edges of that vertex).
  for(std::size_t v = 0; v < point_count; ++v) {
    const std::vector<std::size_t>& around = topo.vertex_polygons[v];
    if(around.empty()) {
      ++topo.unreferenced_points;
      continue;
    }
    std::map<std::size_t, std::size_t> local;
    for(std::size_t p : around)
      local.emplace(p, local.size());
    Union_find fan(around.size());
    for(std::size_t ei : topo.vertex_edges[v]) {
      const Soup_edge& e = topo.edges[ei];
      for(std::size_t k = 1; k < e.polygons.size(); ++k)
        fan.join(local[e.polygons[0]], local[e.polygons[k]]);
    }
    std::set<std::size_t> roots;
    for(std::size_t k = 0; k < around.size(); ++k)
      roots.insert(fan.find(k));
    if(roots.size() > 1)
      ++topo.non_manifold_vertices;
  }
  return topo;
}

double angle_between(const Vector& u, const Vector& v)
{
  const double lu = std::sqrt(u.squared_length()), lv = std::sqrt(v.squared_length());
  if(!(lu > 0) || !(lv > 0))
    return 0;
  return std::acos(std::clamp((u * v) / (lu * lv), -1.0, 1.0));
}

struct Report {
  std::vector<std::string> failed;
  std::vector<std::pair<std::string, std::string>> summary;
  void line(const std::string& name, const std::string& value, bool ok, const std::string& why = "")
  {
    std::cout << name << ": " << value << " (" << (ok ? "ok" : "FAIL") << (why.empty() ? "" : ": " + why) << ")\n";
    if(!ok)
      failed.push_back(name);
  }
  void info(const std::string& name, const std::string& value)
  {
    std::cout << name << ": " << value << " (report)\n";
  }
  void add(const std::string& key, const std::string& value) { summary.emplace_back(key, value); }
  void add(const std::string& key, double value) { summary.emplace_back(key, format(value)); }
  void add(const std::string& key, std::size_t value) { summary.emplace_back(key, std::to_string(value)); }
};

}  // namespace

int main(int argc, char** argv)
{
  const Options options = parse_options(argc, argv);

  Reference ref;
  build_reference(options.input, ref);
  if(options.input_only) {
    std::size_t closed = 0;
    for(const Input_component& c : ref.components)
      closed += c.closed() ? 1 : 0;
    // A surface has no edge shared by more than two faces (the repair splits
    // non-manifold vertices, but such an edge is a cell complex, not a surface).
    std::vector<Point> input_points;
    std::vector<Polygon> input_polygons;
    read_soup(options.input, "INPUT", input_points, input_polygons);
    PMP::repair_polygon_soup(input_points, input_polygons);
    const Quad_topology input_topo = quad_topology(input_points.size(), input_polygons);
    std::cout << "input: " << options.input << ": " << num_faces(ref.mesh) << " triangles, "
              << ref.components.size() << " component(s), " << closed << " closed, bbox diagonal "
              << format(ref.diagonal) << ", area " << format(ref.area) << ", "
              << input_topo.non_manifold_edges << " edges of more than two faces\n";
    if(input_topo.non_manifold_edges > 0)
      unreadable("INPUT '" + options.input + "' is not a surface: " + std::to_string(input_topo.non_manifold_edges) +
                 " edges are shared by more than two faces");
    return 0;
  }

  std::vector<Point> points;
  std::vector<Polygon> polygons;
  read_soup(options.quads, "QUADS", points, polygons);

  Report report;
  std::cout << "input: " << options.input << ": " << num_faces(ref.mesh) << " triangles, "
            << ref.components.size() << " component(s), bbox diagonal " << format(ref.diagonal);
  if(ref.polygons_triangulated > 0)
    std::cout << ", " << ref.polygons_triangulated << " polygon(s) triangulated"
              << (ref.fan_fallbacks > 0 ? " (" + std::to_string(ref.fan_fallbacks) + " as fans)" : std::string());
  std::cout << "\n";

  // --- all quads --------------------------------------------------------------
  std::size_t non_quads = 0;
  for(const Polygon& polygon : polygons)
    if(polygon.size() != 4)
      ++non_quads;
  {
    std::ostringstream value;
    value << polygons.size() << " faces, " << non_quads << " not quads";
    report.line("all_quads", value.str(), !polygons.empty() && non_quads == 0,
                polygons.empty() ? "no face" : (non_quads > 0 ? "faces that are not quads" : ""));
  }

  // --- manifold ---------------------------------------------------------------
  const Quad_topology topo = quad_topology(points.size(), polygons);
  const bool soup_is_mesh = !polygons.empty() && PMP::is_polygon_soup_a_polygon_mesh(polygons);
  bool mesh_valid = false;
  if(soup_is_mesh) {
    // Points no face uses would be isolated vertices: counted in the statistics, not here.
    std::vector<Point> used_points = points;
    std::vector<Polygon> renumbered = polygons;
    PMP::remove_isolated_points_in_polygon_soup(used_points, renumbered);
    Mesh quad_mesh;
    PMP::polygon_soup_to_polygon_mesh(used_points, renumbered, quad_mesh);
    mesh_valid = CGAL::is_valid_polygon_mesh(quad_mesh);
  }
  {
    std::ostringstream value;
    value << topo.non_manifold_edges << " non-manifold edges, " << topo.inconsistent_edges
          << " edges with inconsistent orientation, " << topo.non_manifold_vertices << " non-manifold vertices, "
          << topo.repeated_vertex_polygons << " faces with a repeated vertex";
    std::string why;
    if(!soup_is_mesh)
      why = "not a polygon mesh (PMP::is_polygon_soup_a_polygon_mesh)";
    else if(!mesh_valid)
      why = "the Surface_mesh made from it is not valid";
    report.line("manifold", value.str(), soup_is_mesh && mesh_valid, why);
  }

  // Geometry of the quad vertices: finite, distance to the input, component
  // of the nearest input triangle.
  const std::size_t nq = polygons.size();
  std::vector<double> vertex_distance(points.size(), 0);
  std::vector<std::size_t> vertex_input_component(points.size(), 0);
  std::size_t non_finite = 0;
  for(std::size_t v = 0; v < points.size(); ++v) {
    if(topo.vertex_polygons[v].empty())
      continue;
    if(!is_finite(points[v])) {
      ++non_finite;
      vertex_distance[v] = std::numeric_limits<double>::infinity();
      continue;
    }
    const auto hit = ref.tree.closest_point_and_primitive(points[v]);
    vertex_distance[v] = std::sqrt(CGAL::squared_distance(points[v], hit.first));
    vertex_input_component[v] = ref.component[std::size_t(hit.second - ref.triangles.cbegin())];
  }

  // Mean quad edge length.
  double edge_length_sum = 0;
  std::size_t edge_count = 0;
  for(const Soup_edge& e : topo.edges) {
    const double l = std::sqrt(CGAL::squared_distance(points[e.a], points[e.b]));
    if(std::isfinite(l)) {
      edge_length_sum += l;
      ++edge_count;
    }
  }
  const double mean_edge = edge_count > 0 ? edge_length_sum / double(edge_count) : 0;

  // --- components -------------------------------------------------------------
  // Each quad component votes, by its vertices, for the input component it lies on.
  std::vector<std::map<std::size_t, std::size_t>> votes(topo.component_count);
  std::vector<std::set<std::size_t>> component_vertices(topo.component_count);
  for(std::size_t p = 0; p < nq; ++p)
    for(std::size_t v : polygons[p])
      component_vertices[topo.component[p]].insert(v);
  std::vector<std::size_t> matched_input(topo.component_count, 0);
  for(std::size_t c = 0; c < topo.component_count; ++c) {
    for(std::size_t v : component_vertices[c])
      if(is_finite(points[v]))
        ++votes[c][vertex_input_component[v]];
    std::size_t best = 0, best_votes = 0;
    for(const auto& [input_c, n] : votes[c])
      if(n > best_votes) {
        best = input_c;
        best_votes = n;
      }
    matched_input[c] = best;
  }
  std::vector<std::vector<std::size_t>> quads_of_input(ref.components.size());
  for(std::size_t c = 0; c < topo.component_count; ++c)
    quads_of_input[matched_input[c]].push_back(c);
  {
    std::size_t without = 0, with_several = 0;
    std::ostringstream detail;
    for(std::size_t i = 0; i < ref.components.size(); ++i) {
      if(quads_of_input[i].size() == 1)
        continue;
      (quads_of_input[i].empty() ? without : with_several) += 1;
      if(without + with_several <= 5)
        detail << (detail.str().empty() ? "" : "; ") << "input component " << i << " ("
               << ref.components[i].faces << " triangles) has " << quads_of_input[i].size()
               << " quad components";
    }
    std::ostringstream value;
    value << "input " << ref.components.size() << ", quads " << topo.component_count;
    const bool ok = topo.component_count == ref.components.size() && without == 0 && with_several == 0;
    report.line("components", value.str(), ok, detail.str());
  }

  // --- Euler characteristic ----------------------------------------------------
  std::vector<std::size_t> component_faces(topo.component_count, 0), component_edges(topo.component_count, 0),
      component_border_edges(topo.component_count, 0);
  for(std::size_t p = 0; p < nq; ++p)
    ++component_faces[topo.component[p]];
  for(const Soup_edge& e : topo.edges) {
    const std::size_t c = topo.component[e.polygons[0]];
    ++component_edges[c];
    if(e.polygons.size() == 1)
      ++component_border_edges[c];
  }
  {
    std::size_t closed_checked = 0, mismatches = 0, open_pairs = 0, open_differ = 0;
    std::ostringstream detail;
    for(std::size_t i = 0; i < ref.components.size(); ++i) {
      if(quads_of_input[i].size() != 1)
        continue;  // said by "components"
      const std::size_t c = quads_of_input[i][0];
      const long chi = long(component_vertices[c].size()) - long(component_edges[c]) + long(component_faces[c]);
      const bool quads_closed = component_border_edges[c] == 0;
      const Input_component& in = ref.components[i];
      if(in.closed()) {
        ++closed_checked;
        if(!quads_closed || chi != in.euler()) {
          ++mismatches;
          if(mismatches <= 5)
            detail << (detail.str().empty() ? "" : "; ") << "input component " << i << " closed, chi "
                   << in.euler() << ", its quads " << (quads_closed ? "closed" : "open") << ", chi " << chi;
        }
      } else {
        ++open_pairs;
        if(chi != in.euler())
          ++open_differ;
      }
    }
    std::ostringstream value;
    value << closed_checked << " closed component(s) compared, " << mismatches << " mismatch(es)";
    if(open_pairs > 0)
      value << "; " << open_pairs << " open component(s), " << open_differ << " with another chi (not checked)";
    report.line("euler", value.str(), mismatches == 0, detail.str());
    report.add("euler_mismatches", mismatches);
  }

  // --- every vertex on the surface --------------------------------------------
  {
    double max_distance = 0;
    for(std::size_t v = 0; v < points.size(); ++v)
      if(!topo.vertex_polygons[v].empty())
        max_distance = std::max(max_distance, vertex_distance[v]);
    const bool edge_relative = options.distance_tolerance_edge >= 0;
    const double bound = edge_relative ? options.distance_tolerance_edge * mean_edge
                                       : options.distance_tolerance * ref.diagonal;
    std::size_t beyond = 0;
    for(std::size_t v = 0; v < points.size(); ++v)
      if(!topo.vertex_polygons[v].empty() && !(vertex_distance[v] <= bound))
        ++beyond;
    std::ostringstream value;
    value << "max distance " << format(max_distance / ref.diagonal) << " bbox diagonal ("
          << format(mean_edge > 0 ? max_distance / mean_edge : 0) << " mean quad edge), " << beyond
          << " vertices beyond " << format(bound);
    std::ostringstream why;
    if(non_finite > 0)
      why << non_finite << " vertices with a coordinate that is not finite; ";
    why << "bound " << (edge_relative ? format(options.distance_tolerance_edge) + " mean quad edge"
                                      : format(options.distance_tolerance) + " bbox diagonal");
    report.line("on_surface", value.str(), beyond == 0 && non_finite == 0, why.str());
    report.add("max_distance", max_distance / ref.diagonal);
  }

  // --- planarity of the quads ---------------------------------------------------
  // The distance between the two diagonals (as lines) over their mean length;
  // for diagonals that are parallel, the distance of a vertex of one to the
  // line of the other. Reported always; a check with --max-planarity.
  {
    double max_planarity = 0, sum = 0;
    std::size_t counted = 0, beyond = 0;
    for(const Polygon& q : polygons) {
      if(q.size() != 4)
        continue;
      const Point &a = points[q[0]], &b = points[q[1]], &c = points[q[2]], &d = points[q[3]];
      if(!is_finite(a) || !is_finite(b) || !is_finite(c) || !is_finite(d))
        continue;
      const Vector d1 = c - a, d2 = d - b;
      const double l1 = std::sqrt(d1.squared_length()), l2 = std::sqrt(d2.squared_length());
      const double mean_diagonal = 0.5 * (l1 + l2);
      if(!(mean_diagonal > 0))
        continue;
      const Vector normal = CGAL::cross_product(d1, d2);
      const double normal_length = std::sqrt(normal.squared_length());
      double gap = 0;
      if(normal_length > 1e-12 * l1 * l2)
        gap = std::abs((b - a) * normal) / normal_length;
      else if(l1 > 0)
        gap = std::sqrt(CGAL::cross_product(b - a, d1).squared_length()) / l1;
      const double planarity = gap / mean_diagonal;
      max_planarity = std::max(max_planarity, planarity);
      sum += planarity;
      ++counted;
      if(options.max_planarity >= 0 && !(planarity <= options.max_planarity * (1 + 1e-9)))
        ++beyond;
    }
    std::ostringstream value;
    value << "max " << format(max_planarity) << ", mean " << format(counted > 0 ? sum / double(counted) : 0)
          << " (diagonal distance over mean diagonal, " << counted << " quads)";
    if(options.max_planarity >= 0) {
      value << ", " << beyond << " beyond " << format(options.max_planarity);
      report.line("planar", value.str(), beyond == 0, "bound " + format(options.max_planarity));
    } else {
      report.info("planarity", value.str());
    }
    report.add("max_planarity", max_planarity);
  }

  // --- folds --------------------------------------------------------------------
  std::size_t folded = 0, reversed = 0, folded_both = 0;
  double quad_area = 0;
  for(std::size_t p = 0; p < nq; ++p) {
    const Polygon& q = polygons[p];
    bool finite = true;
    for(std::size_t v : q)
      finite = finite && is_finite(points[v]);
    if(!finite)
      continue;
    if(q.size() != 4) {
      // Only its area, by a fan (it already failed "all_quads").
      for(std::size_t i = 1; i + 1 < q.size(); ++i)
        quad_area += std::sqrt(Triangle(points[q[0]], points[q[i]], points[q[i + 1]]).squared_area());
      continue;
    }
    const Point& a = points[q[0]];
    const Point& b = points[q[1]];
    const Point& c = points[q[2]];
    const Point& d = points[q[3]];
    const Vector splits[4] = {CGAL::cross_product(b - a, c - a), CGAL::cross_product(c - a, d - a),
                              CGAL::cross_product(c - b, d - b), CGAL::cross_product(d - b, a - b)};
    quad_area += 0.25 * (std::sqrt(splits[0].squared_length()) + std::sqrt(splits[1].squared_length()) +
                         std::sqrt(splits[2].squared_length()) + std::sqrt(splits[3].squared_length()));
    const Point centroid = CGAL::centroid(a, b, c, d);
    const auto hit = ref.tree.closest_point_and_primitive(centroid);
    const Vector& n = ref.normals[std::size_t(hit.second - ref.triangles.cbegin())];
    bool against[4];
    int negative = 0;
    for(int k = 0; k < 4; ++k) {
      against[k] = !(splits[k] * n > 0);
      negative += against[k] ? 1 : 0;
    }
    if(negative > 0)
      ++folded;
    if((against[0] || against[1]) && (against[2] || against[3]))
      ++folded_both;  // no triangulation of the quad faces the right way
    if(negative == 4)
      ++reversed;
  }
  {
    std::ostringstream value;
    value << folded << " of " << nq << " quads have a triangle (of either diagonal) against the input normal: "
          << reversed << " reversed, " << folded_both << " along both diagonals, " << folded - folded_both
          << " along one diagonal only (a dart, or a corner near 180 degrees)";
    // A quad is folded when neither diagonal splits it into two triangles that face
    // the surface's side; a dart (a corner near or past 180 degrees, folded along
    // one diagonal only) is a poor quad, not a fold, and is reported.
    report.line("folded", value.str(), folded_both == 0);
    report.add("folded", folded);
    report.add("folded_both_diagonals", folded_both);
  }

  // --- area covered -----------------------------------------------------------------
  const double area_ratio = ref.area > 0 ? quad_area / ref.area : 0;
  {
    std::ostringstream value;
    value << format(area_ratio) << " (quads " << format(quad_area) << ", input " << format(ref.area) << ")";
    if(options.min_area_ratio > 0)
      report.line("area_ratio", value.str(), area_ratio >= options.min_area_ratio,
                  "bar >= " + format(options.min_area_ratio));
    else
      report.info("area_ratio", value.str());
  }

  // --- the other side of the Hausdorff distance -----------------------------------
  std::vector<Triangle> quad_triangles;
  for(const Polygon& q : polygons) {
    bool finite = true;
    for(std::size_t v : q)
      finite = finite && is_finite(points[v]);
    if(!finite || q.size() < 3)
      continue;
    if(q.size() == 4) {
      quad_triangles.emplace_back(points[q[0]], points[q[1]], points[q[2]]);
      quad_triangles.emplace_back(points[q[0]], points[q[2]], points[q[3]]);
      quad_triangles.emplace_back(points[q[1]], points[q[2]], points[q[3]]);
      quad_triangles.emplace_back(points[q[1]], points[q[3]], points[q[0]]);
    } else {
      for(std::size_t i = 1; i + 1 < q.size(); ++i)
        quad_triangles.emplace_back(points[q[0]], points[q[i]], points[q[i + 1]]);
    }
  }
  double hausdorff = std::numeric_limits<double>::infinity();
  if(!quad_triangles.empty()) {
    Triangle_tree quad_tree(quad_triangles.cbegin(), quad_triangles.cend());
    quad_tree.accelerate_distance_queries();
    double worst = 0;
    for(auto v : vertices(ref.mesh))
      worst = std::max(worst, quad_tree.squared_distance(ref.mesh.point(v)));
    for(face_descriptor f : faces(ref.mesh)) {
      const halfedge_descriptor h = halfedge(f, ref.mesh);
      const Point centroid = CGAL::centroid(ref.mesh.point(source(h, ref.mesh)), ref.mesh.point(target(h, ref.mesh)),
                                            ref.mesh.point(target(next(h, ref.mesh), ref.mesh)));
      worst = std::max(worst, quad_tree.squared_distance(centroid));
    }
    hausdorff = std::sqrt(worst) / ref.diagonal;
  }
  report.line("hausdorff",
              "max distance of an input vertex or face centroid to the quads: " + format(hausdorff) + " bbox diagonal",
              hausdorff <= options.max_hausdorff, "bar <= " + format(options.max_hausdorff));

  // --- sharp edges and boundary edges on quad edges -------------------------------
  // Each input edge is sampled at 5 interior points. A sample is *covered*
  // when a quad edge (a segment) passes within 1% of the mean quad edge length
  // of it. It is *traced* when it is covered, or when it lies between the two
  // ends of a quad edge whose ends are both on the selected input edges
  // (within that 1%) and is within a quarter of that quad edge's length of it:
  // a curved crease followed by quad edges, each a chord of the crease, off it
  // by its sagitta. The next parallel iso-line is a whole quad away, so a
  // quarter of a quad edge does not count a crease that the quads cross or run
  // beside. The largest sagitta of the traced samples is reported too.
  std::vector<Segment> quad_edges;
  std::vector<std::pair<std::size_t, std::size_t> > quad_edge_ends;
  for(const Soup_edge& e : topo.edges)
    if(is_finite(points[e.a]) && is_finite(points[e.b]) && points[e.a] != points[e.b]) {
      quad_edges.emplace_back(points[e.a], points[e.b]);
      quad_edge_ends.emplace_back(e.a, e.b);
    }
  Segment_tree edge_tree(quad_edges.cbegin(), quad_edges.cend());
  if(!quad_edges.empty())
    edge_tree.accelerate_distance_queries();
  const double coverage_tolerance = 0.01 * mean_edge;
  struct Coverage {
    std::size_t edges = 0, samples = 0, covered = 0, edges_covered = 0, traced = 0;
    double largest_sagitta = 0;  // of the traced samples, over the mean quad edge
    double fraction() const { return samples > 0 ? double(covered) / double(samples) : 1.0; }
    double traced_fraction() const { return samples > 0 ? double(traced) / double(samples) : 1.0; }
  };
  auto coverage_of = [&](auto&& selected) {
    Coverage c;
    const int samples_per_edge = 5;
    std::vector<Segment> input_edges;
    for(edge_descriptor e : edges(ref.mesh))
      if(selected(e))
        input_edges.emplace_back(ref.mesh.point(source(halfedge(e, ref.mesh), ref.mesh)),
                                 ref.mesh.point(target(halfedge(e, ref.mesh), ref.mesh)));
    if(input_edges.empty())
      return c;
    // the quad edges whose two ends are on the selected input edges
    Segment_tree input_tree(input_edges.cbegin(), input_edges.cend());
    input_tree.accelerate_distance_queries();
    std::vector<char> end_on_feature(points.size(), 2);  // 2: not computed yet
    auto on_feature = [&](std::size_t v) {
      if(end_on_feature[v] == 2)
        end_on_feature[v] = std::sqrt(input_tree.squared_distance(points[v])) <= coverage_tolerance ? 1 : 0;
      return end_on_feature[v] == 1;
    };
    std::vector<Segment> chords;
    for(std::size_t i = 0; i < quad_edges.size(); ++i)
      if(on_feature(quad_edge_ends[i].first) && on_feature(quad_edge_ends[i].second))
        chords.push_back(quad_edges[i]);
    Segment_tree chord_tree(chords.cbegin(), chords.cend());
    if(!chords.empty())
      chord_tree.accelerate_distance_queries();
    for(const Segment& edge : input_edges) {
      ++c.edges;
      std::size_t here = 0;
      for(int k = 0; k < samples_per_edge; ++k) {
        const Point sample = edge.source() + ((k + 0.5) / samples_per_edge) * (edge.target() - edge.source());
        ++c.samples;
        if(!quad_edges.empty() && std::sqrt(edge_tree.squared_distance(sample)) <= coverage_tolerance) {
          ++here;
          ++c.traced;
          continue;
        }
        if(chords.empty())
          continue;
        const auto closest = chord_tree.closest_point_and_primitive(sample);
        const Segment& chord = *closest.second;
        const Vector d = chord.target() - chord.source();
        const double t = ((sample - chord.source()) * d) / d.squared_length();
        const double distance = std::sqrt(CGAL::squared_distance(sample, closest.first));
        if(t > 0 && t < 1 && distance <= 0.25 * std::sqrt(d.squared_length())) {
          ++c.traced;
          c.largest_sagitta = std::max(c.largest_sagitta, distance / mean_edge);
        }
      }
      c.covered += here;
      if(here == std::size_t(samples_per_edge))
        ++c.edges_covered;
    }
    return c;
  };
  auto coverage_text = [&](const Coverage& c) {
    std::ostringstream value;
    value << format(100 * c.fraction()) << "% of their " << c.samples << " samples within "
          << format(coverage_tolerance) << " (1% of the mean quad edge) of a quad edge; " << c.edges_covered
          << " edges covered entirely; " << format(100 * c.traced_fraction())
          << "% traced by quad edges with both ends on them (chords of a curved crease: largest sagitta "
          << format(c.largest_sagitta) << " mean quad edges)";
    return value.str();
  };
  const Coverage boundary = coverage_of([&](edge_descriptor e) { return CGAL::is_border(e, ref.mesh); });
  report.info("boundary_edges", std::to_string(boundary.edges) + " input boundary edges; " + coverage_text(boundary));
  std::string sharp_count = "-", sharp_coverage = "-", sharp_edges_covered = "-", sharp_traced = "-",
              sharp_sagitta = "-";
  if(options.sharp_degrees >= 0) {
    // detect_sharp_edges() also marks the boundary: only interior edges count here.
    auto is_sharp = ref.mesh.add_property_map<edge_descriptor, bool>("e:check_sharp", false).first;
    PMP::detect_sharp_edges(ref.mesh, options.sharp_degrees, is_sharp);
    const Coverage sharp =
        coverage_of([&](edge_descriptor e) { return is_sharp[e] && !CGAL::is_border(e, ref.mesh); });
    report.info("sharp_edges", std::to_string(sharp.edges) + " interior input edges above " +
                                   format(options.sharp_degrees) + " degrees; " + coverage_text(sharp));
    sharp_count = std::to_string(sharp.edges);
    sharp_coverage = format(sharp.fraction());
    sharp_edges_covered = std::to_string(sharp.edges_covered);
    sharp_traced = format(sharp.traced_fraction());
    sharp_sagitta = format(sharp.largest_sagitta);
  }

  // --- statistics ----------------------------------------------------------------------
  // Interior vertex: regular with 4 edges. Boundary vertex: regular when its
  // number of faces equals its interior angle in right angles (1 at a 90
  // degree corner, 2 along a straight boundary, 3 at a 270 degree corner).
  std::size_t used_vertices = 0, irregular_interior = 0, irregular_boundary = 0, boundary_vertices = 0;
  {
    std::vector<double> corner_angle_sum(points.size(), 0);
    for(const Polygon& q : polygons)
      for(std::size_t i = 0; i < q.size(); ++i) {
        const Point& prev_p = points[q[(i + q.size() - 1) % q.size()]];
        const Point& here = points[q[i]];
        const Point& next_p = points[q[(i + 1) % q.size()]];
        corner_angle_sum[q[i]] += angle_between(prev_p - here, next_p - here);
      }
    for(std::size_t v = 0; v < points.size(); ++v) {
      if(topo.vertex_polygons[v].empty())
        continue;
      ++used_vertices;
      bool on_boundary = false;
      for(std::size_t ei : topo.vertex_edges[v])
        on_boundary = on_boundary || topo.edges[ei].polygons.size() == 1;
      if(!on_boundary) {
        if(topo.vertex_edges[v].size() != 4)
          ++irregular_interior;
        continue;
      }
      ++boundary_vertices;
      const double right_angles = corner_angle_sum[v] / (0.5 * CGAL_PI);
      const long expected = std::max(1L, std::lround(right_angles));
      if(long(topo.vertex_polygons[v].size()) != expected)
        ++irregular_boundary;
    }
    std::ostringstream value;
    value << nq << " faces, " << used_vertices << " vertices (" << boundary_vertices << " on the boundary), "
          << irregular_interior << " irregular interior vertices (valence != 4), " << irregular_boundary
          << " irregular boundary vertices, mean edge " << format(mean_edge);
    if(topo.unreferenced_points > 0)
      value << ", " << topo.unreferenced_points << " unreferenced points";
    report.info("statistics", value.str());
  }

  // --- summary ------------------------------------------------------------------------
  const bool valid = report.failed.empty();
  std::string failed_list;
  for(const std::string& name : report.failed)
    failed_list += (failed_list.empty() ? "" : ",") + name;
  std::cout << "summary valid=" << (valid ? 1 : 0) << " failed=" << (valid ? "none" : failed_list)
            << " quads=" << nq << " non_quads=" << non_quads << " vertices=" << used_vertices
            << " input_components=" << ref.components.size() << " quad_components=" << topo.component_count
            << " irregular_interior=" << irregular_interior << " irregular_boundary=" << irregular_boundary
            << " area_ratio=" << format(area_ratio) << " hausdorff=" << format(hausdorff)
            << " sharp_edges=" << sharp_count << " sharp_coverage=" << sharp_coverage
            << " sharp_edges_covered=" << sharp_edges_covered << " sharp_traced=" << sharp_traced
            << " sharp_largest_sagitta=" << sharp_sagitta << " boundary_edges=" << boundary.edges
            << " boundary_coverage=" << format(boundary.fraction())
            << " boundary_traced=" << format(boundary.traced_fraction()) << " mean_edge=" << format(mean_edge);
  for(const auto& [key, value] : report.summary)
    std::cout << " " << key << "=" << value;
  std::cout << std::endl;
  return valid ? 0 : 1;
}
