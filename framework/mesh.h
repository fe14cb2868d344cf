#pragma once
// Mesh containers. Shapes follow libigl's convention.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace akvf {

// A triangle mesh in R^3.
//   V  #V by 3 vertex positions
//   F  #F by 3 vertex indices (0-based), counter-clockwise seen from outside
struct TriMesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;

  int num_vertices() const { return static_cast<int>(V.rows()); }
  int num_faces() const { return static_cast<int>(F.rows()); }
};

// A tetrahedral mesh in R^3.
//   V  #V by 3 vertex positions
//   T  #T by 4 vertex indices (0-based), positively oriented after validation:
//      (x1 - x0) . ((x2 - x0) x (x3 - x0)) > 0
struct TetMesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi T;

  int num_vertices() const { return static_cast<int>(V.rows()); }
  int num_tets() const { return static_cast<int>(T.rows()); }
};

// Non-fatal findings of readers and validation, for the program to print.
using Warnings = std::vector<std::string>;

}  // namespace akvf
