// The pictures of a map given as arrays (akvf/pictures.h).
#include "akvf/error.h"
#include "akvf/mesh_io.h"
#include "akvf/pictures.h"
#include "io/json_text.h"
#include "pictures/html_view.h"
#include "pictures/map_distortion.h"
#include "pictures/uv_png.h"
#include "pictures/uv_svg.h"

namespace akvf {

namespace {

const Eigen::MatrixXi& corners_of(const TriMesh& mesh, const Eigen::MatrixXi& uv_faces) {
  return uv_faces.size() == 0 ? mesh.F : uv_faces;
}

Eigen::VectorXd excess_distortion(const TriMesh& mesh, const Eigen::MatrixXd& uv, const Eigen::MatrixXi& corners) {
  check_corner_uv(mesh, uv, corners);
  return map_distortion(mesh, uv, corners).value.array() - 4;
}

}  // namespace

bool view_available() { return html_view_available(); }

void require_view() { require_html_view(); }

int write_view(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv, const Eigen::MatrixXi& uv_faces,
               const std::string& title, const std::string& summary_json) {
  require_html_view();
  ViewContent view;
  view.mesh = mesh;
  view.uv = uv;
  view.uv_faces = corners_of(mesh, uv_faces);
  check_corner_uv(mesh, view.uv, view.uv_faces);
  view.title = title;
  if (!summary_json.empty()) {
    view.summary = parse_json_text(summary_json, "the summary");
    if (!view.summary.is_object()) throw InputError("the summary must be a JSON object");
  }
  return write_html_view(path, view);
}

void write_layout_png(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
                      const Eigen::MatrixXi& uv_faces, int size) {
  const Eigen::MatrixXi& corners = corners_of(mesh, uv_faces);
  write_uv_png(path, uv, corners, excess_distortion(mesh, uv, corners), size);
}

void write_layout_svg(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
                      const Eigen::MatrixXi& uv_faces, const std::string& title) {
  const Eigen::MatrixXi& corners = corners_of(mesh, uv_faces);
  write_uv_svg(path, uv, corners, excess_distortion(mesh, uv, corners), title);
}

}  // namespace akvf
