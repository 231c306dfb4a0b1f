// Copyright (c) 2026 CGAL Polyvector Fields contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): CGAL Polyvector Fields developers
//
// This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
// It is not part of CGAL.

// design_polyvector_field: the command-line designer.
//
// Reads a mesh and constraints, designs the smoothest N-PolyVector field, and
// writes the field (.rawfield), its singularities (.sings) and a VTK file for
// ParaView. Frame fields (N = 4, sign-symmetric) can then be optimised to
// bound their angles or to be conjugate (paper Section 4), and guide a
// seamless integer-grid map (--parametrize, written as an OBJ file with one
// texture coordinate per corner). With no argument it
// designs a frame field on the bundled architectural mesh from its 84 bundled
// constraints and writes output/inspired_mesh.{rawfield,sings,vtk}. Run with
// --help for the options.
//
// A polygon mesh or a polygon soup is repaired into a triangle mesh first (see
// IO::read_triangle_mesh()), and the summary says what changed; --no-repair
// refuses such a mesh instead. Errors are reported on one line of standard
// error with a non-zero exit status: 2 for a bad command line, 1 otherwise.
// Outputs are written all or none: every destination is checked before the
// work starts, and the files are published only once every stage succeeded.
//
// The program is one translation unit made of these files: options.h (the
// options, --help and the command line), output_files.h (the outputs,
// written all or none), stages.h (the stages of a run), summary.h (what the
// run reports), and this file, which calls them in order.

#include "common.h"
#include "options.h"
#include "output_files.h"
#include "stages.h"
#include "summary.h"

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <limits>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace pvf_cli {

// With the default quad size, the quads are made finer, by this factor, until every
// input vertex and face centroid is within the deviation bound of them.
constexpr double finer_size = 0.70710678118654752;  // 1 / sqrt(2): twice the quads
constexpr std::size_t finer_sizes = 4;
constexpr double default_max_deviation = 0.009;  // of the bounding-box diagonal

int run(const Options& o)
{
  Stopwatch clock;
  Output_files outputs(o);
  Sizing sizing;
  std::size_t sizes_without_progress = 0;  // default sizes in a row that did not bring the quads closer
  sizing.bound = o.max_deviation >= 0 ? o.max_deviation : default_max_deviation;
  for(std::size_t attempt = 0;; ++attempt)
  {
    Input_mesh input = load_mesh(o);
    clock.lap("load mesh");
    const Quad_size size = choose_quad_size(o, input, std::pow(finer_size, double(attempt)));
    if(size.refined())
      clock.lap("refinement");
    // The frames, numbering and connection of the mesh, built once for every stage.
    const Bundle bundle(input.tm);
    check(bundle.status(), "mesh '" + o.mesh + "'");
    clock.lap("frames and connection");
    Curvature curvature;
    const Constraint_set constraints = gather_constraints(o, input, size, bundle, curvature, clock);
    const Field field = design_field(o, input.tm, bundle, constraints, curvature, clock);
    const Analysis analysis = analyse_field(o, input.tm, bundle, field, curvature, clock);
    Parametrization param = parametrize(o, input.tm, size, constraints, field, clock);
    Quad_stage quads;
    try
    {
      // A map without flipped faces whose extraction still finds fold-overs it
      // cannot repair (degenerate triangles): the map again, with the integers
      // rounded in every stiffening round (another search). A map with flipped
      // faces had that search already (compute_integer_grid_map()).
      // On a mesh of one component, with the default size and finer sizes
      // left, fold-overs that the extraction cannot fill (the component split
      // into quads on its triangles, or a quad left folded against the
      // surface) send the whole road to the next finer size. Where the
      // stiffening ends with flipped faces, which fold-overs remain depends
      // on the last bits of the input: cow.off and camel_b.obj of libigl's
      // tutorial data, scaled by 1 +- 1e-12 and 1 + 3e-12, gave quads in 4 of
      // those 6 runs; in the other two, the component split into quads on its
      // triangles, or a folded quad (an error). Not with several components,
      // which share one size: on truck.obj (66 components) some stayed split
      // at every size, and the four finer sizes took the run from 90 s to 242 s.
      const bool may_refine = size.default_size && attempt < finer_sizes && field.components == 1;
      if(!make_quad_mesh(o, input.tm, bundle, param, quads, clock, param.result.flipped_faces == 0, 0, may_refine))
      {
        param = parametrize(o, input.tm, size, constraints, field, clock, false);
        quads = Quad_stage();
        make_quad_mesh(o, input.tm, bundle, param, quads, clock, false, 0, may_refine);
      }
      if(may_refine && (quads.folded || (quads.computed && unfilled_components(quads.extraction) > 0)))
      {
        sizing.unfilled.emplace_back(size.h, quads.folded);
        continue;
      }
      // How far the quads are from the input. With the default size, finer quads
      // until they are within the bound, but not after a size that did not bring
      // them closer (by a tenth at least) than every size before; on a mesh of one
      // component, not after two such sizes in a row. How far a size leaves the
      // quads does not always fall with the size (decimated-knight.off of libigl's
      // tutorial data: 1.76%, 2.21%, 1.09%, then 0.60% of the diagonal, for a
      // bound of 0.9%), and one component split into quads on its triangles is
      // the whole mesh lost; several components share one size, which the
      // farthest of them sets, and are split one by one (truck.obj: 26 of its 66
      // after four sizes and 97 s). Then, at the last size (or at a size given
      // with a bound), the components that the quads do not follow within the
      // bound are split into quads on their triangles, from the same map.
      const bool bounded = size.default_size || o.max_deviation >= 0;
      const double diagonal = bounding_box_diagonal(input.tm);
      if(quads.computed && bounded)
      {
        sizing.deviation = quads.extraction.largest_input_distance / diagonal;
        if(sizing.deviation > sizing.bound)
        {
          double closest = std::numeric_limits<double>::infinity();
          for(const auto& t : sizing.tries)
            closest = (std::min)(closest, t.second);
          sizes_without_progress = sizing.deviation < 0.9 * closest ? 0 : sizes_without_progress + 1;
          const std::size_t patience = field.components == 1 ? 2 : 1;
          if(size.default_size && attempt < finer_sizes && sizes_without_progress < patience)
          {
            sizing.tries.emplace_back(size.h, sizing.deviation);
            continue;
          }
          sizing.split_at = sizing.deviation;
          quads = Quad_stage();
          make_quad_mesh(o, input.tm, bundle, param, quads, clock, false, sizing.bound * diagonal);
          sizing.deviation = quads.extraction.largest_input_distance / diagonal;
          if(sizing.deviation > sizing.bound)  // not expected: the split components lie on the surface
            throw Failure("quad mesh: an input point lies " + std::to_string(100 * sizing.deviation) +
                          "% of the bounding-box diagonal from the quads, beyond the bound " +
                          std::to_string(100 * sizing.bound) + "%");
        }
      }
    }
    catch(const Failure&)
    {
      // What the stages before it made (the map's flips and features, say), so
      // that the error that follows can be read against them; no file is written.
      print_summary(o, input, size, sizing, constraints, field, analysis, param, quads, outputs, clock, false);
      throw;
    }
    write_outputs(o, input.tm, constraints, analysis, param, quads, outputs, clock);
    print_summary(o, input, size, sizing, constraints, field, analysis, param, quads, outputs, clock);
    return EXIT_SUCCESS;
  }
}

} // namespace pvf_cli

int main(int argc, char** argv)
{
#ifdef __GLIBC__
  // The map's solves allocate and free dense blocks of tens of megabytes
  // (CHOLMOD's results, the Schur complement's right-hand sides): above
  // glibc's mmap threshold (at most 32 MB, adaptive) each one is a fresh
  // mapping whose pages fault in again, and page faults are most of the
  // integer rounding's time on the bunny (2.1 s -> 1.2 s without them, whole
  // run 7.1 s -> 6.2 s, same peak memory). Keep such blocks in the heap and
  // give memory back to the system only at exit. A process-wide choice, so
  // it is the program's, not the library's.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  try
  {
    return pvf_cli::run(pvf_cli::parse_options(argc, argv));
  }
  catch(const pvf_cli::Failure& failure)
  {
    std::cerr << "design_polyvector_field: " << failure.what() << std::endl;
    return failure.status;
  }
  catch(const std::exception& e)
  {
    std::cerr << "design_polyvector_field: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
