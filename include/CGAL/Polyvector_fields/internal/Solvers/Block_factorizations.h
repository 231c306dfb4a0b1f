// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

#ifndef CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_BLOCK_FACTORIZATIONS_H
#define CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_BLOCK_FACTORIZATIONS_H

// The factorizations of the blocks of one linear system (one per coefficient
// degree, or one for coupled degrees), each a Sparse_factorization (the model
// of the SparseFactorization concept for the solver). All blocks have one
// sparsity pattern: they share one symbolic analysis, computed on the first
// block; then the blocks are factored, refactored and solved independently, in
// parallel when allowed (TBB and a model whose `is_thread_safe` is true). Each
// block is computed by the same operations whatever the thread, so a parallel
// run is bit-identical to a sequential one.

#include <CGAL/Polyvector_fields/Sparse_factorization.h>
#include <CGAL/Polyvector_fields/internal/parallel.h>
#include <CGAL/Polyvector_fields/internal/types.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polyvector_fields {
namespace internal {

// Runs task(b) for b = 0 .. blocks-1, in parallel when `parallel` (and TBB is
// linked); returns whether every task returned true. One after the other,
// the first failure stops the loop.
template <typename Task>
bool for_each_block(std::size_t blocks, bool parallel, const Task& task)
{
  if(!parallel || blocks < 2)
  {
    for(std::size_t b = 0; b < blocks; ++b)
      if(!task(b))
        return false;
    return true;
  }
  std::vector<char> ok(blocks, 0);
  for_each_index(true, blocks, [&](std::size_t b) { ok[b] = task(b) ? 1 : 0; });
  return std::find(ok.begin(), ok.end(), 0) == ok.end();
}

template <typename SolverTraits, typename Scalar = Complex>
class Block_factorizations
{
public:
  typedef Sparse_factorization<SolverTraits, Scalar> Block;
  typedef typename Block::Matrix Matrix;
  typedef typename Block::Dense_matrix Dense_matrix;
  typedef typename Block::Solver_scope Solver_scope;
  // Whether the factorizations may keep references to the matrices.
  static constexpr bool keeps_matrices = Block::keeps_matrix;

  Block_factorizations(const SolverTraits& prototype, bool parallel)
    : m_prototype(prototype), m_parallel(parallel && Block::is_thread_safe)
  {}

  bool parallel() const { return m_parallel; }
  bool empty() const { return m_blocks.empty(); }
  std::size_t size() const { return m_blocks.size(); }

  // A new shared analysis on matrices[0], then the numeric factorization of
  // every block. The matrices must outlive the factorizations if
  // `keeps_matrices`.
  bool factor(const std::vector<Matrix>& matrices)
  {
    m_blocks.clear();
    const auto analysis = std::make_shared<typename Block::Shared_analysis>();
    for(std::size_t b = 0; b < matrices.size(); ++b)
    {
      m_blocks.emplace_back(new Block(m_prototype));
      m_blocks.back()->share_analysis(analysis);
    }
    if(matrices.empty() || matrices[0].rows() == 0)
      return true;
    // The first analysis computes the shared one, alone; then every block.
    if(!m_blocks[0]->analyze(matrices[0]))
      return false;
    return for_each_block(matrices.size(), m_parallel, [&](std::size_t b) {
      return (b == 0 || m_blocks[b]->analyze(matrices[b])) && m_blocks[b]->factorize(matrices[b]);
    });
  }

  // The numeric factorization of new values on the analysed pattern.
  bool refactor(const std::vector<Matrix>& matrices)
  {
    if(matrices.empty() || matrices[0].rows() == 0)
      return true;
    return for_each_block(matrices.size(), m_parallel, [&](std::size_t b) { return m_blocks[b]->factorize(matrices[b]); });
  }

  // Solves block b for the columns of `B`.
  bool solve(std::size_t b, const Dense_matrix& B, Dense_matrix& X) { return m_blocks[b]->solve(B, X); }

private:
  SolverTraits m_prototype;
  bool m_parallel;
  std::vector<std::unique_ptr<Block> > m_blocks;
};

} // namespace internal
} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_INTERNAL_SOLVERS_BLOCK_FACTORIZATIONS_H
