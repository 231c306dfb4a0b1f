# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

"""PolyVector fields and planar-quad remeshing on triangle meshes, on numpy arrays.

The conventions are those of libigl's Python bindings:

- ``V`` is a float64 array of shape (#V, 3), the vertex positions;
- ``F`` is an integer array (int32 or int64, C or Fortran order) of shape
  (#F, 3), the triangles, as rows of vertex indices (0-based);
- functions return tuples of numpy arrays, the last element being a dict of
  the figures that the C++ function reports (counts, measures, times);
- keyword arguments are named like the C++ named parameters.

Every function refuses bad input with :class:`Error` (a ``ValueError``): its
message names the argument and the cause, and its ``code`` attribute is the
name of the package's ``Error_code`` (``"NON_MANIFOLD_MESH"``,
``"DUPLICATE_CONSTRAINT"``, ...) or ``"BAD_ARRAY"`` for an argument of the wrong
type or shape. The C++ work runs without the GIL, so threads can design fields
at the same time.

The method is that of "Designing N-PolyVector Fields with Complex Polynomials"
(Diamanti, Vaxman, Panozzo, Sorkine-Hornung, SGP 2014); section numbers below
are the paper's. The user manual (doc/Polyvector_fields) has a Python section.
"""

import math
import os
import tempfile

import numpy as np

from . import _core
from ._core import Error

__all__ = [
    "Error", "read_triangle_mesh", "save_mesh", "design_field", "frame_field", "singularities",
    "principal_curvatures", "sharp_edges", "refine_for_quad_size", "integer_grid_map", "quad_mesh",
    "quad_planarity", "planarize", "quad_remesh", "write_html_viewer", "write_quad_mesh_ply",
]

Error.__doc__ = """A refusal or a failure of the package.

``str(e)`` is the package's message with the argument or stage it concerns;
``e.code`` is the name of the ``Error_code`` value (for instance
``"NON_MANIFOLD_MESH"``), or ``"BAD_ARRAY"`` for an array of the wrong type or shape."""


def _refuse(message, code="BAD_ARRAY"):
    error = Error(message + " (" + code + ")")
    error.code = code
    return error


def read_triangle_mesh(filename, repair=True):
    """Reads a mesh file (.off, .obj, .ply, .stl) as a triangle mesh.

    With ``repair`` (default), polygons are triangulated and a polygon soup is
    repaired (duplicate points merged, duplicate and degenerate faces removed,
    faces reoriented, non-manifold vertices split), exactly as the command-line
    program ``design_polyvector_field`` does; without it such a mesh is refused.

    Returns ``V, F, info``; ``info["source_face"][i]`` is the position in the
    file of the face that face ``i`` comes from.
    """
    return _core.read_triangle_mesh(os.fspath(filename), repair)


def save_mesh(filename, V, F):
    """Writes a polygon mesh (triangles or quads: ``F`` of shape (#F, k)) as .obj or .off.

    Rows of ``F`` may end with -1 entries, for faces of fewer corners than
    ``F`` has columns (as :func:`quad_mesh` returns polygons).

    Coordinates are written with 17 significant digits, so that they read back
    exactly. The file is written to a temporary file in the same folder and
    renamed: on failure nothing is left half-written.
    """
    filename = os.fspath(filename)
    V = np.asarray(V, dtype=np.float64)
    F = np.asarray(F)
    if V.ndim != 2 or V.shape[1] != 3:
        raise _refuse("save_mesh: V: expected shape (n, 3), got %s" % (V.shape,))
    if F.ndim != 2 or F.shape[1] < 3 or F.dtype.kind not in "iu":
        raise _refuse("save_mesh: F: expected an integer array of shape (n, k >= 3), got %s %s" % (F.dtype, F.shape))
    if F.size and (F.max() >= len(V) or (F[:, :3] < 0).any() or ((F < 0) & (F != -1)).any()):
        raise _refuse("save_mesh: F: an index is not a vertex of V (0..%d)" % (len(V) - 1))
    if F.size and ((F[:, :-1] == -1) & (F[:, 1:] != -1)).any():
        raise _refuse("save_mesh: F: -1 pads the end of a row only")
    extension = os.path.splitext(filename)[1].lower()
    if extension not in (".obj", ".off"):
        raise _refuse("save_mesh: '%s': the format is chosen by the extension, .obj or .off" % filename)
    lines = []
    if extension == ".off":
        lines.append("OFF\n%d %d 0\n" % (len(V), len(F)))
        lines.extend("%.17g %.17g %.17g\n" % tuple(p) for p in V)
        lines.extend("%d %s\n" % (len(f), " ".join(str(int(i)) for i in f)) for f in (row[row >= 0] for row in F))
    else:
        lines.extend("v %.17g %.17g %.17g\n" % tuple(p) for p in V)
        lines.extend("f %s\n" % " ".join(str(int(i) + 1) for i in f) for f in (row[row >= 0] for row in F))
    folder = os.path.dirname(os.path.abspath(filename))
    handle, temporary = tempfile.mkstemp(prefix=".pvf_", dir=folder)
    try:
        # mkstemp makes the file readable by its owner only: give it the permissions of a file opened for writing
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        with os.fdopen(handle, "w") as out:
            out.writelines(lines)
        os.replace(temporary, filename)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def design_field(V, F, b, bc, degree=4, sign_symmetric=False, soft=None, smoothness_weights="uniform"):
    """Designs the smoothest N-PolyVector field that meets the constraints (Section 3).

    An N-PolyVector field gives every face N tangent vectors, the roots of a
    complex polynomial of degree N in the face's tangent plane (Section 3.1).
    The field minimises the smoothness energy of the coefficients, compared
    across each edge by Levi-Civita transport (Sections 3.2, 3.3), subject to
    the constraints (Section 3.6). It is found by one sparse linear solve per
    coefficient, with no integer variable and no iteration.

    Parameters
    ----------
    V, F : the triangle mesh.
    b : int array (#b,), the constrained faces.
    bc : float array (#b, 3k), the constraint vectors of each face, k vectors
        x, y, z per row. k = N (k = N/2 with ``sign_symmetric``) fixes the whole
        PolyVector of the face (a full constraint); fewer vectors ask that each
        be one of the face's N vectors (a partial constraint, the condition
        P(u) = 0). Rows with fewer vectors than others end with NaN triples.
        ``b`` and ``bc`` may both be None: each connected component then gets
        the smoothest field of unit vectors (an N-RoSy field).
    degree : N, the number of vectors per face (1 to 32).
    sign_symmetric : the vectors come in pairs {u, -u} (N even): with N = 4,
        a frame field {±u, ±v} (Section 4).
    soft : None (hard constraints, met exactly), or a weight in [1e-8, 1e8]
        for all constraints, or one weight per row of ``b``: the constraint is
        then a term weight * |residual|^2 of the energy (Section 3.6).
    smoothness_weights : "uniform" (the paper's: every edge weighs 1) or
        "harmonic" (3|e|^2 / (A_f + A_g), which follows the geometry rather
        than the triangulation's density).

    Returns
    -------
    X : float array (#F, 3N), the N vectors of each face in world coordinates,
        counterclockwise about the face normal (row f: x0 y0 z0 x1 y1 z1 ...);
        with ``sign_symmetric``, vector k + N/2 is exactly -vector k. These are
        the numbers the command-line program writes to its .rawfield file.
    info : dict: the numbers of full, partial and soft constraints, the
        connected components, the smoothness energy and the times.
    """
    return _core.design_field(V, F, b, bc, degree, sign_symmetric, soft, smoothness_weights)


def frame_field(V, F, b=None, bc=None, curvature_constraints=None, conjugate=False, angle_bound=None, soft=None,
                orthogonality_weight=0.0, number_of_iterations=None, tolerance=None, smoothness_weights="uniform"):
    """Designs a frame field {±u, ±v} (N = 4, sign-symmetric), optionally optimised (Section 4).

    The smooth frame field of the constraints (as :func:`design_field` with
    ``degree=4, sign_symmetric=True``) is then, on request, optimised by the
    paper's local-global iterations, which keep the hard constraints:

    Parameters
    ----------
    V, F : the triangle mesh.
    b, bc : constraints as in :func:`design_field`, with 1 or 2 vectors per face
        (bc of 3 or 6 columns); both None for none.
    curvature_constraints : None, or a fraction in (0, 1] of the faces to
        constrain to their principal curvature directions: the most
        anisotropic faces, spread over the surface, as the paper sampled its
        constraints from the principal directions (Section 4.1). Faces in ``b``
        keep their own constraint.
    conjugate : optimise the field to be conjugate, u^T S v = 0 with S the
        shape operator of the surface: the directions that planar-quad meshes
        follow (Section 4.3).
    angle_bound : None, or an angle in degrees in (0, 90]: optimise the field
        so that u and v make at least this angle in every free face (Section 4.2).
    soft : as in :func:`design_field`; a single weight applies to the curvature
        constraints too.
    orthogonality_weight : with ``conjugate``, the weight of the term that pulls
        the field towards a cross field (Section 4.2, "Orthogonality control").
    number_of_iterations : the iteration limit (default: the algorithm's,
        200 for the angle bound, 50 for conjugacy).
    tolerance : with ``angle_bound``, how far in degrees the iterations may stop
        below the bound (default 0.5); with ``conjugate``, the mean normalised
        deviation |u^T S v| / (|u| |v| max|k|) at which they stop (default 5e-3).
    smoothness_weights : as in :func:`design_field`.

    Not reaching the bound or the tolerance within the iterations is reported in
    ``info`` (``angle_bound_converged``, ``conjugate_converged``), not raised, as
    the command-line program does.

    Returns
    -------
    X : float array (#F, 12): u, v, -u, -v of each face in world coordinates.
    info : dict: constraint counts, energies before and after the optimisation,
        iterations, smallest angles (degrees), conjugacy deviation.
    """
    return _core.frame_field(V, F, b, bc, curvature_constraints, conjugate, angle_bound, soft, orthogonality_weight,
                             number_of_iterations, tolerance, smoothness_weights)


def singularities(V, F, X, sign_symmetric=None):
    """Finds the singular vertices of a field given by its vectors (Section 3.4).

    The index of an interior vertex is the number of turns, in units of 1/N,
    that the field's vectors make around it, matched across each edge without
    integer variables by the roots of the transported polynomial (Section 3.4).

    Parameters
    ----------
    X : float array (#F, 3N), the N vectors of each face (as returned by
        :func:`design_field`); the field's coefficients are rebuilt from them.
    sign_symmetric : whether the vectors come in pairs {u, -u}; None (default)
        tells it from X: vector k + N/2 exactly -vector k in every face.

    Returns
    -------
    S : int array, the singular vertices.
    index : float array, their indices k/N (never 0).
    info : dict: ``degree``, ``index_numerators`` (the k's), and
        ``undefined_vertices`` (vertices where a vector vanishes).
    """
    return _core.singularities(V, F, X, sign_symmetric)


def principal_curvatures(V, F):
    """Estimates the principal curvatures and directions of every face.

    By a jet fit of the vertices' neighbourhoods (CGAL's Monge fitting),
    averaged per face. Curvature is positive where the surface bends away from
    the face normal; k1 >= k2; d1, d2 are unit, in the face plane, d2 = n x d1.

    Returns ``PD1, PD2`` (#F, 3), ``PV1, PV2`` (#F,) and ``info``
    (``fallback_vertices``: vertices that no jet fit determined, estimated from
    the variation of the normals).
    """
    return _core.principal_curvatures(V, F)


def sharp_edges(V, F, angle=40.0, boundary_alignment=True, minimum_feature_length=0.0, vectors_per_face=2):
    """Selects the sharp edges and the constraints that make a frame field follow them.

    An edge is sharp when the angle between the normals of its two faces exceeds
    ``angle`` degrees; with ``boundary_alignment`` the border edges count too.
    Connected sharp edges shorter than ``minimum_feature_length`` in all are
    dropped (noise). Each face along a sharp edge gets a partial constraint
    along it, up to ``vectors_per_face`` vectors.

    Returns ``E`` (#E, 2) the feature edges as vertex pairs, ``b``, ``bc`` the
    constraints (bc rows padded with NaN triples), and ``info``.
    """
    return _core.sharp_edges(V, F, angle, boundary_alignment, minimum_feature_length, vectors_per_face)


def refine_for_quad_size(V, F, quad_size, features=None, boundary_alignment=False):
    """Splits the edges longer than two quads (and the edges that join two feature vertices).

    No vertex moves: new vertices are edge midpoints. Returns ``V2, F2``,
    ``origin`` (the face of ``F`` each face of ``F2`` was cut from) and ``E2``,
    the feature edges of the refined mesh.
    """
    return _core.refine_for_quad_size(V, F, quad_size, features, boundary_alignment)


def integer_grid_map(V, F, X, edge_length=None, quads=None, features=None, boundary_alignment=False,
                     singularity_cancellation_distance=None, stiffening_keeps_integers=True):
    """Computes a seamless integer-grid map guided by a frame field (the parametrization of quad remeshing).

    Parameters
    ----------
    X : the frame field, (#F, 12) as :func:`frame_field` returns it, or (#F, 6) for u, v.
    edge_length : the quad size in mesh units: one unit of uv. Default: the
        mean edge length of the mesh.
    quads : instead of ``edge_length``, about this many quads
        (quad size sqrt(area / quads)).
    features : (#E, 2) vertex pairs of edges to put on integer iso-lines (the
        ``E`` of :func:`sharp_edges`), so that they become quad edges.
    boundary_alignment : the border also lies on integer iso-lines.
    singularity_cancellation_distance : singularities of the field closer than
        this (mesh units) are cancelled, merged or moved apart; default: the quad size.
    stiffening_keeps_integers : the stiffening rounds that remove flipped
        triangles keep the integers of the last rounding (faster); False rounds
        them again in every round (another search).

    Returns
    -------
    UV : float array (3 #F, 2), the uv of every corner; FUV : int array (#F, 3),
        row f indexes UV for the corners F[f] (as libigl's MIQ returns them):
        the map is discontinuous across the seams, by integer grid symmetries.
    info : dict: target and mean edge lengths, singular vertices, seams,
        flipped faces, and ``seam_transitions`` (#F, 3, 3): for corner k of face
        f, (rotation r in 0..3, tx, ty) such that across the edge that ends at
        F[f][k], uv in the other face = R^r uv + t (R the quarter turn); give it
        to :func:`quad_mesh`.
    """
    return _core.integer_grid_map(V, F, X, edge_length, quads, features, boundary_alignment,
                                  singularity_cancellation_distance, stiffening_keeps_integers)


def quad_mesh(V, F, UV, FUV, seam_transitions=None, keep_trimmed_boundary=False, split_components=False,
              max_input_distance=None):
    """Extracts the quad mesh of a map's integer iso-lines (after QEx, Ebke et al. 2013).

    One vertex per integer point of the map, one edge per iso-line segment
    between two of them, one quad per cell. ``seam_transitions`` (from
    :func:`integer_grid_map`'s info) gives the exact transitions; without it
    they are found from the uv. Vertices of ``V`` that no face uses are ignored.

    ``keep_trimmed_boundary``: by default only whole cells are kept, so that
    every face is a quad and the border of the result runs along iso-lines
    inside the surface. With True, the cells cut by the border of the mesh
    are kept too, as polygons bounded by the iso-lines and the border (a free
    border: the result covers the whole surface).

    A connected component whose fold-overs cannot be filled gets its
    triangles split into quads (three per triangle, through their centroids
    and edge midpoints). ``split_components``: so does a component that has
    no whole cell (smaller than a quad) or whose quads are not one quad mesh
    of it, instead of the call failing. ``max_input_distance`` (a distance in
    the units of ``V``): so does a component with an input vertex or face
    centroid farther than this from its quads. Neither goes with
    ``keep_trimmed_boundary``, whose border polygons are not split.

    Returns ``Vq`` (#Vq, 3), ``Fq`` and ``info`` (quads, irregular vertices,
    repairs, ``trimmed_polygons``, ``largest_input_distance``: the largest
    distance of an input vertex or face centroid to the quads, and the
    components split into quads: ``split_components``, of which
    ``split_small_components``, ``split_far_components`` and
    ``split_defective_components``, the others for their fold-overs). ``Fq`` is (#Q, 4); with
    ``keep_trimmed_boundary`` it is (#Q, k), k the largest number of corners of
    a face, and the rows of smaller faces end with -1. :func:`save_mesh`,
    :func:`write_html_viewer` and :func:`write_quad_mesh_ply` take such rows;
    :func:`quad_planarity` and :func:`planarize` take quads only.
    """
    return _core.quad_mesh(V, F, UV, FUV, seam_transitions, keep_trimmed_boundary, split_components,
                           max_input_distance)


def quad_planarity(Vq, Fq):
    """Returns the planarity of every quad, and a dict of its max and mean.

    The planarity of a quad is the distance between its two diagonals divided by
    their mean length (the paper's measure of planar-quad meshes, Section 5).
    """
    return _core.quad_planarity(Vq, Fq)


def planarize(Vq, Fq, V, F, threshold=0.01, max_distance_to_surface=None, number_of_iterations=None,
              gauss_newton_steps=None, crease_angle=40.0):
    """Moves the quad vertices until every quad is planar to ``threshold``, staying near the surface (V, F).

    Local-global iterations (best-fit planes, then one sparse solve with
    closeness to the triangle mesh and fairness), at most
    ``number_of_iterations`` (default 500); when they fail, at most
    ``gauss_newton_steps`` Gauss-Newton steps (default 50, 0 for none) from
    the input, over the vertices and a normal per quad
    (``info["gauss_newton_ran"]``, ``info["gauss_newton_steps"]``,
    ``info["gauss_newton_rejected_steps"]``, ``info["gauss_newton_stalled"]``
    when they stopped after three steps without progress, and where they got to:
    ``info["gauss_newton_max_planarity"]``, ``info["gauss_newton_max_distance"]``).
    ``max_distance_to_surface``
    bounds how far a vertex may end from the surface (default 5% of the mean
    quad edge), and how much farther the surface may end from the quads than
    from the input quads (``info["max_distance_to_quads"]`` and
    ``info["max_distance_to_quads_before"]``: quads that shrink away from a
    border or cut a crease are not a success); vertices on the border and on
    the surface's creases (its edges whose faces' normals make an angle above
    ``crease_angle`` degrees, 0 to 180, 180 for none) slide along them only,
    and where the border or a crease turns by more than ``crease_angle`` or
    creases meet, the vertex stays. No quad may be folded that
    was not (neither diagonal splitting it into two triangles that face the
    side of its input normal).
    When the threshold is not reached (``info["status"]`` is
    ``"DID_NOT_CONVERGE"``, ``"TOO_FAR_FROM_SURFACE"``, or ``"FOLDED_QUAD"``
    with ``info["folded_quads"]``), the quad mesh is
    returned as given, not raised: the command-line program does the same.
    ``info["left_surface"]`` is true when the iterations stopped early because
    a vertex was beyond that bound once the pull towards the surface had
    reached its floor.

    Returns ``Vq2`` (the moved vertices; ``Fq`` is unchanged) and ``info``.
    """
    return _core.planarize(Vq, Fq, V, F, threshold, max_distance_to_surface, number_of_iterations, gauss_newton_steps,
                           crease_angle)


def _area_and_mean_edge(V, F):
    p0, p1, p2 = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(p1 - p0, p2 - p0), axis=1).sum()
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    edges = np.unique(edges, axis=0)
    mean_edge = np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1).mean()
    return area, mean_edge


def _merge_constraints(rows, width):
    """Stacks (b, bc) pairs into one, bc padded with NaN triples to `width` vectors."""
    b = [np.asarray(r[0], dtype=np.int64).reshape(-1) for r in rows if len(r[0])]
    if not b:
        return None, None
    bc = []
    for r in rows:
        if len(r[0]):
            m = np.asarray(r[1], dtype=np.float64)
            pad = np.full((len(m), 3 * width - m.shape[1]), np.nan)
            bc.append(np.hstack([m, pad]))
    return np.concatenate(b), np.vstack(bc)


def quad_remesh(V, F, quads=None, edge_length=None, sharp_edges=40.0, boundary_alignment=True, conjugate=False,
                planarize=False, b=None, bc=None, curvature_constraints=None, singularity_separation=1.0,
                max_surface_distance=0.05, keep_trimmed_boundary=False, gauss_newton_steps=None, max_deviation=None):
    """Remeshes a triangle mesh into quads: the whole road, from the surface to a (planar-)quad mesh.

    The stages are those of the command-line program ``design_polyvector_field
    --mesh M --parametrize --quad-mesh Q [--conjugate] [--planarize]``, each one
    a function of this module:

    1. the quad size h: ``edge_length``, or sqrt(area / ``quads``), or by default
       the mean edge length, but at most sqrt(area / 1000) (at least about 1000 quads);
       the default is then made finer, by sqrt(2) up to 4 times, as the program makes
       it (stages 2 to 6 again at each size): on a mesh of one component, where a
       quad would stay folded or a component split into quads on its triangles
       because its fold-overs cannot be filled (stage 6); and while an input
       vertex or face centroid is farther from the quads than ``max_deviation``
       bounding-box diagonals (default 0.009 with the default size; with
       ``edge_length`` or ``quads``, or with ``keep_trimmed_boundary``, whose
       border polygons are not measured, no bound unless given, and it cannot
       be given with ``keep_trimmed_boundary``), until a size comes
       no closer, by a tenth, than every size before (one such size ends the
       search, two in a row on a mesh of one component). At the last size, the
       components still farther than the bound get their triangles split into
       quads (:func:`quad_mesh`'s ``max_input_distance``);
    2. the feature edges (:func:`sharp_edges`: dihedral angle above
       ``sharp_edges`` degrees, None for none; the border with
       ``boundary_alignment``), creases shorter than 3h dropped, and the mesh
       refined where its edges are longer than 2h (:func:`refine_for_quad_size`);
    3. the constraints: ``b``, ``bc`` (on the faces of ``F``, passed to the
       faces cut from them), then partial constraints along the feature edges of
       the refined mesh on the faces not yet constrained;
    4. the frame field (:func:`frame_field`, ``conjugate`` and
       ``curvature_constraints`` passed on): conjugate for planar quads (Section 4.3);
    5. the integer-grid map (:func:`integer_grid_map`, features on integer
       iso-lines, singularities closer than ``singularity_separation`` quads cancelled);
    6. the quad mesh (:func:`quad_mesh`, with the map's exact transitions,
       components that it cannot follow split into quads on their triangles,
       ``split_components=True`` unless ``keep_trimmed_boundary``, as in the program); when
       it reports ``UNREPAIRABLE_FOLD_OVER`` on a map without flipped
       triangles, the map is computed again with ``stiffening_keeps_integers=False``
       and the quads extracted from it; ``keep_trimmed_boundary`` is passed
       on (with True, the cells cut by a free border are kept as polygons,
       rows of ``Fq`` padded with -1; it goes with ``boundary_alignment=False``
       and cannot be combined with ``planarize``);
    7. with ``planarize`` (True for the paper's 1%, or a threshold),
       :func:`planarize`, each vertex kept within ``max_surface_distance``
       mean quad edges of the surface (``gauss_newton_steps`` passed on, and
       ``sharp_edges`` as its ``crease_angle``);
       then the planarity. A planarization
       that does not reach the threshold leaves the quads as extracted
       (``info["planarization"]["status"]`` says why), as in the program.

    The defaults are the program's for a mesh given with ``--mesh``: sharp
    edges above 40 degrees and the border on quad edges (its bundled run without
    ``--mesh`` keeps a free border: ``sharp_edges=None, boundary_alignment=False``),
    singularity separation 1, surface distance 5% of the mean quad edge.
    Differences from the command-line program: the map receives the field as
    its vectors (the roots, rebuilt into coefficients, equal up to rounding), and
    always the quad size h (the program lets the map compute its own mean edge
    length when h is that mean on an unrefined mesh: the same value up to rounding).

    Returns
    -------
    Vq, Fq : the quad mesh.
    info : dict: ``quad_size`` (the last size), the stages' dicts (``field``, ``map``,
        ``quads``, ``planarization``) at that size, ``planarity`` (max, mean),
        ``map_recomputed``, ``V``, ``F`` of the refined triangle mesh and ``X``
        the frame field on it (what :func:`write_html_viewer` draws with the quads);
        ``deviation``: the largest distance of an input vertex or face centroid to
        the extracted quads, in bounding-box diagonals; ``max_deviation``: the
        bound it was held to (None: none); ``finer_sizes``: the (size, deviation)
        of the sizes left for a finer one because the quads were too far;
        ``unfilled_sizes``: the (size, folded) of those left because of
        fold-overs (folded: a quad stayed folded); ``split_at``: the deviation
        at the last size before its far components were split (None: none was).
    """
    V = np.asarray(V, dtype=np.float64)
    F = np.asarray(F)
    if V.ndim != 2 or V.shape[1] != 3:
        raise _refuse("quad_remesh: V: expected shape (n, 3), got %s" % (V.shape,))
    if F.ndim != 2 or F.shape[1] != 3 or F.dtype.kind not in "iu" or len(F) == 0:
        raise _refuse("quad_remesh: F: expected a non-empty integer array of shape (n, 3), got %s %s" % (F.dtype, F.shape))
    if F.min() < 0 or F.max() >= len(V):
        raise _refuse("quad_remesh: F: an index is not a vertex of V (0..%d)" % (len(V) - 1))
    if edge_length is not None and quads is not None:
        raise _refuse("quad_remesh: give edge_length or quads, not both")
    if not isinstance(keep_trimmed_boundary, (bool, np.bool_)):
        raise _refuse("quad_remesh: keep_trimmed_boundary: expected True or False", "INVALID_PARAMETER")
    if keep_trimmed_boundary and planarize:
        raise _refuse("quad_remesh: planarize takes quads only, and keep_trimmed_boundary keeps the border's "
                      "polygons: give one of them", "INVALID_PARAMETER")
    # 1. the quad size, and the bound on the distance of the input from the quads
    area, mean_edge = _area_and_mean_edge(V, F)
    default_size = edge_length is None and quads is None
    if edge_length is not None:
        h0 = float(edge_length)
    elif quads is not None:
        h0 = math.sqrt(area / float(quads))
    else:
        h0 = min(mean_edge, math.sqrt(area / 1000.0))
    if not (h0 > 0 and math.isfinite(h0)):
        raise _refuse("quad_remesh: no quad size (a mesh without area, or a non-positive edge_length / quads)")
    if max_deviation is not None:
        if isinstance(max_deviation, (bool, np.bool_)) or not isinstance(max_deviation, (int, float, np.number)):
            raise _refuse("quad_remesh: max_deviation: expected a number, got %r" % (max_deviation,),
                          "INVALID_PARAMETER")
        max_deviation = float(max_deviation)
        if not (0 < max_deviation <= 1):
            raise _refuse("quad_remesh: max_deviation must be a fraction of the bounding-box diagonal in (0, 1], "
                          "got %r" % max_deviation, "INVALID_PARAMETER")
        if keep_trimmed_boundary:
            raise _refuse("quad_remesh: max_deviation is measured on whole quads, and keep_trimmed_boundary keeps "
                          "the border's polygons: give one of them", "INVALID_PARAMETER")
    # the border's polygons are not measured, nor split: with them, no bound
    bounded = (default_size and not keep_trimmed_boundary) or max_deviation is not None
    bound = max_deviation if max_deviation is not None else _DEFAULT_MAX_DEVIATION
    used = V[np.unique(F)]
    diagonal = float(np.linalg.norm(used.max(axis=0) - used.min(axis=0)))
    crease = float(sharp_edges) if sharp_edges is not None else 179.9
    # 2.-6. at each size; with the default size, finer sizes as the program makes them
    tries, unfilled, split_at = [], [], None
    sizes_without_progress = 0
    attempt = 0
    while True:
        h = h0 * _FINER_SIZE ** attempt
        road = _quad_remesh_at_size(V, F, h, sharp_edges, crease, boundary_alignment, conjugate, b, bc,
                                    curvature_constraints, singularity_separation, keep_trimmed_boundary)
        components = road["field"]["components"]
        may_refine = default_size and attempt < _FINER_SIZES and components == 1
        if road["folded"] is not None:
            if not may_refine:
                raise road["folded"]
            unfilled.append((h, True))
            attempt += 1
            continue
        quad_info = road["quads"]
        if may_refine and _unfilled_components(quad_info) > 0:
            unfilled.append((h, False))
            attempt += 1
            continue
        deviation = quad_info["largest_input_distance"] / diagonal
        if bounded and deviation > bound:
            closest = min([t[1] for t in tries], default=math.inf)
            sizes_without_progress = 0 if deviation < 0.9 * closest else sizes_without_progress + 1
            patience = 2 if components == 1 else 1
            if default_size and attempt < _FINER_SIZES and sizes_without_progress < patience:
                tries.append((h, deviation))
                attempt += 1
                continue
            # the components farther than the bound split into quads on their triangles, from the same map
            split_at = deviation
            road["Vq"], road["Fq"], quad_info = quad_mesh(road["V"], road["F"], road["UV"], road["FUV"],
                                                          road["map"]["seam_transitions"], keep_trimmed_boundary,
                                                          split_components=True, max_input_distance=bound * diagonal)
            road["quads"] = quad_info
            deviation = quad_info["largest_input_distance"] / diagonal
            if deviation > bound:  # not expected: the split components lie on their triangles
                raise _refuse("quad_remesh: an input point lies %g%% of the bounding-box diagonal from the quads "
                              "after the components farther than %g%% were split into quads on their triangles"
                              % (100 * deviation, 100 * bound), "TOO_FAR_FROM_SURFACE")
        break
    V2, F2, X, Vq, Fq = road["V"], road["F"], road["X"], road["Vq"], road["Fq"]
    # 7. planarization
    planarization_info = None
    if planarize:
        threshold = 0.01 if planarize is True else float(planarize)
        edges = np.unique(np.sort(np.concatenate([Fq[:, [k, (k + 1) % 4]] for k in range(4)]), axis=1), axis=0)
        mean_quad_edge = np.linalg.norm(Vq[edges[:, 0]] - Vq[edges[:, 1]], axis=1).mean()
        Vq, planarization_info = globals()["planarize"](Vq, Fq, V2, F2, threshold=threshold,
                                                        max_distance_to_surface=max_surface_distance * mean_quad_edge,
                                                        gauss_newton_steps=gauss_newton_steps,
                                                        crease_angle=crease)
    # the planarity of the quads (with keep_trimmed_boundary, of the faces with 4 corners)
    quad_rows = Fq[(Fq[:, :4] >= 0).all(axis=1) & ((Fq[:, 4:] < 0).all(axis=1))][:, :4]
    _, planarity = quad_planarity(Vq, quad_rows)
    info = {
        "quad_size": h, "V": V2, "F": F2, "X": X, "field": road["field"], "map": road["map"], "quads": quad_info,
        "planarization": planarization_info, "planarity": planarity, "map_recomputed": road["map_recomputed"],
        "deviation": deviation, "max_deviation": bound if bounded else None, "finer_sizes": tries,
        "unfilled_sizes": unfilled, "split_at": split_at,
    }
    return Vq, Fq, info


# With the default quad size, the quads are made finer by this factor (twice the
# quads), at most _FINER_SIZES times, as the command-line program makes them.
_FINER_SIZE = 0.70710678118654752  # 1 / sqrt(2), the program's constant to the last bit
_FINER_SIZES = 4
_DEFAULT_MAX_DEVIATION = 0.009  # of the bounding-box diagonal


def _unfilled_components(quad_info):
    """The components split into quads because their fold-overs could not be filled."""
    return (quad_info["split_components"] - quad_info["split_small_components"]
            - quad_info["split_far_components"] - quad_info["split_defective_components"])


def _quad_remesh_at_size(V, F, h, sharp_edges, crease, boundary_alignment, conjugate, b, bc,
                         curvature_constraints, singularity_separation, keep_trimmed_boundary):
    """Stages 2 to 6 of :func:`quad_remesh` at the quad size h: a dict of what they made. A quad folded
    against the surface leaves "folded" set to the error (and no quads)."""
    # 2. features and refinement
    with_features = sharp_edges is not None or boundary_alignment
    minimum_crease = 3.0 * h
    if with_features:
        E = globals()["sharp_edges"](V, F, crease, boundary_alignment, minimum_crease)[0]
        V2, F2, origin, _ = refine_for_quad_size(V, F, h, E, boundary_alignment)
    else:
        V2, F2, origin, _ = refine_for_quad_size(V, F, h)
    # 3. constraints: the user's, then the feature edges' on the faces left
    rows = []
    if b is not None or bc is not None:
        b0 = np.asarray(b).reshape(-1)
        bc0 = np.asarray(bc, dtype=np.float64)
        if bc0.ndim != 2 or len(bc0) != len(b0):
            raise _refuse("quad_remesh: bc: expected one row per entry of b")
        row_of = {int(f): i for i, f in enumerate(b0)}
        new_faces = [f for f in range(len(F2)) if int(origin[f]) in row_of]
        rows.append((np.array(new_faces, dtype=np.int64), bc0[[row_of[int(origin[f])] for f in new_faces]]))
    features = None
    if with_features:
        features, b_sharp, bc_sharp, _ = globals()["sharp_edges"](V2, F2, crease, boundary_alignment, minimum_crease)
        taken = set(int(f) for f in rows[0][0]) if rows else set()
        keep = [i for i, f in enumerate(b_sharp) if int(f) not in taken]
        rows.append((b_sharp[keep], bc_sharp[keep]))
    b2, bc2 = _merge_constraints(rows, 2)
    # 4. the frame field
    X, field_info = frame_field(V2, F2, b2, bc2, curvature_constraints=curvature_constraints, conjugate=conjugate)
    # 5. the map, 6. the quads (a component whose fold-overs cannot be filled split into quads on its triangles)
    map_args = dict(edge_length=h, features=features, boundary_alignment=boundary_alignment,
                    singularity_cancellation_distance=singularity_separation * h)
    UV, FUV, map_info = integer_grid_map(V2, F2, X, **map_args)
    road = {"V": V2, "F": F2, "X": X, "field": field_info, "map_recomputed": False, "folded": None,
            "Vq": None, "Fq": None, "quads": None}
    for retry in (False, True):
        try:
            road["Vq"], road["Fq"], road["quads"] = quad_mesh(V2, F2, UV, FUV, map_info["seam_transitions"],
                                                              keep_trimmed_boundary,
                                                              split_components=not keep_trimmed_boundary)
            break
        except Error as e:
            if e.code == "FOLDED_QUAD":
                road["folded"] = e
                break
            if retry or e.code != "UNREPAIRABLE_FOLD_OVER" or map_info["flipped_faces"] != 0:
                raise
            UV, FUV, map_info = integer_grid_map(V2, F2, X, stiffening_keeps_integers=False, **map_args)
            road["map_recomputed"] = True
    road.update({"UV": UV, "FUV": FUV, "map": map_info})
    return road


def _singularity_rows(singularities):
    """The singularities as a (k, 2) integer array of rows (vertex, index numerator)."""
    if isinstance(singularities, tuple) and len(singularities) == 3 and isinstance(singularities[2], dict):
        vertex, _, info = singularities  # as singularities() returns them
        return np.column_stack((np.asarray(vertex, dtype=np.int64).reshape(-1),
                                np.asarray(info["index_numerators"], dtype=np.int64).reshape(-1)))
    return singularities


def write_html_viewer(filename, V, F, X, singularities=None, Vq=None, Fq=None, constrained_faces=None,
                      page_title=None, max_glyph_faces=None, planarity_colour_range=None, three_js_directory=None):
    """Writes one self-contained web page that shows a field and, if given, its quad mesh.

    The page works offline: it fetches nothing, and holds the data and the code
    that draws it, three.js (r111) and its OrbitControls included, copied from
    the files of Debian's ``libjs-three`` when the page is written. It has
    orbit controls, a check box per layer, and a title with the figures: the
    number of faces and of singularities and, with quads, the number of quads
    and their largest and mean planarity. The layers (the manual's section "A
    web page of every result, and coloured PLY" describes them) are:

    - the surface ``V, F``;
    - the field ``X`` (#F, 3N), as :func:`design_field` or :func:`frame_field`
      return it: short lines from each face's centroid along its N vectors (a
      field of pairs {u, -u} as N/2 lines through the centroid); above
      ``max_glyph_faces`` faces (default 20000) on a subsample of about that many;
    - the singularities: a ball per singular vertex, red for a positive index
      and blue for a negative one. ``singularities`` is what
      :func:`singularities` returns, or an integer array of rows (vertex, index
      numerator k of the index k/N); None (default) finds them from ``X`` as
      :func:`singularities` does;
    - the constrained faces (``constrained_faces``, e.g. the ``b`` of the
      design), in orange;
    - the quad mesh ``Vq, Fq`` (rows of polygons padded with -1 allowed), each
      face coloured by its planarity (:func:`quad_planarity`'s measure) from
      blue (planar) to red at ``planarity_colour_range`` (default: the
      largest planarity), with a colour bar, as in the paper's planar-quad
      figures (Section 5).

    ``page_title`` (default "CGAL Polyvector Fields") comes before the figures.
    ``three_js_directory`` is the folder of three.js r111 that holds
    ``three.min.js`` and ``examples/js/controls/OrbitControls.js`` (default
    ``/usr/share/javascript/three``, where Debian's ``libjs-three`` puts them).

    The page is written to a temporary file in the same folder and renamed
    when complete. Bad input, or a missing three.js file (the message gives its
    path, the code is ``CANNOT_OPEN_FILE``), raises :class:`Error` and leaves
    no file behind (and ``filename`` as it was).
    """
    if three_js_directory is not None and not isinstance(three_js_directory, str):
        three_js_directory = os.fspath(three_js_directory)
    _core.write_html_viewer(os.fspath(filename), V, F, X, _singularity_rows(singularities), Vq, Fq,
                            constrained_faces, page_title, max_glyph_faces, planarity_colour_range,
                            three_js_directory)


def write_quad_mesh_ply(filename, Vq, Fq, planarity_colour_range=None):
    """Writes a quad mesh as PLY with a colour and a quality per face: its planarity, for MeshLab.

    ``quality`` is the planarity of each quad (:func:`quad_planarity`'s
    measure, -1 for a face that is not a quad) and ``red, green, blue`` its
    colour on the page's scale, blue (planar) to red at
    ``planarity_colour_range`` (default: the largest planarity). Rows of
    ``Fq`` may be polygons padded with -1. Written through a temporary file:
    on failure :class:`Error` is raised and no file is left behind.
    """
    _core.write_quad_mesh_ply(os.fspath(filename), Vq, Fq, planarity_colour_range)
