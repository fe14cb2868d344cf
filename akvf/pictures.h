#pragma once
// Pictures of a UV map given as arrays, as `akvf param` writes them: the
// self-contained HTML view (the checkerboard on the surface, the layout,
// a switch to colour both by distortion, the run's summary) and the layout
// as PNG or SVG. Faces are coloured by their symmetric Dirichlet excess
// D(J_f) - 4 under the map scaled to the surface's area.
//   uv        #V by 2 (one row per vertex), or #T by 2 with uv_faces
//   uv_faces  #F by 3 rows of uv; empty = F
// Every file is written atomically; OutputError when it cannot be.
#include <Eigen/Core>
#include <string>

#include "akvf/mesh.h"

namespace akvf {

// True when this build embeds three.js (Debian's libjs-three was found at
// configure time); write_view needs it.
bool view_available();
// OptionsError saying what to install when !view_available().
void require_view();

// The HTML view. summary_json: a run's summary as JSON text (an object, as
// `akvf param --summary` writes it), shown beside the pictures; "" for none.
// Meshes beyond 500 000 faces are decimated for display, and the page says
// so. Returns the number of faces shown. OptionsError without three.js.
int write_view(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
               const Eigen::MatrixXi& uv_faces = Eigen::MatrixXi(), const std::string& title = "",
               const std::string& summary_json = "");

// The layout as a PNG image whose longer side has `size` pixels (16 to 16384).
void write_layout_png(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
                      const Eigen::MatrixXi& uv_faces = Eigen::MatrixXi(), int size = 1024);

// The layout as SVG, with `title` above it.
void write_layout_svg(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
                      const Eigen::MatrixXi& uv_faces = Eigen::MatrixXi(), const std::string& title = "");

}  // namespace akvf
