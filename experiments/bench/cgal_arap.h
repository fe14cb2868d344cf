#pragma once
// CGAL's ARAP parameterizer (Surface_mesh_parameterization::ARAP_parameterizer_3,
// the local/global method of Liu et al. 2008) as a peer of akvf_speed: its
// own start (mean value coordinates for one boundary), its own stopping rule
// (at most 50 iterations, relative change of its energy below 1e-6), and
// lambda large enough that every local step is ARAP's rotation (the pure-ARAP
// end of its family). Built only where Debian's CGAL is found.
#include <Eigen/Core>
#include <string>

namespace akvf::bench {

struct CgalArapRun {
  Eigen::MatrixXd uv;        // #V by 2, the final map (after CGAL's post-processing, if it ran; its last on an error)
  double seconds = 0;        // of the timed run
  int iterations = 0;        // local/global iterations it took
  int initial_inverted = 0;  // triangles with area <= 0 in its start
  int max_iterate_inverted = 0;  // the most over its iterates
  bool post_processed = false;   // CGAL post-processed its last iterate (not one-to-one); may fail: `error`
  std::string error;             // CGAL's error message; empty when it succeeded
};

// V (#V by 3), F (#F by 3): one disk (a triangle mesh with one boundary loop).
// Runs twice: once timed, once writing every iterate (to a temporary folder,
// then removed) to count its inverted triangles.
CgalArapRun run_cgal_arap(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace akvf::bench
