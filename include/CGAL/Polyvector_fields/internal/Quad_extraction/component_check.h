// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// The check of the quads of each connected component of the surface before they are
// returned: one polygon mesh, in one piece, and on a closed component, closed with the
// component's Euler characteristic.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_COMPONENT_CHECK_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_COMPONENT_CHECK_H

#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace qex {

// What is wrong with the polygons of one component (empty: nothing).
struct Component_defect
{
  std::size_t component = npos;
  std::size_t face = npos;  // a face of the component
  std::string why;
};

// The components of M (`component[t]`, `components` of them) whose polygons (those not
// `skip`ped; `polygon_face[f]` a surface face under polygon f, or npos) are not one
// quad mesh of the component: a polygon passes twice through a point, the polygons do
// not form a polygon mesh, they fall into several pieces, or, on a closed component,
// they have a border or another Euler characteristic than the component. A polygon
// whose face is npos takes the component of the polygons it shares a point with, and
// `polygon_face` is set to a face of that component.
inline std::vector<Component_defect> defective_components(const Chart_mesh& M, const std::vector<std::size_t>& component,
                                                          std::size_t components,
                                                          const std::vector<std::vector<std::size_t> >& polygons,
                                                          std::vector<std::size_t>& polygon_face,
                                                          const std::vector<char>& skip)
{
  // pieces: the polygons joined through shared points
  std::size_t points = 0;
  for(std::size_t f = 0; f < polygons.size(); ++f)
    if(!skip[f])
      for(std::size_t v : polygons[f])
        points = (std::max)(points, v + 1);
  std::vector<std::size_t> parent(points);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(std::size_t f = 0; f < polygons.size(); ++f)
    if(!skip[f])
      for(std::size_t k = 1; k < polygons[f].size(); ++k)
        parent[root(polygons[f][k])] = root(polygons[f][0]);
  // the component of each piece, from the faces under its polygons
  // (by the root point of the piece; sorted, each component once)
  std::vector<std::vector<std::size_t> > piece_components(points);
  for(std::size_t f = 0; f < polygons.size(); ++f)
    if(!skip[f] && !polygons[f].empty() && polygon_face[f] != npos)
    {
      std::vector<std::size_t>& ks = piece_components[root(polygons[f][0])];
      const std::size_t k = component[polygon_face[f]];
      if(ks.empty() || ks.back() != k)
        ks.push_back(k);
    }
  for(std::vector<std::size_t>& ks : piece_components)
    if(ks.size() > 1)
    {
      std::sort(ks.begin(), ks.end());
      ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
    }
  std::vector<std::size_t> first_face(components, npos);
  for(std::size_t t = 0; t < M.F; ++t)
    if(first_face[component[t]] == npos)
      first_face[component[t]] = t;
  std::vector<std::string> why(components);
  auto flag = [&](std::size_t k, const std::string& reason) {
    if(why[k].empty())
      why[k] = reason;
  };
  std::vector<std::vector<std::size_t> > members(components);
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    if(skip[f] || polygons[f].empty())
      continue;
    const std::vector<std::size_t>& ks = piece_components[root(polygons[f][0])];
    if(ks.empty())
      continue;  // a piece on no known face: it cannot be told apart, the mesh check below sees it
    if(ks.size() > 1)
      for(std::size_t k : ks)
        flag(k, "its quads share points with those of another component");
    const std::size_t k = ks.front();
    if(polygon_face[f] == npos)
      polygon_face[f] = first_face[k];
    members[k].push_back(f);
  }
  // the Euler characteristic and the border of each component of the surface
  std::vector<long long> chi(components, 0);
  std::vector<char> closed(components, 1);
  {
    std::vector<std::pair<std::size_t, std::size_t> > seen;  // (vertex, component): a pinch vertex is in several
    seen.reserve(3 * M.F);
    for(std::size_t t = 0; t < M.F; ++t)
    {
      const std::size_t k = component[t];
      chi[k] += 1;
      for(std::size_t j = 0; j < 3; ++j)
      {
        const std::size_t e = 3 * t + j;
        if(M.opp[e] == npos)
        {
          closed[k] = 0;
          chi[k] -= 2;  // a border edge counts once; halved below with the interior ones
        }
        else
          chi[k] -= 1;
        seen.emplace_back(M.vertex[e], k);
      }
      chi[k] += 1;
    }
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    for(const auto& vk : seen)
      chi[vk.second] += 2;
    for(long long& c : chi)
      c /= 2;  // 2 (V - E + F)
  }
  // the local number of each point in the component being checked (npos: none yet)
  std::vector<std::size_t> local(points, npos);
  for(std::size_t k = 0; k < components; ++k)
  {
    if(members[k].empty() || !why[k].empty())
      continue;
    // the component's polygons, their points numbered from 0
    std::vector<std::vector<std::size_t> > own;
    std::vector<std::size_t> numbered;  // the points, in the order of their local numbers
    std::vector<std::size_t> roots;
    for(std::size_t f : members[k])
    {
      const std::vector<std::size_t>& p = polygons[f];
      std::vector<std::size_t> distinct(p);
      std::sort(distinct.begin(), distinct.end());
      if(std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end())
        flag(k, "one of its cells passes twice through a point");
      own.emplace_back();
      for(std::size_t v : p)
      {
        if(local[v] == npos)
        {
          local[v] = numbered.size();
          numbered.push_back(v);
        }
        own.back().push_back(local[v]);
      }
      roots.push_back(root(p[0]));
    }
    for(std::size_t v : numbered)
      local[v] = npos;
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    if(!why[k].empty())
      continue;
    if(roots.size() > 1)
    {
      flag(k, "its quads fall into " + std::to_string(roots.size()) + " pieces");
      continue;
    }
    if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(own))
    {
      flag(k, "its cells do not form a polygon mesh");
      continue;
    }
    if(!closed[k])
      continue;
    // the edges of the polygons, each once per polygon side along it
    std::vector<std::pair<std::size_t, std::size_t> > sides;
    for(const std::vector<std::size_t>& p : own)
      for(std::size_t j = 0; j < p.size(); ++j)
      {
        const std::size_t a = p[j], b = p[(j + 1) % p.size()];
        sides.emplace_back((std::min)(a, b), (std::max)(a, b));
      }
    std::sort(sides.begin(), sides.end());
    std::size_t edges = 0, border_edges = 0;
    for(std::size_t i = 0; i < sides.size();)
    {
      std::size_t j = i;
      while(j < sides.size() && sides[j] == sides[i])
        ++j;
      ++edges;
      border_edges += j - i == 1 ? 1 : 0;
      i = j;
    }
    // (every point is on a polygon: the points are those numbered)
    const long long chi_quads = (long long)(numbered.size()) - (long long)(edges) + (long long)(own.size());
    if(border_edges > 0)
      flag(k, "the component is closed, and its quads leave a hole (" + std::to_string(border_edges) + " border edges)");
    else if(chi_quads != chi[k])
      flag(k, "its quads have Euler characteristic " + std::to_string(chi_quads) + ", the component " + std::to_string(chi[k]));
  }
  std::vector<Component_defect> defects;
  for(std::size_t k = 0; k < components; ++k)
    if(!why[k].empty())
      defects.push_back({ k, first_face[k], why[k] });
  return defects;
}

} // namespace qex
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_QUAD_EXTRACTION_COMPONENT_CHECK_H
