// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_MESH_INDICES_H
#define CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_MESH_INDICES_H

// Face and vertex ids of the file formats.
//
// Ids are 0-based, in the order of faces(tm) / vertices(tm). The writers look
// up descriptors given by the caller, which may be stale or null, so the
// lookup here reports "not found" instead of failing.

#include <CGAL/Polyvector_fields/internal/Face_numbering.h>
#include <CGAL/Polyvector_fields/internal/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <unordered_map>
#include <vector>

#include <boost/functional/hash.hpp>


namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

// Maps descriptors to 0..n-1 in the order they are added; unknown descriptors
// are reported by `find`, never looked up out of bounds.
template <typename Descriptor, bool dense = Polyvector_fields::internal::Has_idx<Descriptor>::value>
class Descriptor_index
{
public:
  void add(const Descriptor& d)
  {
    const std::size_t k = std::size_t(d.idx());
    if(k >= m_index.size())
      m_index.resize(k + 1, not_found);
    m_index[k] = m_count++;
  }

  bool find(const Descriptor& d, std::size_t& id) const
  {
    const std::size_t k = std::size_t(d.idx());
    if(k >= m_index.size() || m_index[k] == not_found)
      return false;
    id = m_index[k];
    return true;
  }

private:
  static constexpr std::size_t not_found = std::size_t(-1);
  std::vector<std::size_t> m_index;
  std::size_t m_count = 0;
};

template <typename Descriptor>
class Descriptor_index<Descriptor, false>
{
public:
  void add(const Descriptor& d) { m_index.emplace(d, m_index.size()); }

  bool find(const Descriptor& d, std::size_t& id) const
  {
    const auto it = m_index.find(d);
    if(it == m_index.end())
      return false;
    id = it->second;
    return true;
  }

private:
  std::unordered_map<Descriptor, std::size_t, boost::hash<Descriptor> > m_index;
};

// The faces of `tm` in faces(tm) order: position = file id.
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
face_list(const TriangleMesh& tm)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> list;
  for(auto f : faces(tm))  // unqualified: found by ADL when the mesh type is known
    list.push_back(f);
  return list;
}

// The vertices of `tm` in vertices(tm) order: position = file id.
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
vertex_list(const TriangleMesh& tm)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> list;
  for(auto v : vertices(tm))  // unqualified: found by ADL when the mesh type is known
    list.push_back(v);
  return list;
}

template <typename Descriptor>
Descriptor_index<Descriptor> make_index(const std::vector<Descriptor>& list)
{
  Descriptor_index<Descriptor> index;
  for(const Descriptor& d : list)
    index.add(d);
  return index;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_MESH_INDICES_H
