// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_SOUP_REPAIR_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_SOUP_REPAIR_H

// The checks that a polygon soup must pass to become a surface mesh, each with
// its own message, and the repairs that make it pass them, each counted. The
// order is that of the checks: a repair may create the next problem (merging
// points can make polygons degenerate or duplicate) but never an earlier one.
//   1. duplicate points (repair only: merged; a soup of separate triangles, as
//      STL files are, becomes a connected surface);
//   2. polygons that repeat a vertex (repair: consecutive repetitions removed,
//      what is left with fewer than 3 distinct vertices dropped);
//   3. polygons with more than 3 vertices (refused without repair; with repair
//      triangulated afterwards, see triangulate_polygons.h);
//   4. duplicate polygons, the same vertex set in any order (repair: dropped);
//   5. non-manifold edges, inconsistent orientations and pinched vertices
//      (repair: CGAL's orient_polygon_soup, which reverses polygons and
//      duplicates vertices until the soup is an oriented manifold);
//   6. isolated vertices (repair: removed; without repair they are kept: they
//      do not change the field).
// `source[i]` follows each polygon to the polygon of the file it comes from.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/IO/internal/polygon_soup.h>
#include <CGAL/Polyvector_fields/IO/internal/text_parsing.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// What a repair changed (see Mesh_repair_report).
struct Soup_repair_counts
{
  std::size_t merged_points = 0;
  std::size_t degenerate_polygons = 0;
  std::size_t duplicate_faces = 0;
  std::size_t reoriented_faces = 0;
  std::size_t split_vertices = 0;
  std::size_t isolated_vertices = 0;
};

// Replaces the polygons of `soup` by `polygons` (with their lines and sources).
inline void set_polygons(Polygon_soup& soup, const std::vector<std::vector<std::size_t> >& polygons,
                         std::vector<std::size_t> lines)
{
  soup.ids.clear();
  soup.first.assign(1, 0);
  for(const auto& polygon : polygons)
  {
    soup.ids.insert(soup.ids.end(), polygon.begin(), polygon.end());
    soup.first.push_back(soup.ids.size());
  }
  soup.polygon_line = std::move(lines);
}

// Keeps the polygons whose `keep` flag is set, in order, with their lines and sources.
inline void keep_polygons(Polygon_soup& soup, std::vector<std::size_t>& source, const std::vector<char>& keep)
{
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<std::size_t> lines, kept_source;
  for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
    if(keep[i])
    {
      polygons.emplace_back(soup.polygon(i), soup.polygon(i) + soup.size(i));
      if(i < soup.polygon_line.size())
        lines.push_back(soup.polygon_line[i]);
      kept_source.push_back(source[i]);
    }
  set_polygons(soup, polygons, std::move(lines));
  source.swap(kept_source);
}

// 1. Points with the same coordinates (+0 and -0 alike) become one.
inline std::size_t merge_duplicate_points(Polygon_soup& soup)
{
  struct Key_hash
  {
    std::size_t operator()(const std::array<double, 3>& p) const
    {
      std::uint64_t h = 0x9E3779B97F4A7C15ULL;
      for(double x : p)
      {
        std::uint64_t bits;
        const double y = (x == 0.) ? 0. : x;
        std::memcpy(&bits, &y, sizeof bits);
        h ^= bits + 0x9E3779B97F4A7C15ULL + (h << 6) + (h >> 2);
      }
      return std::size_t(h);
    }
  };
  struct Key_equal
  {
    bool operator()(const std::array<double, 3>& a, const std::array<double, 3>& b) const
    {
      return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    }
  };
  std::unordered_map<std::array<double, 3>, std::size_t, Key_hash, Key_equal> first;
  first.reserve(soup.points.size());
  std::vector<std::size_t> representative(soup.points.size());
  std::size_t merged = 0;
  for(std::size_t v = 0; v < soup.points.size(); ++v)
  {
    const auto inserted = first.emplace(soup.points[v], v);
    representative[v] = inserted.first->second;
    merged += inserted.second ? 0 : 1;
  }
  if(merged > 0)
    for(std::size_t& id : soup.ids)
      id = representative[id];
  return merged;  // the merged-away points are isolated now
}

// 2. Repeated vertices. Without repair: the first offending polygon is
// refused. With repair: consecutive repetitions (cyclically) are removed; a
// polygon that still repeats a vertex (pinched) or keeps fewer than 3 vertices
// is dropped. `fixed` counts the polygons changed or dropped.
inline Error_code fix_repeated_vertices(Polygon_soup& soup, std::vector<std::size_t>& source, bool repair,
                                        std::size_t& fixed, const Diagnostic& diagnostic)
{
  auto repeated_vertex = [](std::vector<std::size_t> polygon, std::size_t& vertex) {
    std::sort(polygon.begin(), polygon.end());
    const auto it = std::adjacent_find(polygon.begin(), polygon.end());
    if(it == polygon.end())
      return false;
    vertex = *it;
    return true;
  };
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<std::size_t> lines, kept_source;
  fixed = 0;
  for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
  {
    std::vector<std::size_t> polygon(soup.polygon(i), soup.polygon(i) + soup.size(i));
    std::size_t vertex = 0;
    if(repeated_vertex(polygon, vertex))
    {
      if(!repair)
        return diagnostic.fail(Error_code::DEGENERATE_FACE, soup.face_name(i) + " repeats " + soup.vertex_name(vertex));
      ++fixed;
      std::vector<std::size_t> simplified;
      for(std::size_t k = 0; k < polygon.size(); ++k)
        if(polygon[k] != polygon[(k + 1) % polygon.size()])
          simplified.push_back(polygon[k]);
      if(simplified.size() < 3 || repeated_vertex(simplified, vertex))
        continue;
      polygon.swap(simplified);
    }
    polygons.push_back(std::move(polygon));
    if(i < soup.polygon_line.size())
      lines.push_back(soup.polygon_line[i]);
    kept_source.push_back(source[i]);
  }
  if(fixed > 0)
  {
    set_polygons(soup, polygons, std::move(lines));
    source.swap(kept_source);
  }
  return Error_code::SUCCESS;
}

// 4. Polygons with the same vertex set as an earlier one.
inline Error_code remove_duplicate_polygons(Polygon_soup& soup, std::vector<std::size_t>& source, bool repair,
                                            std::size_t& removed, const Diagnostic& diagnostic)
{
  const std::size_t n = soup.number_of_polygons();
  std::vector<std::vector<std::size_t> > keys(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    keys[i].assign(soup.polygon(i), soup.polygon(i) + soup.size(i));
    std::sort(keys[i].begin(), keys[i].end());
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  // The sort is stable: the first polygon of a run of equal keys is the earliest one, the one kept.
  std::vector<char> keep(n, 1);
  removed = 0;
  for(std::size_t k = 1, run = 0; k < n; ++k)
  {
    if(keys[order[k]] != keys[order[run]])
    {
      run = k;
      continue;
    }
    if(!repair)
      return diagnostic.fail(Error_code::DUPLICATE_FACE, soup.face_name(order[k]) + " has the same vertices as " +
                                                           soup.face_name(order[run]));
    keep[order[k]] = 0;
    ++removed;
  }
  if(removed > 0)
    keep_polygons(soup, source, keep);
  return Error_code::SUCCESS;
}

// 5. Without repair: the first non-manifold edge, inconsistently oriented
// edge, or pinched vertex is refused. Returns SUCCESS and sets `manifold`.
inline Error_code check_manifold(const Polygon_soup& soup, bool& manifold, const Diagnostic& diagnostic)
{
  struct Half
  {
    std::size_t a, b, polygon;  // a < b
    bool forward;               // the polygon runs a -> b
  };
  std::vector<Half> halves;
  halves.reserve(soup.ids.size());
  for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
  {
    const std::size_t* p = soup.polygon(i);
    const std::size_t n = soup.size(i);
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t u = p[k], v = p[(k + 1) % n];
      halves.push_back(Half{ (std::min)(u, v), (std::max)(u, v), i, u < v });
    }
  }
  std::sort(halves.begin(), halves.end(), [](const Half& x, const Half& y) {
    return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.polygon < y.polygon);
  });
  manifold = true;
  for(std::size_t k = 0; k < halves.size();)
  {
    std::size_t end = k;
    while(end < halves.size() && halves[end].a == halves[k].a && halves[end].b == halves[k].b)
      ++end;
    const std::string edge = "the edge between vertices " + std::to_string(halves[k].a) + " and " + std::to_string(halves[k].b);
    if(end - k > 2)
    {
      manifold = false;
      return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, edge + " is shared by " + std::to_string(end - k) +
                                                              " faces (" + soup.face_name(halves[k].polygon) + ", " +
                                                              soup.face_name(halves[k + 1].polygon) + ", " +
                                                              soup.face_name(halves[k + 2].polygon) +
                                                              (end - k > 3 ? ", ..." : "") + ")");
    }
    if(end - k == 2 && halves[k].forward == halves[k + 1].forward)
    {
      manifold = false;
      return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, soup.face_name(halves[k].polygon) + " and " +
                                                              soup.face_name(halves[k + 1].polygon) +
                                                              " are oriented inconsistently across " + edge);
    }
    k = end;
  }
  // Pinched vertices: the corners at a vertex must form one fan, i.e. be
  // connected through the edges they share.
  struct Corner
  {
    std::size_t vertex, previous, next;
  };
  std::vector<Corner> corners;
  corners.reserve(soup.ids.size());
  for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
  {
    const std::size_t* p = soup.polygon(i);
    const std::size_t n = soup.size(i);
    for(std::size_t k = 0; k < n; ++k)
      corners.push_back(Corner{ p[k], p[(k + n - 1) % n], p[(k + 1) % n] });
  }
  std::sort(corners.begin(), corners.end(), [](const Corner& x, const Corner& y) { return x.vertex < y.vertex; });
  std::vector<std::size_t> parent;
  std::vector<std::pair<std::size_t, std::size_t> > ends;  // (neighbour vertex, corner)
  for(std::size_t k = 0; k < corners.size();)
  {
    std::size_t end = k;
    while(end < corners.size() && corners[end].vertex == corners[k].vertex)
      ++end;
    const std::size_t count = end - k;
    parent.resize(count);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&](std::size_t x) {
      while(parent[x] != x)
        x = parent[x] = parent[parent[x]];
      return x;
    };
    ends.clear();
    for(std::size_t c = 0; c < count; ++c)
    {
      ends.emplace_back(corners[k + c].previous, c);
      ends.emplace_back(corners[k + c].next, c);
    }
    std::sort(ends.begin(), ends.end());
    for(std::size_t e = 1; e < ends.size(); ++e)
      if(ends[e].first == ends[e - 1].first)
        parent[find(ends[e].second)] = find(ends[e - 1].second);
    std::size_t fans = 0;
    for(std::size_t c = 0; c < count; ++c)
      fans += (find(c) == c) ? 1 : 0;
    if(fans > 1)
    {
      manifold = false;
      return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, soup.vertex_name(corners[k].vertex) +
                                                              " is pinched: its faces form " + std::to_string(fans) +
                                                              " separate fans");
    }
    k = end;
  }
  return Error_code::SUCCESS;
}

// Counts what CGAL's soup orientation does.
struct Orientation_counter : public CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::size_t* reversed;
  std::size_t* duplicated;
  Orientation_counter(std::size_t* r, std::size_t* d) : reversed(r), duplicated(d) {}
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
  void duplicated_vertex(std::size_t, std::size_t) { ++*duplicated; }
};

// 5 (repair). Orients the soup and splits what is not manifold.
inline Error_code orient_soup(Polygon_soup& soup, Soup_repair_counts& counts, const Diagnostic& diagnostic)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t> > polygons(soup.number_of_polygons());
  for(std::size_t i = 0; i < polygons.size(); ++i)
    polygons[i].assign(soup.polygon(i), soup.polygon(i) + soup.size(i));
  CGAL::Polygon_mesh_processing::orient_polygon_soup(
    points, polygons,
    CGAL::parameters::visitor(Orientation_counter(&counts.reoriented_faces, &counts.split_vertices)));
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, "the faces cannot be made into an oriented manifold surface");
  for(std::size_t v = soup.points.size(); v < points.size(); ++v)
  {
    soup.points.push_back({ points[v].x(), points[v].y(), points[v].z() });
    soup.point_line.push_back(0);
  }
  soup.point_line.resize(soup.points.size());
  set_polygons(soup, polygons, soup.polygon_line);
  return Error_code::SUCCESS;
}

// 6. Removes the points of no polygon; returns how many.
inline std::size_t remove_isolated_points(Polygon_soup& soup)
{
  std::vector<std::size_t> new_id(soup.points.size(), std::size_t(-1));
  for(std::size_t id : soup.ids)
    new_id[id] = 0;
  std::size_t kept = 0;
  for(std::size_t v = 0; v < soup.points.size(); ++v)
    if(new_id[v] == 0)
    {
      new_id[v] = kept;
      soup.points[kept] = soup.points[v];
      if(v < soup.point_line.size())
        soup.point_line[kept] = soup.point_line[v];
      ++kept;
    }
  const std::size_t removed = soup.points.size() - kept;
  soup.points.resize(kept);
  soup.point_line.resize((std::min)(soup.point_line.size(), kept));
  for(std::size_t& id : soup.ids)
    id = new_id[id];
  return removed;
}

inline std::size_t count_isolated_points(const Polygon_soup& soup)
{
  std::vector<char> used(soup.points.size(), 0);
  for(std::size_t id : soup.ids)
    used[id] = 1;
  return std::size_t(std::count(used.begin(), used.end(), 0));
}

// Steps 1 to 6 (3 only checks, without repair). On success the soup is an
// oriented manifold polygon soup.
inline Error_code check_or_repair_soup(Polygon_soup& soup, std::vector<std::size_t>& source, bool repair,
                                       Soup_repair_counts& counts, const Diagnostic& diagnostic)
{
  if(soup.number_of_polygons() == 0)
    return diagnostic.fail(Error_code::EMPTY_MESH, "the file has no face");
  source.resize(soup.number_of_polygons());
  std::iota(source.begin(), source.end(), std::size_t(0));
  if(repair)
    counts.merged_points = merge_duplicate_points(soup);
  Error_code code = fix_repeated_vertices(soup, source, repair, counts.degenerate_polygons, diagnostic);
  if(code != Error_code::SUCCESS)
    return code;
  if(soup.number_of_polygons() == 0)
    return diagnostic.fail(Error_code::EMPTY_MESH, "no face is left once the degenerate ones are removed");
  if(!repair)
    for(std::size_t i = 0; i < soup.number_of_polygons(); ++i)
      if(soup.size(i) != 3)
        return diagnostic.fail(Error_code::NON_TRIANGLE_FACE, soup.face_name(i) + " has " + std::to_string(soup.size(i)) +
                                                                " vertices: the mesh is not a triangle mesh");
  code = remove_duplicate_polygons(soup, source, repair, counts.duplicate_faces, diagnostic);
  if(code != Error_code::SUCCESS)
    return code;
  bool manifold = true;
  std::string ignored;
  code = check_manifold(soup, manifold, repair ? Diagnostic(&ignored) : diagnostic);
  if(!manifold)
  {
    if(!repair)
      return code;
    code = orient_soup(soup, counts, diagnostic);
    if(code != Error_code::SUCCESS)
      return code;
  }
  if(repair)
    counts.isolated_vertices = remove_isolated_points(soup);
  else
    counts.isolated_vertices = count_isolated_points(soup);
  return Error_code::SUCCESS;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_SOUP_REPAIR_H
