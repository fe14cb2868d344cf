// The timed run of CGAL's ARAP parameterizer (cgal_arap.h); the iterates are
// counted by cgal_arap_iterates.cpp.
#include "experiments/bench/cgal_arap.h"

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <chrono>

#include "experiments/bench/cgal_arap_iterates.h"
#include "experiments/bench/cgal_arap_mesh.h"

namespace akvf::bench {

CgalArapRun run_cgal_arap(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  namespace smp = CGAL::Surface_mesh_parameterization;
  CgalArapRun run;
  cgal::Mesh mesh = cgal::make_mesh(V, F);
  if (mesh.number_of_faces() != static_cast<std::size_t>(F.rows())) {
    run.error = "the mesh is not a manifold surface CGAL can build";
    return run;
  }
  cgal::UvMap uv = mesh.add_property_map<cgal::Vertex, cgal::Kernel::Point_2>("v:uv").first;
  smp::ARAP_parameterizer_3<cgal::Mesh> parameterizer(cgal::kArapLambda);
  const auto start = std::chrono::steady_clock::now();
  const smp::Error_code status = smp::parameterize(mesh, parameterizer, cgal::longest_border(mesh), uv);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // On an error CGAL leaves its last map in `uv`: it is scored all the same.
  if (status != smp::OK) run.error = smp::get_error_message(status);
  run.uv.resize(V.rows(), 2);
  for (int i = 0; i < V.rows(); ++i) {
    const auto& p = uv[cgal::Vertex(i)];
    run.uv.row(i) << p.x(), p.y();
  }
  const ArapIterates iterates = count_arap_iterates(V, F);
  run.iterations = iterates.iterations;
  run.initial_inverted = iterates.initial_inverted;
  run.max_iterate_inverted = iterates.max_inverted;
  run.post_processed = iterates.post_processed;
  if (iterates.error != run.error)
    run.error += (run.error.empty() ? "" : "; ") + ("counting its iterates: " + iterates.error);
  return run;
}

}  // namespace akvf::bench
