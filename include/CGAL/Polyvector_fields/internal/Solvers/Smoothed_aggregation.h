// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// Smoothed-aggregation multigrid (Vanek, Mandel, Brezina 1996) for complex
// Hermitian positive definite "connection Laplacians", used as the
// preconditioner of conjugate gradient.
//
// The near-null space of a connection Laplacian is not the constant vector
// but a locally parallel field: the energy term |a_i x_i - a_j x_j|^2 (|a| = 1)
// vanishes when x_j = a_i conj(a_j) x_i, and the matrix entry is
// A_ij = -conj(a_i) a_j, so the local parallel transport is read off the
// matrix itself: x_j = -conj(A_ij) / |A_ij| x_i. (For any Hermitian matrix this
// is the phase that makes the term 2 Re(conj(x_i) A_ij x_j) = -2 |A_ij| |x_i|^2
// smallest.) Each aggregate carries one such field, propagated from its root
// along a spanning tree of the aggregate: the tentative prolongator has one
// column per aggregate, holding these unit-modulus phases scaled by
// 1/sqrt(|aggregate|) (orthonormal columns).
//
// Split between structure and values:
// - Structure (computed once per sparsity pattern, shared by all the blocks of
//   a system and reused by every numeric refactorization): the aggregates of
//   every level, their spanning trees, the patterns of the prolongators and
//   of the Galerkin operators, and the maps between them. The aggregation is
//   purely structural: on the finest level it runs on the graph of A (every
//   off-diagonal entry of these matrices has modulus 1: all connections are
//   equally strong), on coarser levels on the quotient graph of the level
//   below (aggregates adjacent when an edge joins them). So the aggregates do
//   not depend on the values: one analysis serves all degrees and every lambda.
// - Values (factorize): phases, the damping omega = 4 / (3 rho(D^-1 A)), the
//   smoothed prolongator P = (I - omega D^-1 A) P_tent row by row (one pass over
//   the entries of A, each scattered to a precomputed position of P), the
//   Galerkin operator P^H A P (one fused pass: for each coarse row a, the fine
//   rows i of column a of P, their entries A_ij, the entries P(j, b); a dense
//   accumulator, no intermediate product), the dense Cholesky factor of the
//   coarsest operator.
//
// V-cycle: one forward Gauss-Seidel sweep before the coarse correction, one
// backward sweep after it: the cycle is a Hermitian positive definite
// preconditioner (the post-smoother is the adjoint of the pre-smoother, the
// coarse correction is exact Galerkin, the coarsest level is solved exactly).
//
// Everything is sequential inside one hierarchy and deterministic: two runs on
// the same matrix give bit-identical results whatever the thread.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_SMOOTHED_AGGREGATION_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_SMOOTHED_AGGREGATION_H

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <CGAL/Polyvector_fields/internal/parallel.h>


#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {
namespace amg {

typedef std::complex<double> Complex;
// The prolongators are stored in single precision: a preconditioner needs no
// more, and the cycle reads them twice per iteration. The Galerkin operators
// are computed from the rounded values, so the cycle stays exactly the
// symmetric V-cycle of the stored prolongators.
typedef std::complex<float> Prolongator_value;

struct Parameters
{
  // CG stops when ||b - A x||_2 <= tolerance * ||b||_2 (true residual).
  double tolerance = 1e-10;
  int max_iterations = 200;
  // Aggregate radius on the finest level and on the coarser ones.
  int fine_radius = 2;
  int coarse_radius = 1;
  // A level with at most this many unknowns is solved by a dense Cholesky.
  int coarsest_size = 500;
  int max_levels = 12;
  // Gauss-Seidel sweeps before and after the coarse correction.
  int sweeps = 1;
  // Power iterations for rho(D^-1 A) on the coarse levels; 0: the Gershgorin
  // bound max_i sum_j |A_ij| / A_ii on every level (measured at 640k faces:
  // one more CG iteration than 10 power iterations, a cheaper setup).
  int power_iterations = 0;
  // What a numeric refactorization (factorize after the first) recomputes:
  //   0: every value of the hierarchy (phases, omega, P, Galerkin, coarse factor);
  //   1: the Galerkin operators and the coarse factor, keeping the prolongators;
  //   2: nothing but the finest matrix (the old coarse levels precondition the
  //      new one) while CG needs at most max(2, 30%) more iterations than right
  //      after the last Galerkin setup; then as 1.
  int reuse = 2;
  // Renumber the finest level along the aggregates (locality).
  bool reorder = true;
  // Roots of aggregates tried in a pseudo-random order (else breadth-first).
  bool random_scan = false;
  // CG starts from the previous solution of this factorization (when its
  // residual is smaller than ||b||).
  bool warm_start = true;
};

// Compressed rows with sorted column indices.
struct Pattern
{
  int rows = 0, cols = 0;
  std::vector<int> ptr, idx;
  std::size_t nnz() const { return idx.size(); }
  std::size_t bytes() const { return (ptr.size() + idx.size()) * sizeof(int); }
};

// The structure of one level (shared between factorizations).
struct Level_structure
{
  Pattern A;                  // this level's operator (square)
  std::vector<int> diagonal;  // position of A(i, i)
  bool coarsest = false;
  // Below: only when !coarsest.
  int coarse_size = 0;
  std::vector<int> aggregate;    // per node
  std::vector<float> scale;      // 1 / sqrt(|aggregate(i)|)
  std::vector<int> order;        // nodes, each after its tree parent
  std::vector<int> parent_entry; // per node: position in A of (parent, node), -1 for a root
  std::vector<int> parent;       // per node: tree parent, -1 for a root
  Pattern P;                     // fine x coarse
  std::vector<int> a_to_p;       // per entry (i, j) of A: position of (i, aggregate(j)) in P
  Pattern PT;                    // coarse x fine (transpose pattern of P)
  std::vector<int> pt_to_p;      // per entry of PT: position in P

  std::size_t bytes() const
  {
    return A.bytes() + P.bytes() + PT.bytes() +
           (diagonal.size() + aggregate.size() + order.size() + parent_entry.size() + parent.size() + a_to_p.size() +
            pt_to_p.size()) * sizeof(int) + scale.size() * sizeof(float);
  }
};

struct Structure
{
  std::vector<Level_structure> levels;
  // Finest level renumbered (Parameters::reorder): permutation[new] = old
  // unknown, input_map[k] = position in the input matrix of entry k.
  std::vector<int> permutation, input_map;
  std::uint64_t input_fingerprint = 0;
  double t_aggregate = 0, t_permute = 0, t_prolongator = 0, t_quotient = 0;
  bool computed = false;
  double seconds = 0;
  std::size_t bytes() const
  {
    std::size_t b = 0;
    for(const auto& l : levels)
      b += l.bytes();
    return b + (permutation.size() + input_map.size()) * sizeof(int);
  }
};

// Independent chunks of rows, run in parallel (for_each_index) when TBB is
// linked: each row is computed by the same operations whatever the chunk and
// the thread, so the result is deterministic.
inline int chunk_count(int rows)
{
#ifdef CGAL_LINKED_WITH_TBB
  return rows > 20000 ? 16 : 1;
#else
  (void)rows;
  return 1;
#endif
}

// ---------------------------------------------------------------------------
// Structure
// ---------------------------------------------------------------------------

// An undirected graph in compressed rows (no self loops).
struct Graph
{
  std::vector<int> ptr, adj;
  int size() const { return int(ptr.size()) - 1; }
};

inline Graph graph_of(const Pattern& A)
{
  Graph g;
  g.ptr.assign(std::size_t(A.rows) + 1, 0);
  g.adj.reserve(A.nnz());
  for(int i = 0; i < A.rows; ++i)
  {
    for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      if(A.idx[k] != i)
        g.adj.push_back(A.idx[k]);
    g.ptr[std::size_t(i) + 1] = int(g.adj.size());
  }
  return g;
}

// Aggregation of radius 1 or 2 (Vanek et al. phases 1 and 2):
// 1. a node whose neighbours are all free is a root: its aggregate is itself,
//    its neighbours and (radius 2) the free neighbours of those;
// 2. every node still free has an aggregated neighbour (or it would have been
//    a root) and joins the aggregate of the first one, of the smallest size.
// Also records a spanning tree of each aggregate (parents) and an order in
// which every node comes after its parent.
inline int aggregate_graph(const Graph& g, int radius, std::vector<int>& aggregate, std::vector<int>& parent,
                           std::vector<int>& order, const std::vector<int>* scan = nullptr)
{
  const int n = g.size();
  aggregate.assign(std::size_t(n), -1);
  parent.assign(std::size_t(n), -1);
  order.clear();
  order.reserve(std::size_t(n));
  std::vector<int> sizes;
  int count = 0;
  for(int s = 0; s < n; ++s)
  {
    const int i = scan ? (*scan)[std::size_t(s)] : s;
    if(aggregate[i] >= 0)
      continue;
    bool free = true;
    for(int k = g.ptr[i]; k < g.ptr[i + 1] && free; ++k)
      free = aggregate[g.adj[k]] < 0;
    if(!free)
      continue;
    const int a = count++;
    aggregate[i] = a;
    order.push_back(i);
    int size = 1;
    const std::size_t first = order.size();
    for(int k = g.ptr[i]; k < g.ptr[i + 1]; ++k)
    {
      const int j = g.adj[k];
      if(aggregate[j] < 0)
      {
        aggregate[j] = a;
        parent[j] = i;
        order.push_back(j);
        ++size;
      }
    }
    if(radius >= 2)
    {
      const std::size_t last = order.size();
      for(std::size_t m = first; m < last; ++m)
      {
        const int j = order[m];
        for(int k = g.ptr[j]; k < g.ptr[j + 1]; ++k)
        {
          const int l = g.adj[k];
          if(aggregate[l] < 0)
          {
            aggregate[l] = a;
            parent[l] = j;
            order.push_back(l);
            ++size;
          }
        }
      }
    }
    sizes.push_back(size);
  }
  // Phase 2: attach the rest to the smallest neighbouring aggregate of phase 1.
  std::vector<char> phase1(static_cast<std::size_t>(n));
  for(int i = 0; i < n; ++i)
    phase1[i] = aggregate[i] >= 0;
  for(int i = 0; i < n; ++i)
  {
    if(phase1[i])
      continue;
    int best = -1, best_size = 0;
    for(int k = g.ptr[i]; k < g.ptr[i + 1]; ++k)
    {
      const int j = g.adj[k];
      if(phase1[j] && (best < 0 || sizes[std::size_t(aggregate[j])] < best_size))
      {
        best = j;
        best_size = sizes[std::size_t(aggregate[j])];
      }
    }
    if(best < 0)
    {
      // Cannot happen (such a node would have been a root): an aggregate of its own.
      aggregate[i] = count++;
      sizes.push_back(1);
      order.push_back(i);
      continue;
    }
    aggregate[i] = aggregate[best];
    parent[i] = best;
    ++sizes[std::size_t(aggregate[best])];
    order.push_back(i);
  }
  return count;
}

// The quotient graph of g by the aggregates.
inline Graph quotient_graph(const Graph& g, const std::vector<int>& aggregate, int count)
{
  // members of each aggregate
  std::vector<int> start(std::size_t(count) + 1, 0), members(aggregate.size());
  for(int a : aggregate)
    ++start[std::size_t(a) + 1];
  for(int a = 0; a < count; ++a)
    start[std::size_t(a) + 1] += start[std::size_t(a)];
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for(int i = 0; i < int(aggregate.size()); ++i)
      members[std::size_t(fill[std::size_t(aggregate[i])]++)] = i;
  }
  Graph q;
  q.ptr.assign(std::size_t(count) + 1, 0);
  std::vector<int> mark(std::size_t(count), -1);
  for(int a = 0; a < count; ++a)
  {
    mark[a] = a;
    const std::size_t row_start = q.adj.size();
    for(int m = start[a]; m < start[a + 1]; ++m)
    {
      const int i = members[m];
      for(int k = g.ptr[i]; k < g.ptr[i + 1]; ++k)
      {
        const int b = aggregate[g.adj[k]];
        if(mark[b] != a)
        {
          mark[b] = a;
          q.adj.push_back(b);
        }
      }
    }
    std::sort(q.adj.begin() + std::ptrdiff_t(row_start), q.adj.end());
    q.ptr[std::size_t(a) + 1] = int(q.adj.size());
  }
  return q;
}

inline int find_entry(const Pattern& A, int row, int col)
{
  const int* begin = A.idx.data() + A.ptr[row];
  const int* end = A.idx.data() + A.ptr[row + 1];
  const int* it = std::lower_bound(begin, end, col);
  return (it != end && *it == col) ? int(it - A.idx.data()) : -1;
}

inline void find_diagonal(Level_structure& L)
{
  L.diagonal.assign(std::size_t(L.A.rows), -1);
  for(int i = 0; i < L.A.rows; ++i)
    L.diagonal[i] = find_entry(L.A, i, i);
}

// The pattern of P (rows: aggregates of i and of its neighbours in A), the map
// from entries of A to entries of P, the transpose, and the pattern of P^H A P.
inline void prolongator_structure(Level_structure& L, Pattern& coarse)
{
  const Pattern& A = L.A;
  const int n = A.rows, nc = L.coarse_size;
  Pattern& P = L.P;
  P.rows = n;
  P.cols = nc;
  P.ptr.assign(std::size_t(n) + 1, 0);
  P.idx.clear();
  P.idx.reserve(std::size_t(n) * 3);
  L.a_to_p.assign(A.nnz(), -1);
  std::vector<int> row;
  for(int i = 0; i < n; ++i)
  {
    row.clear();
    for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      row.push_back(L.aggregate[A.idx[k]]);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    const int base = int(P.idx.size());
    P.idx.insert(P.idx.end(), row.begin(), row.end());
    P.ptr[std::size_t(i) + 1] = int(P.idx.size());
    for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      L.a_to_p[k] = base + int(std::lower_bound(row.begin(), row.end(), L.aggregate[A.idx[k]]) - row.begin());
  }
  // Transpose.
  Pattern& PT = L.PT;
  PT.rows = nc;
  PT.cols = n;
  PT.ptr.assign(std::size_t(nc) + 1, 0);
  for(int c : P.idx)
    ++PT.ptr[std::size_t(c) + 1];
  for(int a = 0; a < nc; ++a)
    PT.ptr[std::size_t(a) + 1] += PT.ptr[std::size_t(a)];
  PT.idx.resize(P.nnz());
  L.pt_to_p.resize(P.nnz());
  {
    std::vector<int> fill(PT.ptr.begin(), PT.ptr.end() - 1);
    for(int i = 0; i < n; ++i)
      for(int k = P.ptr[i]; k < P.ptr[i + 1]; ++k)
      {
        const int slot = fill[std::size_t(P.idx[k])]++;
        PT.idx[std::size_t(slot)] = i;
        L.pt_to_p[std::size_t(slot)] = k;
      }
  }
  // Pattern of P^H A P, by chunks of rows (in parallel with TBB; the result
  // does not depend on the chunks).
  coarse.rows = coarse.cols = nc;
  coarse.ptr.assign(std::size_t(nc) + 1, 0);
  const int chunks = chunk_count(nc);
  std::vector<std::vector<int> > chunk_idx(static_cast<std::size_t>(chunks));
  for_each_index(chunks > 1, std::size_t(chunks), [&](std::size_t chunk) {
    const int c = int(chunk);
    const int first = int((long long)nc * c / chunks), last = int((long long)nc * (c + 1) / chunks);
    std::vector<int> mark(std::size_t(nc), -1);
    std::vector<int>& idx = chunk_idx[std::size_t(c)];
    for(int a = first; a < last; ++a)
    {
      const std::size_t row_start = idx.size();
      for(int m = PT.ptr[a]; m < PT.ptr[a + 1]; ++m)
      {
        const int i = PT.idx[m];
        for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
        {
          const int j = A.idx[k];
          for(int l = P.ptr[j]; l < P.ptr[j + 1]; ++l)
          {
            const int b = P.idx[l];
            if(mark[b] != a)
            {
              mark[b] = a;
              idx.push_back(b);
            }
          }
        }
      }
      std::sort(idx.begin() + std::ptrdiff_t(row_start), idx.end());
      coarse.ptr[std::size_t(a) + 1] = int(idx.size() - row_start);
    }
  });
  for(int a = 0; a < nc; ++a)
    coarse.ptr[std::size_t(a) + 1] += coarse.ptr[std::size_t(a)];
  coarse.idx.clear();
  coarse.idx.reserve(std::size_t(coarse.ptr[std::size_t(nc)]));
  for(auto& v : chunk_idx)
  {
    coarse.idx.insert(coarse.idx.end(), v.begin(), v.end());
    std::vector<int>().swap(v);
  }
}

// Breadth-first order of the nodes (component after component): the
// aggregates are grown along it, so that they and their numbering are local.
inline std::vector<int> breadth_first_order(const Graph& g)
{
  const int n = g.size();
  std::vector<int> order;
  order.reserve(std::size_t(n));
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for(int s = 0; s < n; ++s)
  {
    if(seen[s])
      continue;
    seen[s] = 1;
    std::size_t head = order.size();
    order.push_back(s);
    while(head < order.size())
    {
      const int i = order[head++];
      for(int k = g.ptr[i]; k < g.ptr[i + 1]; ++k)
        if(!seen[g.adj[k]])
        {
          seen[g.adj[k]] = 1;
          order.push_back(g.adj[k]);
        }
    }
  }
  return order;
}

// B = A(perm, perm) (perm: new -> old), with sorted rows; map[k'] = position in
// A of the entry at position k' of B.
inline void permute_pattern(const Pattern& A, const std::vector<int>& perm, const std::vector<int>& inverse, Pattern& B,
                            std::vector<int>& map)
{
  const int n = A.rows;
  B.rows = B.cols = n;
  B.ptr.assign(std::size_t(n) + 1, 0);
  B.idx.resize(A.nnz());
  map.resize(A.nnz());
  std::vector<std::pair<int, int> > row;
  for(int i = 0; i < n; ++i)
  {
    const int old = perm[i];
    row.clear();
    for(int k = A.ptr[old]; k < A.ptr[old + 1]; ++k)
      row.emplace_back(inverse[A.idx[k]], k);
    std::sort(row.begin(), row.end());
    const int base = B.ptr[i];
    for(std::size_t m = 0; m < row.size(); ++m)
    {
      B.idx[std::size_t(base) + m] = row[m].first;
      map[std::size_t(base) + m] = row[m].second;
    }
    B.ptr[std::size_t(i) + 1] = base + int(row.size());
  }
}

// The whole hierarchy's structure from the finest pattern.
inline void build_structure(Pattern fine, const Parameters& prm, Structure& S)
{
  Timer timer;
  S.levels.clear();
  S.levels.emplace_back();
  S.levels.back().A = std::move(fine);
  Graph g = graph_of(S.levels.back().A);
  for(int l = 0;; ++l)
  {
    Level_structure& L = S.levels[std::size_t(l)];
    find_diagonal(L);
    if(L.A.rows <= prm.coarsest_size || l + 1 >= prm.max_levels)
    {
      L.coarsest = true;
      break;
    }
    const int radius = (l == 0) ? prm.fine_radius : prm.coarse_radius;
    const int n = L.A.rows;
    // Roots are tried in a pseudo-random order (fixed seed) or in breadth-first order.
    std::vector<int> scan;
    if(prm.random_scan)
    {
      scan.resize(std::size_t(n));
      for(int i = 0; i < n; ++i)
        scan[i] = i;
      std::uint64_t h = 0x9E3779B97F4A7C15ull + std::uint64_t(l);
      for(int i = n - 1; i > 0; --i)
      {
        h = h * 6364136223846793005ull + 1442695040888963407ull;
        std::swap(scan[i], scan[int((h >> 33) % std::uint64_t(i + 1))]);
      }
    }
    else
      scan = breadth_first_order(g);
    Timer ta;
    L.coarse_size = aggregate_graph(g, radius, L.aggregate, L.parent, L.order, &scan);
    S.t_aggregate += ta.elapsed();
    {
      // Aggregates numbered in breadth-first order: coarse levels stay local.
      const std::vector<int> bfs = prm.random_scan ? breadth_first_order(g) : scan;
      std::vector<int> label(std::size_t(L.coarse_size), -1);
      int next = 0;
      for(int i : bfs)
        if(label[std::size_t(L.aggregate[i])] < 0)
          label[std::size_t(L.aggregate[i])] = next++;
      for(int& a : L.aggregate)
        a = label[std::size_t(a)];
    }
    Timer tp;
    if(l == 0 && prm.reorder)
    {
      // Number the finest level aggregate by aggregate (members contiguous).
      std::vector<int> start(std::size_t(L.coarse_size) + 1, 0);
      for(int a : L.aggregate)
        ++start[std::size_t(a) + 1];
      for(int a = 0; a < L.coarse_size; ++a)
        start[std::size_t(a) + 1] += start[std::size_t(a)];
      std::vector<int> inverse(static_cast<std::size_t>(n));
      S.permutation.resize(std::size_t(n));
      for(int i : L.order)  // each aggregate's members in tree order
      {
        const int position = start[std::size_t(L.aggregate[i])]++;
        S.permutation[std::size_t(position)] = i;
        inverse[std::size_t(i)] = position;
      }
      Pattern B;
      permute_pattern(L.A, S.permutation, inverse, B, S.input_map);
      L.A = std::move(B);
      find_diagonal(L);
      g = graph_of(L.A);
      std::vector<int> aggregate(static_cast<std::size_t>(n)), parent(static_cast<std::size_t>(n));
      for(int i = 0; i < n; ++i)
      {
        const int old = S.permutation[i];
        aggregate[i] = L.aggregate[old];
        parent[i] = L.parent[old] < 0 ? -1 : inverse[L.parent[old]];
      }
      for(int& i : L.order)
        i = inverse[i];
      L.aggregate.swap(aggregate);
      L.parent.swap(parent);
    }
    S.t_permute += tp.elapsed();
    if(L.coarse_size >= L.A.rows)  // no coarsening (e.g. a diagonal matrix)
    {
      L.coarsest = true;
      L.aggregate.clear();
      L.parent.clear();
      L.order.clear();
      break;
    }
    std::vector<int> sizes(std::size_t(L.coarse_size), 0);
    for(int a : L.aggregate)
      ++sizes[std::size_t(a)];
    L.scale.resize(L.aggregate.size());
    for(std::size_t i = 0; i < L.aggregate.size(); ++i)
      L.scale[i] = float(1.0 / std::sqrt(double(sizes[std::size_t(L.aggregate[i])])));
    L.parent_entry.assign(L.aggregate.size(), -1);
    for(int i = 0; i < L.A.rows; ++i)
      if(L.parent[i] >= 0)
        L.parent_entry[i] = find_entry(L.A, L.parent[i], i);
    Pattern coarse;
    Timer tq;
    prolongator_structure(L, coarse);
    S.t_prolongator += tq.elapsed();
    Timer tg;
    g = quotient_graph(g, L.aggregate, L.coarse_size);
    S.t_quotient += tg.elapsed();
    S.levels.emplace_back();
    S.levels.back().A = std::move(coarse);
  }
  S.computed = true;
  S.seconds = timer.elapsed();
}

// ---------------------------------------------------------------------------
// Values
// ---------------------------------------------------------------------------

struct Level_values
{
  std::vector<Complex> a;          // A, on the pattern of the structure
  std::vector<double> inverse_diagonal;
  std::vector<Complex> phase;      // tentative prolongator values (per node), while P is built
  std::vector<Prolongator_value> p;  // P values, rounded to single precision
  double omega = 0;
  std::vector<Complex> x, b;       // V-cycle work vectors of the coarse levels
  std::vector<Complex> r;          // residual (all levels but the coarsest)
  Eigen::LLT<Eigen::MatrixXcd> dense;  // coarsest level
  std::size_t bytes() const
  {
    return (a.size() + phase.size() + x.size() + b.size() + r.size()) * sizeof(Complex) +
           p.size() * sizeof(Prolongator_value) +
           inverse_diagonal.size() * sizeof(double) + std::size_t(dense.matrixLLT().size()) * sizeof(Complex);
  }
};

struct Setup_times
{
  double phases = 0, omega = 0, prolongator = 0, galerkin = 0, coarsest = 0, total = 0;
};

// Complex arithmetic written out: std::complex's operator* checks for NaN
// results (Annex G) unless compiled with -ffast-math, which a header cannot ask.
inline void add_product(double& re, double& im, const Complex& a, const Complex& x)
{
  re += a.real() * x.real() - a.imag() * x.imag();
  im += a.real() * x.imag() + a.imag() * x.real();
}
// re, im += conj(a) x
inline void add_conj_product(double& re, double& im, const Complex& a, const Complex& x)
{
  re += a.real() * x.real() + a.imag() * x.imag();
  im += a.real() * x.imag() - a.imag() * x.real();
}
inline Complex product(const Complex& a, const Complex& x)
{
  return Complex(a.real() * x.real() - a.imag() * x.imag(), a.real() * x.imag() + a.imag() * x.real());
}

// y = A x for a level; returns Re(x^H y) when `dot`.
inline double level_multiply(const Pattern& A, const Complex* a, const Complex* x, Complex* y)
{
  double dot = 0;
  for(int i = 0; i < A.rows; ++i)
  {
    double re = 0, im = 0;
    for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      add_product(re, im, a[k], x[A.idx[k]]);
    y[i] = Complex(re, im);
    dot += x[i].real() * re + x[i].imag() * im;
  }
  return dot;
}

class Hierarchy
{
public:
  const Structure* structure = nullptr;
  std::vector<Level_values> levels;
  Setup_times times;
  int sweeps = 1;

  std::size_t bytes() const
  {
    std::size_t b = 0;
    for(const auto& l : levels)
      b += l.bytes();
    return b;
  }

  // Level 0's values must already be in levels[0].a. Computes the rest
  // (keep_prolongators: the prolongators' values are kept, only the Galerkin
  // operators and the coarsest factor are recomputed).
  bool setup(const Parameters& prm, bool keep_prolongators)
  {
    Timer total;
    const Structure& S = *structure;
    levels.resize(S.levels.size());
    times = Setup_times();
    for(std::size_t l = 0; l < S.levels.size(); ++l)
    {
      const Level_structure& L = S.levels[l];
      Level_values& V = levels[l];
      if(!diagonal(L, V))
        return false;
      if(l > 0)
      {
        V.x.assign(std::size_t(L.A.rows), Complex(0));
        V.b.assign(std::size_t(L.A.rows), Complex(0));
      }
      if(!L.coarsest && l > 0)  // the finest level's residual is the caller's work vector
        V.r.assign(std::size_t(L.A.rows), Complex(0));
      if(L.coarsest)
      {
        Timer t;
        const int n = L.A.rows;
        Eigen::MatrixXcd D = Eigen::MatrixXcd::Zero(n, n);
        for(int i = 0; i < n; ++i)
          for(int k = L.A.ptr[i]; k < L.A.ptr[i + 1]; ++k)
            D(i, L.A.idx[k]) = V.a[k];
        V.dense.compute(D);
        times.coarsest += t.elapsed();
        if(V.dense.info() != Eigen::Success)
          return false;
        break;
      }
      if(!keep_prolongators || V.p.size() != L.P.nnz())
      {
        Timer t;
        phases(L, V);
        times.phases += t.elapsed();
        Timer t2;
        const double rho = (l == 0 || prm.power_iterations <= 0) ? gershgorin(L, V) : spectral_radius(L, V, prm.power_iterations);
        V.omega = 4.0 / (3.0 * rho);
        times.omega += t2.elapsed();
        Timer t3;
        smoothed_prolongator(L, V);
        std::vector<Complex>().swap(V.phase);  // only needed to build P
        times.prolongator += t3.elapsed();
      }
      Timer t4;
      galerkin(L, V, S.levels[l + 1], levels[l + 1]);
      times.galerkin += t4.elapsed();
    }
    times.total = total.elapsed();
    return true;
  }

  // Only the finest level's diagonal (the rest of the hierarchy is kept).
  bool refresh_finest()
  {
    times = Setup_times();
    return diagonal(structure->levels[0], levels[0]);
  }

  // z = M^-1 r (one V-cycle) on the finest level; `work` of the finest size.
  void apply(const Complex* r, Complex* z, Complex* work) { cycle(0, r, z, work); }

  // y = A x on the finest level; returns Re(x^H A x).
  double multiply(const Complex* x, Complex* y) const
  {
    return level_multiply(structure->levels[0].A, levels[0].a.data(), x, y);
  }

private:
  static bool diagonal(const Level_structure& L, Level_values& V)
  {
    V.inverse_diagonal.resize(std::size_t(L.A.rows));
    for(int i = 0; i < L.A.rows; ++i)
    {
      const int k = L.diagonal[i];
      const double d = (k >= 0) ? V.a[k].real() : 0.0;
      if(!(d > 0) || !std::isfinite(d))
        return false;  // not positive definite
      V.inverse_diagonal[i] = 1.0 / d;
    }
    return true;
  }

  // Unit-modulus parallel field on each aggregate, along its spanning tree.
  static void phases(const Level_structure& L, Level_values& V)
  {
    V.phase.resize(std::size_t(L.A.rows));
    for(int i : L.order)
    {
      const int pe = L.parent_entry[i];
      if(pe < 0)
      {
        V.phase[i] = 1;
        continue;
      }
      const Complex aij = V.a[pe];  // A(parent, i)
      const double m = std::sqrt(aij.real() * aij.real() + aij.imag() * aij.imag());
      const Complex t = (m > 0) ? Complex(-aij.real() / m, aij.imag() / m) : Complex(1);  // -conj(aij) / |aij|
      V.phase[i] = product(V.phase[L.parent[i]], t);
    }
    for(int i = 0; i < L.A.rows; ++i)
      V.phase[i] *= double(L.scale[i]) / std::sqrt(std::norm(V.phase[i]));
  }

  // Gershgorin bound of rho(D^-1 A): max_i sum_j |A_ij| / A_ii (tight for a
  // connection Laplacian, whose diagonal is the sum of the off-diagonal moduli).
  static double gershgorin(const Level_structure& L, const Level_values& V)
  {
    double rho = 0;
    for(int i = 0; i < L.A.rows; ++i)
    {
      double s = 0;
      for(int k = L.A.ptr[i]; k < L.A.ptr[i + 1]; ++k)
        s += std::sqrt(V.a[k].real() * V.a[k].real() + V.a[k].imag() * V.a[k].imag());
      rho = (std::max)(rho, s * V.inverse_diagonal[i]);
    }
    return rho > 0 ? rho : 1.0;
  }

  // rho(D^-1 A) by power iteration on D^-1/2 A D^-1/2 (deterministic start).
  static double spectral_radius(const Level_structure& L, const Level_values& V, int iterations)
  {
    const int n = L.A.rows;
    std::vector<Complex> x(static_cast<std::size_t>(n)), y(static_cast<std::size_t>(n));
    std::vector<double> s(static_cast<std::size_t>(n));
    for(int i = 0; i < n; ++i)
      s[i] = std::sqrt(V.inverse_diagonal[i]);
    std::uint32_t h = 12345u;
    for(int i = 0; i < n; ++i)
    {
      h = h * 1664525u + 1013904223u;
      x[i] = Complex(double(h >> 8) / double(1u << 24) - 0.5, 0.0);
    }
    double rho = 0;
    for(int it = 0; it < iterations; ++it)
    {
      double norm = 0, dot = 0, xnorm = 0;
      for(int i = 0; i < n; ++i)
      {
        double re = 0, im = 0;
        for(int k = L.A.ptr[i]; k < L.A.ptr[i + 1]; ++k)
          add_product(re, im, V.a[k], s[L.A.idx[k]] * x[L.A.idx[k]]);
        y[i] = Complex(s[i] * re, s[i] * im);
        norm += std::norm(y[i]);
        dot += x[i].real() * y[i].real() + x[i].imag() * y[i].imag();
        xnorm += std::norm(x[i]);
      }
      rho = dot / xnorm;  // Rayleigh quotient
      const double inv = 1.0 / std::sqrt(norm);
      for(int i = 0; i < n; ++i)
        x[i] = y[i] * inv;
    }
    return rho > 0 ? rho : 1.0;
  }

  // P = (I - omega D^-1 A) P_tent, one pass over the entries of A.
  static void smoothed_prolongator(const Level_structure& L, Level_values& V)
  {
    std::vector<Complex> p(L.P.nnz(), Complex(0));
    const Pattern& A = L.A;
    for(int i = 0; i < A.rows; ++i)
    {
      const double w = V.omega * V.inverse_diagonal[i];
      for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      {
        const int j = A.idx[k];
        const Complex s = (j == i ? Complex(1.0 - w * V.a[k].real(), -w * V.a[k].imag()) : -w * V.a[k]);
        p[L.a_to_p[k]] += product(s, V.phase[j]);
      }
    }
    V.p.assign(p.begin(), p.end());
  }

  // A_c = P^H A P on the precomputed pattern: for each coarse row c, the
  // fine rows i of column c of P, their entries A(i, j), the entries P(j, b).
  static void galerkin(const Level_structure& L, const Level_values& V, const Level_structure& C, Level_values& W)
  {
    const Pattern& A = L.A;
    const Pattern& P = L.P;
    const Pattern& PT = L.PT;
    const int nc = L.coarse_size;
    W.a.resize(C.A.nnz());
    const Complex* a = V.a.data();
    const Prolongator_value* p = V.p.data();
    const int chunks = chunk_count(nc);
    for_each_index(chunks > 1, std::size_t(chunks), [&](std::size_t chunk_index) {
      const int chunk = int(chunk_index);
      const int first = int((long long)nc * chunk / chunks), last = int((long long)nc * (chunk + 1) / chunks);
      std::vector<double> acc(2 * std::size_t(nc), 0.0);
      for(int c = first; c < last; ++c)
      {
        for(int m = PT.ptr[c]; m < PT.ptr[c + 1]; ++m)
        {
          const int i = PT.idx[m];
          const Complex pc(p[L.pt_to_p[m]]);
          const Complex w(pc.real(), -pc.imag());
          for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
          {
            const int j = A.idx[k];
            const Complex v = product(w, a[k]);
            for(int l = P.ptr[j]; l < P.ptr[j + 1]; ++l)
            {
              double* t = &acc[2 * std::size_t(P.idx[l])];
              add_product(t[0], t[1], v, Complex(p[l]));
            }
          }
        }
        for(int k = C.A.ptr[c]; k < C.A.ptr[c + 1]; ++k)
        {
          double* t = &acc[2 * std::size_t(C.A.idx[k])];
          W.a[k] = Complex(t[0], t[1]);
          t[0] = t[1] = 0;
        }
        W.a[C.diagonal[c]].imag(0);  // Hermitian to rounding: a real diagonal
      }
    });
  }

  static void level_residual(const Level_structure& L, const Level_values& V, const Complex* b, const Complex* x, Complex* r)
  {
    const Complex* a = V.a.data();
    for(int i = 0; i < L.A.rows; ++i)
    {
      double re = b[i].real(), im = b[i].imag();
      for(int k = L.A.ptr[i]; k < L.A.ptr[i + 1]; ++k)
      {
        const Complex& ak = a[k];
        const Complex& xj = x[L.A.idx[k]];
        re -= ak.real() * xj.real() - ak.imag() * xj.imag();
        im -= ak.real() * xj.imag() + ak.imag() * xj.real();
      }
      r[i] = Complex(re, im);
    }
  }

  static void gauss_seidel(const Level_structure& L, const Level_values& V, const Complex* b, Complex* x, bool forward)
  {
    const Pattern& A = L.A;
    const Complex* a = V.a.data();
    const int n = A.rows;
    for(int i0 = 0; i0 < n; ++i0)
    {
      const int i = forward ? i0 : n - 1 - i0;
      double re = b[i].real(), im = b[i].imag();
      for(int k = A.ptr[i]; k < A.ptr[i + 1]; ++k)
      {
        const Complex& ak = a[k];
        const Complex& xj = x[A.idx[k]];
        re -= ak.real() * xj.real() - ak.imag() * xj.imag();
        im -= ak.real() * xj.imag() + ak.imag() * xj.real();
      }
      const double d = V.inverse_diagonal[i];
      x[i] = Complex(x[i].real() + re * d, x[i].imag() + im * d);
    }
  }

  void cycle(std::size_t l, const Complex* b, Complex* x, Complex* work)
  {
    const Level_structure& L = structure->levels[l];
    Level_values& V = levels[l];
    const int n = L.A.rows;
    if(L.coarsest)
    {
      Eigen::Map<const Eigen::VectorXcd> B(b, n);
      Eigen::Map<Eigen::VectorXcd> X(x, n);
      X = V.dense.solve(B);
      return;
    }
    Level_values& W = levels[l + 1];
    const Complex* a = V.a.data();
    const Prolongator_value* p = V.p.data();
    Complex* r = work ? work : V.r.data();
    // First forward sweep from x = 0, computing r = b - A x on the way: after
    // row i, b_i - sum_{j <= i} A_ij x_j = 0, so r_j = -sum_{i > j} A_ji x_i,
    // accumulated from row i's lower entries (A_ji = conj(A_ij)).
    for(int i = 0; i < n; ++i)
    {
      double re = b[i].real(), im = b[i].imag();
      const int end = L.diagonal[i];
      for(int k = L.A.ptr[i]; k < end; ++k)
      {
        const Complex& ak = a[k];
        const Complex& xj = x[L.A.idx[k]];
        re -= ak.real() * xj.real() - ak.imag() * xj.imag();
        im -= ak.real() * xj.imag() + ak.imag() * xj.real();
      }
      const double d = V.inverse_diagonal[i];
      const Complex xi(re * d, im * d);
      x[i] = xi;
      r[i] = 0;
      for(int k = L.A.ptr[i]; k < end; ++k)
      {
        Complex& rj = r[L.A.idx[k]];
        const Complex& ak = a[k];
        rj = Complex(rj.real() - (ak.real() * xi.real() + ak.imag() * xi.imag()),
                     rj.imag() - (ak.real() * xi.imag() - ak.imag() * xi.real()));
      }
    }
    for(int s = 1; s < sweeps; ++s)
    {
      gauss_seidel(L, V, b, x, true);
      level_residual(L, V, b, x, r);
    }
    // bc = P^H r, row by row (scatter into the coarse vector).
    std::fill(W.b.begin(), W.b.end(), Complex(0));
    Complex* bc = W.b.data();
    for(int i = 0; i < n; ++i)
    {
      const Complex ri = r[i];
      for(int k = L.P.ptr[i]; k < L.P.ptr[i + 1]; ++k)
      {
        Complex& t = bc[L.P.idx[k]];
        double tr = t.real(), ti = t.imag();
        add_conj_product(tr, ti, Complex(p[k]), ri);
        t = Complex(tr, ti);
      }
    }
    Complex* xc = W.x.data();
    cycle(l + 1, bc, xc, nullptr);  // coarse levels: their own residual vectors
    // x += P xc, row c applied just before the first row that reads it, then
    // the backward sweep: row i reads rows >= the first column of row i.
    int corrected = n;
    auto correct_down_to = [&](int lowest) {
      while(corrected > lowest)
      {
        const int c = --corrected;
        double re = x[c].real(), im = x[c].imag();
        for(int k = L.P.ptr[c]; k < L.P.ptr[c + 1]; ++k)
          add_product(re, im, Complex(p[k]), xc[L.P.idx[k]]);
        x[c] = Complex(re, im);
      }
    };
    for(int i = n - 1; i >= 0; --i)
    {
      const int first = L.A.ptr[i];
      correct_down_to((std::min)(i, L.A.idx[first]));
      double re = b[i].real(), im = b[i].imag();
      for(int k = first; k < L.A.ptr[i + 1]; ++k)
      {
        const Complex& ak = a[k];
        const Complex& xj = x[L.A.idx[k]];
        re -= ak.real() * xj.real() - ak.imag() * xj.imag();
        im -= ak.real() * xj.imag() + ak.imag() * xj.real();
      }
      const double d = V.inverse_diagonal[i];
      x[i] = Complex(x[i].real() + re * d, x[i].imag() + im * d);
    }
    for(int s = 1; s < sweeps; ++s)
      gauss_seidel(L, V, b, x, false);
  }
};

// Preconditioned conjugate gradient. x holds the initial guess. Returns the
// number of iterations, or -1 if A or the preconditioner is not positive
// definite; `residual` is the final relative true residual.
// With `initial`, x holds an initial guess, kept when its residual is below
// ||b|| (`initial` is then left true), else CG starts from 0 (`initial` false).
inline int pcg(Hierarchy& H, const Complex* b, Complex* x, int n, double tolerance, int max_iterations,
               double& residual, bool& converged, bool& initial)
{
  const std::size_t N = static_cast<std::size_t>(n);
  std::vector<Complex> r(N), z(N), p(N), q(N);
  double bnorm = 0;
  for(int i = 0; i < n; ++i)
    bnorm += std::norm(b[i]);
  bnorm = std::sqrt(bnorm);
  converged = false;
  if(bnorm == 0)
  {
    std::fill(x, x + n, Complex(0));
    residual = 0;
    converged = true;
    return 0;
  }
  auto true_residual = [&]() {
    H.multiply(x, q.data());
    double t = 0;
    for(int i = 0; i < n; ++i)
    {
      r[i] = b[i] - q[i];
      t += std::norm(r[i]);
    }
    return std::sqrt(t);
  };
  double rnorm;
  if(initial)
  {
    rnorm = true_residual();
    if(!(rnorm < bnorm))
      initial = false;
  }
  if(!initial)
  {
    std::fill(x, x + n, Complex(0));
    std::copy(b, b + n, r.begin());
    rnorm = bnorm;
  }
  const double threshold = tolerance * bnorm;
  int it = 0;
  double rz = 0;
  while(true)
  {
    if(rnorm <= threshold)
    {
      rnorm = true_residual();
      if(rnorm <= threshold)
      {
        converged = true;
        break;
      }
      rz = 0;  // restart the directions from the true residual
    }
    if(it >= max_iterations)
      break;
    H.apply(r.data(), z.data(), q.data());  // q is free until A p
    double rz_new = 0;
    for(int i = 0; i < n; ++i)
      rz_new += r[i].real() * z[i].real() + r[i].imag() * z[i].imag();
    if(!(rz_new > 0))
      return -1;
    if(rz == 0)
      std::copy(z.begin(), z.end(), p.begin());
    else
    {
      const double beta = rz_new / rz;
      for(int i = 0; i < n; ++i)
        p[i] = Complex(z[i].real() + beta * p[i].real(), z[i].imag() + beta * p[i].imag());
    }
    rz = rz_new;
    const double pq = H.multiply(p.data(), q.data());
    if(!(pq > 0))
      return -1;
    const double alpha = rz / pq;
    double t = 0;
    for(int i = 0; i < n; ++i)
    {
      x[i] = Complex(x[i].real() + alpha * p[i].real(), x[i].imag() + alpha * p[i].imag());
      r[i] = Complex(r[i].real() - alpha * q[i].real(), r[i].imag() - alpha * q[i].imag());
      t += std::norm(r[i]);
    }
    rnorm = std::sqrt(t);
    ++it;
  }
  residual = rnorm / bnorm;
  return it;
}

} // namespace amg
} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_SMOOTHED_AGGREGATION_H
