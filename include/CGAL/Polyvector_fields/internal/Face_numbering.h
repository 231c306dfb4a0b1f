// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_FACE_NUMBERING_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_FACE_NUMBERING_H

#include <cstddef>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include <boost/functional/hash.hpp>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

template <typename Descriptor, typename = void>
struct Has_idx : std::false_type {};

template <typename Descriptor>
struct Has_idx<Descriptor, std::void_t<decltype(std::size_t(std::declval<const Descriptor&>().idx()))> >
  : std::true_type {};

// Numbers descriptors (faces or vertices) 0..n-1 in the order they are added:
// the one numbering of the package (tangent bundle, file formats).
//
// Descriptors that expose a dense `idx()` (Surface_mesh, OpenMesh) are looked
// up in a vector indexed by `idx()`, sized by the largest index seen, so a
// Surface_mesh that holds removed elements is numbered correctly. Other
// descriptors (Polyhedron_3 handles) go through a hash map.
template <typename Descriptor, bool dense = Has_idx<Descriptor>::value>
class Numbering
{
public:
  // Prepares for `n` descriptors of indices below `n` (a hint).
  void reserve(std::size_t n) { m_index.reserve(n); }
  void add(const Descriptor& d)
  {
    const std::size_t k = std::size_t(d.idx());
    if(k == m_index.size())
      m_index.push_back(m_count++);  // the common case: indices in increasing order
    else
    {
      if(k > m_index.size())
        m_index.resize(k + 1, std::size_t(-1));
      m_index[k] = m_count++;
    }
  }
  std::size_t operator()(const Descriptor& d) const { return m_index[std::size_t(d.idx())]; }
  bool contains(const Descriptor& d) const
  {
    const std::size_t k = std::size_t(d.idx());
    return k < m_index.size() && m_index[k] != std::size_t(-1);
  }
  // The number of a descriptor that may be unknown (stale, null): false if it is.
  bool find(const Descriptor& d, std::size_t& number) const
  {
    if(!contains(d))
      return false;
    number = (*this)(d);
    return true;
  }
  std::size_t size() const { return m_count; }

private:
  std::vector<std::size_t> m_index;
  std::size_t m_count = 0;
};

template <typename Descriptor>
class Numbering<Descriptor, false>
{
public:
  void reserve(std::size_t n) { m_index.reserve(n); }
  void add(const Descriptor& d) { m_index.emplace(d, m_index.size()); }
  std::size_t operator()(const Descriptor& d) const { return m_index.at(d); }
  bool contains(const Descriptor& d) const { return m_index.count(d) != 0; }
  bool find(const Descriptor& d, std::size_t& number) const
  {
    const auto it = m_index.find(d);
    if(it == m_index.end())
      return false;
    number = it->second;
    return true;
  }
  std::size_t size() const { return m_index.size(); }

private:
  std::unordered_map<Descriptor, std::size_t, boost::hash<Descriptor> > m_index;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_FACE_NUMBERING_H
