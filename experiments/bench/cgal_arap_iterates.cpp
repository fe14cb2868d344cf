#define CGAL_SMP_ARAP_DEBUG
#include "experiments/bench/cgal_arap_iterates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "experiments/bench/cgal_arap_mesh.h"

namespace akvf::bench {

namespace {

namespace fs = std::filesystem;

// Triangles of an OFF map (u v 0 per vertex) whose signed area is not of the
// sign of the total: the inverted ones, whichever way the map is mirrored.
int inverted_in_off(const fs::path& file) {
  std::ifstream in(file);
  std::string header;
  int num_vertices = 0, num_faces = 0, num_edges = 0;
  in >> header >> num_vertices >> num_faces >> num_edges;
  std::vector<double> u(num_vertices), v(num_vertices);
  double w;
  for (int i = 0; i < num_vertices; ++i) in >> u[i] >> v[i] >> w;
  std::vector<double> area(num_faces);
  double total = 0;
  for (int f = 0; f < num_faces; ++f) {
    int n, a, b, c;
    in >> n >> a >> b >> c;
    area[f] = (u[b] - u[a]) * (v[c] - v[a]) - (u[c] - u[a]) * (v[b] - v[a]);
    total += area[f];
  }
  int inverted = 0;
  for (double a : area) inverted += !(a * total > 0);
  return in ? inverted : -1;
}

}  // namespace

ArapIterates count_arap_iterates(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  namespace smp = CGAL::Surface_mesh_parameterization;
  ArapIterates result;
  Mesh mesh = cgal::make_mesh<Mesh>(V, F);
  auto uv = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  const auto border = cgal::longest_border(mesh);

  // CGAL writes into the working folder: a fresh temporary one, removed after.
  const fs::path previous = fs::current_path();
  fs::path folder = fs::temp_directory_path() / ("akvf_cgal_" + std::to_string(std::random_device{}()));
  fs::create_directories(folder);
  fs::current_path(folder);
  smp::ARAP_parameterizer_3<Mesh> parameterizer(cgal::kArapLambda);
  const smp::Error_code status = smp::parameterize(mesh, parameterizer, border, uv);
  fs::current_path(previous);
  if (status != smp::OK) result.error = smp::get_error_message(status);
  result.initial_inverted = inverted_in_off(folder / "ARAP_initial_param.off");
  for (int k = 1; fs::exists(folder / ("ARAP_iteration_" + std::to_string(k) + ".off")); ++k) {
    result.iterations = k;
    result.max_inverted =
        std::max(result.max_inverted, inverted_in_off(folder / ("ARAP_iteration_" + std::to_string(k) + ".off")));
  }
  result.post_processed = fs::exists(folder / "ARAP_final_post_processing.off");
  fs::remove_all(folder);
  return result;
}

}  // namespace akvf::bench
