#pragma once
// Small meshes and helpers shared by the tests.
#include <Eigen/Core>
#include <functional>
#include <random>
#include <string>

#include "akvf/mesh.h"

namespace akvf::test {

// An nx by ny grid of the unit square (a disk), z = 0, optionally with the
// interior vertices jittered by up to `jitter` of the spacing.
TriMesh grid_disk(int nx, int ny, double jitter = 0, unsigned seed = 1);

// The grid lifted onto a bumpy height field (not developable).
TriMesh bumpy_disk(int nx, int ny);

// An n by n torus grid (closed, genus 1), radii 2 and 1, without its last
// `dropped_faces` faces (1: a punctured torus, one boundary loop).
TriMesh torus(int n, int dropped_faces = 0);

// A closed genus-0 surface: an octahedron subdivided `rounds` times, its
// vertices on the unit sphere.
TriMesh sphere(int rounds);

// A square annulus: a 4x4 grid without its centre cell (two boundary loops).
TriMesh annulus();

// The two meshes side by side as one (b's vertices after a's, shifted by
// `offset` along x).
TriMesh side_by_side(const TriMesh& a, const TriMesh& b, double offset);

// The unit cube split into n^3 cells of 6 tets each (Kuhn triangulation),
// every tet positively oriented.
TetMesh tet_grid(int n);

// The tet mesh's rest positions stretched by (1.3, 0.9, 1.1) and jittered by
// up to 0.03: a valid but distorted deformation (interleaved, 3|V|).
Eigen::VectorXd distorted_tet_positions(const TetMesh& mesh, unsigned seed);

// A planar UV map of grid_disk's connectivity: the grid with random interior
// jitter, never inverted for jitter < 0.3.
Eigen::MatrixXd jittered_uv(const TriMesh& mesh, double jitter, unsigned seed);

// Parse a mesh from text as if it were a file of the given name.
TriMesh parse_mesh(const std::string& text, const std::string& name);

// The folder of real meshes ($AKVF_DATA_DIR or ../shared/meshes beside the
// source tree), or "" when it is absent.
std::string data_dir();

// The what() of the akvf::Error that f throws, or "" if it throws nothing.
std::string error_message(const std::function<void()>& f);

// The dimension of a symmetric matrix's null space: its eigenvalues below
// 1e-10 of the largest. Sets *psd to whether none lies below minus that, and
// *gap to the first eigenvalue above the null space over the threshold.
int null_space_dimension(const Eigen::MatrixXd& K, bool* psd, double* gap);

// Prints "SKIPPED: reason" (ctest marks the test skipped on that text).
void skip(const std::string& reason);

}  // namespace akvf::test
