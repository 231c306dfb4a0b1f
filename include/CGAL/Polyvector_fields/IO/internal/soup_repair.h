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

// What a repair changed (see Mesh_repair_result).
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

// A 64-bit mix (the finaliser of MurmurHash3), for the hash tables below.
inline std::uint64_t mix_bits(std::uint64_t h)
{
  h ^= h >> 33;
  h *= 0xFF51AFD7ED558CCDULL;
  h ^= h >> 33;
  h *= 0xC4CEB93FE1A85EC3ULL;
  h ^= h >> 33;
  return h;
}

// The smallest power of two that is at least 2n (and 16): the size of an
// open-addressing table of n keys, at most half full.
inline std::size_t hash_table_size(std::size_t n)
{
  std::size_t size = 16;
  while(size < 2 * n)
    size *= 2;
  return size;
}

// 1. Points with the same coordinates (+0 and -0 alike) become one, the
// first of them in file order. One pass over an open-addressing table of
// point ids (no allocation per point).
inline std::size_t merge_duplicate_points(Polygon_soup& soup)
{
  const std::size_t n = soup.points.size();
  auto hash = [&](std::size_t v) {
    std::uint64_t h = 0x9E3779B97F4A7C15ULL;
    for(double x : soup.points[v])
    {
      std::uint64_t bits;
      const double y = (x == 0.) ? 0. : x;  // -0 hashes as +0
      std::memcpy(&bits, &y, sizeof bits);
      h = mix_bits(h ^ bits);
    }
    return h;
  };
  const std::size_t size = hash_table_size(n);
  std::vector<std::size_t> table(size, std::size_t(-1));
  std::vector<std::size_t> representative;
  std::size_t merged = 0;
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::array<double, 3>& p = soup.points[v];
    for(std::size_t slot = std::size_t(hash(v)) & (size - 1);; slot = (slot + 1) & (size - 1))
    {
      const std::size_t w = table[slot];
      if(w == std::size_t(-1))
      {
        table[slot] = v;
        break;
      }
      const std::array<double, 3>& q = soup.points[w];
      if(p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
      {
        if(representative.empty())
        {
          representative.resize(n);
          std::iota(representative.begin(), representative.end(), std::size_t(0));
        }
        representative[v] = w;
        ++merged;
        break;
      }
    }
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
  fixed = 0;
  // A first pass, without allocation for triangles, tells whether there is
  // anything to do; the pass below that does it is the rare case.
  {
    bool any = false;
    std::vector<std::size_t> sorted;
    for(std::size_t i = 0; i < soup.number_of_polygons() && !any; ++i)
    {
      const std::size_t* p = soup.polygon(i);
      if(soup.size(i) == 3)
        any = p[0] == p[1] || p[1] == p[2] || p[0] == p[2];
      else
      {
        sorted.assign(p, p + soup.size(i));
        std::sort(sorted.begin(), sorted.end());
        any = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      }
    }
    if(!any)
      return Error_code::SUCCESS;
  }
  std::vector<std::vector<std::size_t> > polygons;
  std::vector<std::size_t> lines, kept_source;
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

// Whether two polygons of `soup` have the same vertex set. Two such polygons
// have the same smallest vertex: the polygons are bucketed by it (a counting
// sort), and the few polygons of a bucket compared.
inline bool has_duplicate_polygons(const Polygon_soup& soup)
{
  const std::size_t n = soup.number_of_polygons();
  auto smallest = [&](std::size_t i) { return *std::min_element(soup.polygon(i), soup.polygon(i) + soup.size(i)); };
  std::vector<std::size_t> first(soup.points.size() + 1, 0);
  for(std::size_t i = 0; i < n; ++i)
    ++first[smallest(i) + 1];
  for(std::size_t v = 0; v + 1 < first.size(); ++v)
    first[v + 1] += first[v];
  std::vector<std::size_t> bucketed(n);
  {
    std::vector<std::size_t> cursor(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < n; ++i)
      bucketed[cursor[smallest(i)]++] = i;
  }
  // The sorted vertices of the polygons of a bucket, one after the other.
  std::vector<std::size_t> keys, key_first, order;
  for(std::size_t v = 0; v + 1 < first.size(); ++v)
  {
    const std::size_t count = first[v + 1] - first[v];
    if(count < 2)
      continue;
    keys.clear();
    key_first.assign(1, 0);
    for(std::size_t k = first[v]; k < first[v + 1]; ++k)
    {
      const std::size_t i = bucketed[k];
      keys.insert(keys.end(), soup.polygon(i), soup.polygon(i) + soup.size(i));
      std::sort(keys.begin() + std::ptrdiff_t(key_first.back()), keys.end());
      key_first.push_back(keys.size());
    }
    auto key_less = [&](std::size_t a, std::size_t b) {
      return std::lexicographical_compare(keys.begin() + std::ptrdiff_t(key_first[a]),
                                          keys.begin() + std::ptrdiff_t(key_first[a + 1]),
                                          keys.begin() + std::ptrdiff_t(key_first[b]),
                                          keys.begin() + std::ptrdiff_t(key_first[b + 1]));
    };
    auto key_equal = [&](std::size_t a, std::size_t b) {
      return key_first[a + 1] - key_first[a] == key_first[b + 1] - key_first[b] &&
             std::equal(keys.begin() + std::ptrdiff_t(key_first[a]), keys.begin() + std::ptrdiff_t(key_first[a + 1]),
                        keys.begin() + std::ptrdiff_t(key_first[b]));
    };
    if(count <= 16)
    {
      for(std::size_t a = 0; a < count; ++a)
        for(std::size_t b = a + 1; b < count; ++b)
          if(key_equal(a, b))
            return true;
    }
    else
    {
      order.resize(count);
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::sort(order.begin(), order.end(), key_less);
      for(std::size_t k = 1; k < count; ++k)
        if(key_equal(order[k - 1], order[k]))
          return true;
    }
  }
  return false;
}

// 4. Polygons with the same vertex set as an earlier one.
inline Error_code remove_duplicate_polygons(Polygon_soup& soup, std::vector<std::size_t>& source, bool repair,
                                            std::size_t& removed, const Diagnostic& diagnostic)
{
  const std::size_t n = soup.number_of_polygons();
  removed = 0;
  if(!has_duplicate_polygons(soup))
    return Error_code::SUCCESS;
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

// Whether corners a and b of `corners` share a neighbour vertex.
template <typename Corner>
bool share_a_neighbour(const Corner& a, const Corner& b)
{
  return a.previous == b.previous || a.previous == b.next || a.next == b.previous || a.next == b.next;
}

// 5. Without repair: the first non-manifold edge, inconsistently oriented
// edge, or pinched vertex is refused. Returns SUCCESS and sets `manifold`.
// The edges are visited in the order of their (smaller, larger) vertex ids,
// then the vertices in id order. Both checks read the corners of the soup
// grouped by vertex (a counting sort): the check is linear in the size of
// the soup.
inline Error_code check_manifold(const Polygon_soup& soup, bool& manifold, const Diagnostic& diagnostic)
{
  const std::size_t nv = soup.points.size();
  const std::size_t np = soup.number_of_polygons();
  manifold = true;

  // The corners at each vertex, in polygon order.
  struct Corner
  {
    std::size_t previous, next, polygon;
  };
  std::vector<std::size_t> first(nv + 1, 0);
  for(std::size_t id : soup.ids)
    ++first[id + 1];
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<Corner> corners(soup.ids.size());
  {
    std::vector<std::size_t> cursor(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < np; ++i)
    {
      const std::size_t* p = soup.polygon(i);
      const std::size_t n = soup.size(i);
      for(std::size_t k = 0; k < n; ++k)
        corners[cursor[p[k]]++] = Corner{ p[(k + n - 1) % n], p[(k + 1) % n], i };
    }
  }

  // The sides a-b with a < b of the polygons, for each a: the corners at a
  // give them (a -> next, forward, and previous -> a, backward), sorted by
  // (b, polygon).
  struct Half
  {
    std::size_t b, polygon;
    bool forward;  // the polygon runs a -> b
  };
  std::vector<Half> halves;
  for(std::size_t a = 0; a < nv; ++a)
  {
    halves.clear();
    for(std::size_t c = first[a]; c < first[a + 1]; ++c)
    {
      if(corners[c].next > a)
        halves.push_back(Half{ corners[c].next, corners[c].polygon, true });
      if(corners[c].previous > a)
        halves.push_back(Half{ corners[c].previous, corners[c].polygon, false });
    }
    std::sort(halves.begin(), halves.end(),
              [](const Half& x, const Half& y) { return x.b != y.b ? x.b < y.b : x.polygon < y.polygon; });
    for(std::size_t k = 0; k < halves.size();)
    {
      std::size_t end = k;
      while(end < halves.size() && halves[end].b == halves[k].b)
        ++end;
      const std::size_t count = end - k;
      if(count > 2 || (count == 2 && halves[k].forward == halves[k + 1].forward))
      {
        manifold = false;
        const std::string edge = "the edge between vertices " + std::to_string(a) + " and " + std::to_string(halves[k].b);
        if(count > 2)
          return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, edge + " is shared by " + std::to_string(count) +
                                                                  " faces (" + soup.face_name(halves[k].polygon) + ", " +
                                                                  soup.face_name(halves[k + 1].polygon) + ", " +
                                                                  soup.face_name(halves[k + 2].polygon) +
                                                                  (count > 3 ? ", ..." : "") + ")");
        return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, soup.face_name(halves[k].polygon) + " and " +
                                                                soup.face_name(halves[k + 1].polygon) +
                                                                " are oriented inconsistently across " + edge);
      }
      k = end;
    }
  }

  // Pinched vertices: the corners at a vertex must form one fan, i.e. be
  // connected through the edges they share (the neighbour vertices they
  // share).
  std::vector<std::size_t> parent;
  std::vector<std::pair<std::size_t, std::size_t> > ends;  // (neighbour vertex, corner)
  for(std::size_t v = 0; v < nv; ++v)
  {
    const Corner* const at = corners.data() + first[v];
    const std::size_t count = first[v + 1] - first[v];
    if(count <= 1)
      continue;  // one corner (or none) is one fan (or none)
    parent.resize(count);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&](std::size_t x) {
      while(parent[x] != x)
        x = parent[x] = parent[parent[x]];
      return x;
    };
    if(count <= 16)
    {
      for(std::size_t a = 0; a < count; ++a)
        for(std::size_t b = a + 1; b < count; ++b)
          if(share_a_neighbour(at[a], at[b]))
            parent[find(b)] = find(a);
    }
    else
    {
      ends.clear();
      for(std::size_t c = 0; c < count; ++c)
      {
        ends.emplace_back(at[c].previous, c);
        ends.emplace_back(at[c].next, c);
      }
      std::sort(ends.begin(), ends.end());
      for(std::size_t e = 1; e < ends.size(); ++e)
        if(ends[e].first == ends[e - 1].first)
          parent[find(ends[e].second)] = find(ends[e - 1].second);
    }
    std::size_t fans = 0;
    for(std::size_t c = 0; c < count; ++c)
      fans += (find(c) == c) ? 1 : 0;
    if(fans > 1)
    {
      manifold = false;
      return diagnostic.fail(Error_code::NON_MANIFOLD_MESH, soup.vertex_name(v) + " is pinched: its faces form " +
                                                              std::to_string(fans) + " separate fans");
    }
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
