// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.
//
// Quad-mesh extraction from a seamless integer-grid map,
// after Ebke, Bommes, Campen, Kobbelt 2013 (QEx). Written from the paper only.

#ifndef CGAL_POLYVECTOR_FIELDS_EXTRACT_QUAD_MESH_H
#define CGAL_POLYVECTOR_FIELDS_EXTRACT_QUAD_MESH_H

/// \file extract_quad_mesh.h
/// The quad mesh of an integer-grid map: its vertices are the integer points of
/// the map, its edges the integer iso-lines between them. The map is the one of
/// `compute_integer_grid_map()` with its exact seam transitions, on the same
/// `Tangent_bundle`, or a uv map given by the user.

#include <CGAL/Polyvector_fields/Error_code.h>
#include <CGAL/Polyvector_fields/Tangent_bundle.h>
#include <CGAL/Polyvector_fields/compute_integer_grid_map.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/Chart_mesh.h>
#include <CGAL/Polyvector_fields/internal/Quad_extraction/extract_from_chart_mesh.h>
#include <CGAL/Polyvector_fields/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Polyvector_fields {

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// reports on a run of `extract_quad_mesh()`.
struct Quad_extraction_result
{
  // input map
  std::size_t flipped_faces = 0;          ///< triangles of the input map that fold: det(uv) <= 0, or around a wound vertex (see <b>Fold-overs</b>)
  std::size_t degenerate_uv_faces = 0;    ///< of which det(uv) == 0
  std::size_t repaired_regions = 0;       ///< fold-over regions re-embedded
  std::size_t repaired_vertices = 0;      ///< vertices whose uv the repair moved
  std::size_t repair_rings = 0;           ///< largest ring count the repair needed
  std::size_t filled_holes = 0;           ///< holes left by the fold-overs that the repair could not unfold, filled with quads (see <b>Fold-overs</b>)
  std::size_t filling_quads = 0;          ///< quads of those fillings (counted in `quads`)
  std::size_t replaced_quads = 0;         ///< quads of the map that a hole enclosed, replaced by its filling
  std::size_t filling_rings = 0;          ///< largest ring count a hole's region grew by around its fold-overs
  std::size_t refilled_quads = 0;         ///< quads still folded after their repair, cut out with the quads around them and filled
  std::size_t split_components = 0;       ///< connected components whose fold-overs could not be filled: their triangles are split into quads
  std::size_t split_small_components = 0; ///< of which components without a whole cell, with `split_components_without_cells`
  std::size_t split_far_components = 0;   ///< of which components farther than `max_input_distance` from their quads
  std::size_t split_defective_components = 0; ///< of which components whose quads were not one quad mesh of them, with `split_components_without_cells` (see <b>Components</b>)
  std::size_t split_triangles = 0;        ///< the triangles so split (three quads each, counted in `quads`)
  std::size_t cut_faces = 0;              ///< triangles cut out of the map around those fold-overs
  std::size_t seam_edges = 0;             ///< interior edges with a non-identity transition
  std::size_t degenerate_uv_edges = 0;    ///< interior edges of zero uv length
  // integer points and iso-lines
  std::size_t integer_points = 0;         ///< integer points of the map (in vertices, on edges, in faces)
  std::size_t points_at_vertices = 0;     ///< of which at mesh vertices
  std::size_t points_on_edges = 0;        ///< of which inside mesh edges
  std::size_t points_in_faces = 0;        ///< of which inside faces
  std::size_t singular_points = 0;        ///< interior integer points whose valence in the map is not 4
  std::size_t traced_half_edges = 0;      ///< iso-line traces (one per direction leaving an integer point)
  std::size_t boundary_traces = 0;        ///< traces that leave the surface before the next integer point
  std::size_t triangle_crossings = 0;     ///< triangles entered by all traces
  // output
  std::size_t vertices = 0;               ///< vertices of the output
  std::size_t faces = 0;                  ///< faces of the output
  std::size_t quads = 0;                  ///< of which whole cells (quads)
  std::size_t trimmed_polygons = 0;       ///< of which cells trimmed by the boundary (with `keep_trimmed_boundary`)
  std::size_t discarded_cells = 0;        ///< boundary cells dropped (whole-cell mode)
  std::size_t non_quad_cells = 0;         ///< closed cells with other than 4 corners (dropped; expected 0)
  std::size_t folded_quads = 0;           ///< quads folded against the surface after the repair (`FOLDED_QUAD`; 0 on success)
  std::size_t unfolded_quads = 0;         ///< folded quads repaired by moving their corners on the surface
  std::size_t moved_quad_vertices = 0;    ///< quad vertices the repair moved (off their integer points, onto input vertices or edge midpoints)
  std::size_t snapped_tips = 0;           ///< quad corners moved onto input vertices that were far from the quads (see <b>Tips</b>)
  double largest_input_distance = 0;      ///< the largest distance of an input vertex or face centroid to the quads (each cut along its diagonal from its first corner), after the tips are snapped
  std::size_t split_vertices = 0;         ///< vertices duplicated because their kept faces formed several fans
  std::size_t split_cells = 0;            ///< trimmed cells (with `keep_trimmed_boundary`) that went around the surface or passed twice through a point, cut into simple polygons (counted in `trimmed_polygons` by their pieces)
  std::size_t added_vertices = 0;         ///< vertices added inside iso-line segments of split cells that closed on themselves or joined the same two points as another one
  std::size_t irregular_vertices = 0;     ///< interior output vertices of valence != 4
  std::size_t components = 0;             ///< connected components of the input mesh (through its edges)
  std::size_t components_without_cells = 0;  ///< of which components where the map has no whole integer cell (`NO_INTEGER_CELL`)
  std::size_t inconsistencies = 0;        ///< internal checks that failed (expected 0)
  std::string diagnostic;                 ///< on failure: which check failed
  // times in seconds
  double time_setup = 0;    ///< charts, transitions and vertex fans
  double time_repair = 0;   ///< fold-over repair and the checks after it
  double time_points = 0;   ///< integer points and their iso-line directions
  double time_tracing = 0;  ///< iso-line tracing
  double time_faces = 0;    ///< cells
  double time_output = 0;   ///< positions and the output mesh
  double time_total = 0;  ///< the whole call
};

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// extracts the quad mesh of the integer-grid map `uv_map` of the triangle mesh
/// `tm` (after QEx, Ebke et al. 2013): one vertex per integer point of the map,
/// one edge per integer iso-line segment between two of them, one face per cell.
///
/// <b>Map.</b> `uv_map[h]` is the uv of `target(h)` inside `face(h)`. Across every
/// interior edge the two charts must be related exactly (in floating point) by
/// `uv_B = R^r uv_A + t`, `R` the quarter turn and `t` integer, and every vertex of
/// non-zero index must be on an integer point: what `compute_integer_grid_map()` writes.
/// This overload is for a map given by the user (computed elsewhere, or read from a
/// file): it finds each transition from the uv of the edge's two endpoints in both
/// charts. For a map computed by `compute_integer_grid_map()`, the other overload takes
/// the transitions the map returns, which stay right where the uv alone cannot tell
/// them (an edge of zero uv length).
///
/// <b>Exactness.</b> The transitions are found and checked exactly; integer points,
/// iso-line/edge crossings and point-in-triangle tests are decided by exact
/// comparisons and orientation predicates on the uv values; a point on an edge or
/// at a vertex is one point for all the triangles around it (found through the mesh
/// connectivity, never by distance). Positions: the barycentric combination of the
/// triangle's corners, computed in exact rationals and rounded once per coordinate
/// (a point of a flat mesh whose map is exact gets its exact coordinates).
///
/// <b>Singular vertices.</b> A vertex whose uv angles sum to `(4 - k) pi/2` has
/// `4 - k` iso-line directions, hence valence `4 - k` in the output.
///
/// <b>Boundary.</b> By default only whole cells are kept (all quads). With
/// `keep_trimmed_boundary(true)`, the cells cut by the boundary become polygons
/// bounded by the iso-lines and by the mesh boundary (through its vertices). Where
/// the quads are as large as a part of the surface (a cylinder whose circumference
/// is about one quad), such a cell can go around the surface or pass twice through
/// a point: it is then cut into simple polygons, by diagonals between its corners
/// and, where an iso-line closes on itself or joins the same two points as another
/// one, by vertices added inside that iso-line (`result.split_cells`,
/// `result.added_vertices`). The polygons are checked to form a polygon mesh with
/// the Euler characteristic of `tm`.
///
/// <b>Fold-overs.</b> Triangles with `det <= 0` are repaired before extraction:
/// they and up to `fold_over_repair_rings` rings around them are re-embedded
/// (Tutte, ring boundary fixed, exact transitions). So are the triangles
/// around a wound vertex: a vertex off the integer grid, every triangle
/// around it positive, and either interior, with no cone there, with a star
/// that does not turn `2 pi` (for example `4 pi`: the map covers the plane
/// twice there), or on the border with a star that turns `2 pi` or more.
/// Each region is tried on one ring, then two, up to `fold_over_repair_rings`;
/// when no re-embedding of a region unfolds it, the one that leaves the fewest
/// folded triangles (those of `det <= 0` and around wound vertices) is kept if
/// that is fewer than before, and the next, larger region starts from it. Reported in `result`.
///
/// <b>Holes.</b> What the repair cannot unfold is cut out of the map (with `fill_fold_overs`, the
/// default, and whole cells only): the triangles that still fold, and those around a vertex whose
/// remaining triangles would form several fans or wind. The whole cells of the rest are
/// extracted; they stop short of the cut, and leave a hole around it bounded by a loop of quad
/// edges. The surface under each hole, grown ring by ring (up to twice `fold_over_repair_rings`)
/// until it is a disk that holds the loop (a hole of the surface inside it is closed by a fan for
/// this), is parametrized on the unit disk by mean value coordinates (Floater 2003), one to one;
/// the loop is a simple polygon there, filled with quads: a constrained Delaunay triangulation
/// with points on a square lattice inside, its triangles merged in pairs into convex quads (a
/// largest matching) and the others split, an odd number of sides each, at their midpoints, the
/// inner points then smoothed. The new corners go back to the surface through the
/// parametrization's triangles, so they lie on it. A hole at the surface's border is closed along
/// the border (new corners on its edges), and a hole of the surface inside the loop stays a hole.
/// A region may not take more than half of its connected component. A component whose holes
/// cannot all be filled gets its triangles split into quads, three each, around their centroids
/// and through their edge midpoints (`result.split_components`). Without `fill_fold_overs`, or
/// with `keep_trimmed_boundary`, what the repair cannot unfold makes the call fail with
/// `UNREPAIRABLE_FOLD_OVER`. The fillings are counted in `result.filled_holes` and
/// `result.filling_quads`; their quads are not aligned with the map, and have corners of any valence.
///
/// <b>Folded quads.</b> Every quad is checked against the input surface under it: it is
/// folded when neither of its diagonals splits it into two triangles that face the side
/// of the input faces there: of each face nearest to its centroid, and of the sum of
/// the normals of the faces its sides were traced through. A quad folds where the surface bends by more than a right angle under it
/// (a crease or a thin ridge finer than the quads). Unless `fold_over_repair_rings` is
/// 0, a corner of a folded quad is then moved to the nearest point of the surface under
/// its quads (a vertex of an input face, or an edge midpoint) that leaves every quad at
/// that corner unfolded (`result.unfolded_quads`, `result.moved_quad_vertices`). With
/// `fill_fold_overs`, a quad still folded is cut out with the quads that share a corner with
/// it, and the hole filled as above (`result.refilled_quads`); otherwise, or if that fails, a
/// quad still folded makes the call fail with `FOLDED_QUAD`.
///
/// <b>Tips.</b> An input vertex farther than `tip_snapping_distance` mean quad sides from the quads
/// (the tip of a spike, the end of a part thinner than the quads) moves the nearest corner of its
/// nearest quad onto itself, if every quad at that corner stays unfolded; a corner on the border of
/// the quads never moves, a vertex on the surface's border pulls none, each corner moves once
/// (`result.snapped_tips`), and with `keep_trimmed_boundary` nothing moves. Then
/// `result.largest_input_distance` is the largest distance of an input vertex or face centroid
/// to the quads, each cut along the diagonal from its first corner. With `max_input_distance`, a
/// connected component whose input is farther than that from the quads gets its triangles split
/// into quads (see <b>Holes</b>; `result.split_far_components`), which lie on them.
///
/// <b>Components.</b> Each connected component of `tm` gets its own quads. One where the map has
/// no whole cell (smaller than a quad) makes the call fail with `NO_INTEGER_CELL`, or, with
/// `split_components_without_cells`, gets its triangles split into quads as above (unless no
/// component has a cell). The quads of each component are then checked: they form one polygon
/// mesh, in one piece, and on a closed component they are closed and have its Euler
/// characteristic. A component whose quads fail (the quad size is too large for a thin part of
/// it) makes the call fail with `NON_DISK_CELL`, naming the component and the cause, or, with
/// `split_components_without_cells`, gets its triangles split into quads
/// (`result.split_defective_components`; unless every component fails).
///
/// All computations are done in `double` (and exact rationals where stated),
/// whatever the kernels of `tm` and `quad_mesh`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
///         with parallelism (TBB) the distances of the input to the quads (<b>Tips</b>) are shared among
///         threads; the quad mesh is the same to the last bit
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` whose faces are triangles
/// \tparam UVMap a model of `ReadablePropertyMap` from halfedges of `tm` to a 2D point (with `x()` and `y()`)
///         or to a pair of numbers indexed by `[0]` and `[1]` (`std::array<double, 2>`), as written by
///         `compute_integer_grid_map()`: the value at `target(h)` inside `face(h)`
/// \tparam PolygonMesh a model of `MutableFaceGraph` (the output)
///
/// \param tm the triangle mesh
/// \param uv_map the integer-grid map
/// \param quad_mesh receives the quad mesh (cleared first), on success only
/// \param result receives the counts, the diagnostic and the times (also on failure, as far as they were computed)
/// \param np an optional sequence of named parameters for `tm`, among the ones listed below
/// \param np_out an optional sequence of named parameters for `quad_mesh`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{keep_trimmed_boundary}
///     \cgalParamDescription{keep the cells cut by the mesh boundary as polygons bounded by the iso-lines and
///                           the boundary (through its vertices); given with
///                           `Polyvector_fields::parameters::keep_trimmed_boundary()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`: whole cells only, so that every face is a quad}
///   \cgalParamNEnd
///   \cgalParamNBegin{fold_over_repair_rings}
///     \cgalParamDescription{the largest number of vertex rings around a fold-over that its repair may
///                           re-embed (0: no repair, neither of the map's fold-overs nor of folded quads); given with
///                           `Polyvector_fields::parameters::fold_over_repair_rings()`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{6}
///   \cgalParamNEnd
///   \cgalParamNBegin{fill_fold_overs}
///     \cgalParamDescription{cut out what the fold-over repair leaves and fill the holes with quads, and
///                           fill the quads still folded after their repair in the same way (see <b>Holes</b>);
///                           given with `Polyvector_fields::parameters::fill_fold_overs()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{tip_snapping_distance}
///     \cgalParamDescription{an input vertex farther than this many mean quad sides from the quads pulls the
///                           nearest quad corner onto itself (0: none; see <b>Tips</b>); given with
///                           `Polyvector_fields::parameters::tip_snapping_distance()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.3}
///   \cgalParamNEnd
///   \cgalParamNBegin{split_components_without_cells}
///     \cgalParamDescription{split the triangles of a connected component without a whole cell, or whose
///                           quads are not one quad mesh of it, into quads instead of failing (see
///                           <b>Components</b>); given with
///                           `Polyvector_fields::parameters::split_components_without_cells()`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_input_distance}
///     \cgalParamDescription{a connected component with an input vertex or face centroid farther than this
///                           from the quads gets its triangles split into quads (0: none; see <b>Tips</b>); given
///                           with `Polyvector_fields::parameters::max_input_distance()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// The named parameters of `np_out`:
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `quad_mesh`}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` (constructible from three `double`) as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, quad_mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `Error_code::SUCCESS`; `EMPTY_MESH`; `NON_TRIANGLE_FACE`; `DEGENERATE_FACE` (a face with a repeated
///          vertex) or `NON_MANIFOLD_MESH` (a vertex whose faces do not form one fan); `NON_FINITE_VALUE` (a
///          coordinate or a uv value); `NOT_AN_INTEGER_GRID_MAP` (no face of positive uv area, a transition
///          that is not a grid symmetry, a vertex of non-zero index off the integer grid, or traces that do not
///          close up: see `result.diagnostic`); `UNREPAIRABLE_FOLD_OVER` (without `fill_fold_overs`, with
///          `keep_trimmed_boundary`, or when every triangle would be cut out: see <b>Holes</b>); `NO_INTEGER_CELL` if a connected
///          component of `tm` gets no face, the quad size of the map being larger than that part of the
///          surface (`result.diagnostic` names the first such component; never an empty or partial quad
///          mesh); `FOLDED_QUAD` if a quad is still folded against the surface after the repair (see <b>Folded
///          quads</b>), their number in `result.folded_quads`; `NON_DISK_CELL` if a cell goes around a hole or
///          a handle of the surface or passes twice through a point and cannot be cut into polygons (always so
///          for whole cells, which must stay quads), the quad size being larger than that part of the surface.
///          `quad_mesh` is written only on success; `tm` is never changed.
///
/// \sa `compute_integer_grid_map()`, `quad_planarity()`, `planarize_quad_mesh()`, `IO::write_quad_mesh_VTK()`
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh, typename UVMap,
          typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename NamedParametersOut = CGAL::parameters::Default_named_parameters>
Error_code extract_quad_mesh(const TriangleMesh& tm, UVMap uv_map, PolygonMesh& quad_mesh, Quad_extraction_result& result,
                             const NamedParameters& np = CGAL::parameters::default_values(),
                             const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto start = internal::qex::Clock::now();
  result = Quad_extraction_result();
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    CGAL::get_const_property_map(CGAL::vertex_point, tm));
  internal::qex::Chart_mesh M;
  const Error_code code = internal::qex::build_chart_mesh(tm, vpm, uv_map, M);
  if(code != Error_code::SUCCESS)
    return code;
  const Error_code extraction = internal::qex::extract_from_chart_mesh(
    M, false, std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value, np, quad_mesh, np_out, result, start);
  result.time_total = internal::qex::seconds(start);
  return extraction;
}

/// \ingroup PkgPolyvectorFieldsQuadMeshes
///
/// extracts the quad mesh of the integer-grid map `uv_map` that
/// `compute_integer_grid_map()` computed on `bundle`, with the exact seam
/// transitions it returned in `map.seam_transitions` (after QEx, Ebke et al. 2013).
///
/// This is the overload of the meshing road (`comb_frame_field()`, then
/// `compute_integer_grid_map()`, then this function, on one tangent bundle): the
/// transitions are not found again from the uv but taken from the map, and checked
/// exactly against the uv. Everything else (exactness, singular vertices, boundary,
/// fold-overs, output, named parameters) is as in the other overload.
///
/// \tparam ConcurrencyTag as in the other overload
/// \tparam TriangleMesh, VertexPointMap the parameters of the bundle
/// \tparam UVMap as in the other overload
/// \tparam PolygonMesh a model of `MutableFaceGraph` (the output)
///
/// \param bundle the tangent bundle the map was computed on
/// \param uv_map the integer-grid map, as written by `compute_integer_grid_map()`
/// \param map the report of that call, with its `seam_transitions`
/// \param quad_mesh receives the quad mesh (cleared first), on success only
/// \param result receives the counts, the diagnostic and the times
/// \param np `keep_trimmed_boundary` and `fold_over_repair_rings` (see the other overload)
/// \param np_out the named parameters for `quad_mesh` (see the other overload)
///
/// \returns as the other overload; `NOT_AN_INTEGER_GRID_MAP` also if `map.seam_transitions` does
///          not hold one transition per corner of the bundle, or a transition does not map the uv
///          of its edge exactly (`result.diagnostic` says which).
///
/// \sa `comb_frame_field()`, `compute_integer_grid_map()`, `Seam_transition`
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh, typename VertexPointMap,
          typename UVMap, typename PolygonMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename NamedParametersOut = CGAL::parameters::Default_named_parameters>
Error_code extract_quad_mesh(const Tangent_bundle<TriangleMesh, VertexPointMap>& bundle, UVMap uv_map,
                             const Integer_grid_map_result& map, PolygonMesh& quad_mesh, Quad_extraction_result& result,
                             const NamedParameters& np = CGAL::parameters::default_values(),
                             const NamedParametersOut& np_out = CGAL::parameters::default_values())
{
  const auto start = internal::qex::Clock::now();
  result = Quad_extraction_result();
  internal::qex::Chart_mesh M;
  const Error_code code = internal::qex::build_chart_mesh(bundle, uv_map, map.seam_transitions, M);
  if(code != Error_code::SUCCESS)
  {
    if(code == Error_code::NOT_AN_INTEGER_GRID_MAP)
      result.diagnostic = "the map's seam transitions do not match the bundle";
    return code;
  }
  const Error_code extraction = internal::qex::extract_from_chart_mesh(
    M, true, std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value, np, quad_mesh, np_out, result, start);
  result.time_total = internal::qex::seconds(start);
  return extraction;
}

} // namespace Polyvector_fields
} // namespace CGAL

#endif // CGAL_POLYVECTOR_FIELDS_EXTRACT_QUAD_MESH_H
