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

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace IO {
namespace internal {

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
Polyvector_fields::internal::Numbering<Descriptor> make_index(const std::vector<Descriptor>& list)
{
  Polyvector_fields::internal::Numbering<Descriptor> index;
  for(const Descriptor& d : list)
    index.add(d);
  return index;
}

} // namespace internal
} // namespace IO
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_IO_INTERNAL_MESH_INDICES_H
