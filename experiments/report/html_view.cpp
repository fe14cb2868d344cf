#include "experiments/report/html_view.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "experiments/report/display_decimation.h"
#include "experiments/report/distortion_color.h"
#include "experiments/report/seam_split_mesh.h"
#include "experiments/report/text_utilities.h"
#include "framework/mesh/rest_geometry.h"
#include "framework/process/error.h"
#include "framework/process/output_file.h"

namespace akvf {

namespace embedded {
extern const char* const three_js;
extern const char* const orbit_controls_js;
extern const char* const view_page_js;
extern const char* const view_page_css;
}  // namespace embedded

namespace {

std::string base64(const void* data, std::size_t size) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const unsigned value = bytes[i] << 16 | (i + 1 < size ? bytes[i + 1] << 8 : 0) | (i + 2 < size ? bytes[i + 2] : 0);
    out += kDigits[value >> 18 & 63];
    out += kDigits[value >> 12 & 63];
    out += i + 1 < size ? kDigits[value >> 6 & 63] : '=';
    out += i + 2 < size ? kDigits[value & 63] : '=';
  }
  return out;
}

template <class T>
std::string base64_of(const std::vector<T>& values) {
  return base64(values.data(), values.size() * sizeof(T));
}

// JSON text that can sit inside a <script> element: "</" never appears
// (only strings can hold '<'; "<\/" is the same JSON string).
std::string script_safe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    out += json[i];
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/') out += '\\';
  }
  return out;
}

// The mesh moved and scaled into the unit box (areas of any coordinate
// range stay finite; ratios of areas do not change).
TriMesh unit_extent(const TriMesh& mesh) {
  TriMesh unit = mesh;
  const Eigen::RowVector3d low = mesh.V.colwise().minCoeff();
  unit.V = (mesh.V.rowwise() - low) / std::max((mesh.V.colwise().maxCoeff() - low).maxCoeff(), 1e-300);
  return unit;
}

nlohmann::json page_data(const ViewContent& content) {
  const Eigen::VectorXd distortion = face_symmetric_dirichlet(content.mesh, content.uv, content.uv_faces);
  const DisplayMesh display =
      decimate_for_display(split_at_seams(content.mesh, content.uv, content.uv_faces), kViewFaceLimit);
  const SeamSplitMesh& split = display.mesh;
  std::string note = content.note;
  if (split.mesh.num_faces() < content.mesh.num_faces())
    note += (note.empty() ? "" : " ") + std::string("Decimated for display: ") +
            std::to_string(split.mesh.num_faces()) + " of " + std::to_string(content.mesh.num_faces()) +
            " faces shown (vertex clustering); the distortion colours and mean are the original faces'.";
  std::vector<float> positions, uv;
  std::vector<std::uint32_t> indices;
  std::vector<unsigned char> colors;
  // Centred and scaled to a unit box (the picture is the same, and any
  // coordinate range fits the page's 32-bit floats).
  const Eigen::RowVector3d low = split.mesh.V.colwise().minCoeff(), high = split.mesh.V.colwise().maxCoeff();
  const Eigen::RowVector2d uv_low = split.uv.colwise().minCoeff(), uv_high = split.uv.colwise().maxCoeff();
  const double extent = std::max((high - low).maxCoeff(), 1e-300),
               uv_extent = std::max((uv_high - uv_low).maxCoeff(), 1e-300);
  for (int v = 0; v < split.mesh.num_vertices(); ++v) {
    for (int c = 0; c < 3; ++c)
      positions.push_back(static_cast<float>((split.mesh.V(v, c) - 0.5 * (low[c] + high[c])) / extent));
    for (int c = 0; c < 2; ++c) uv.push_back(static_cast<float>((split.uv(v, c) - uv_low[c]) / uv_extent));
  }
  for (int f = 0; f < split.mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<std::uint32_t>(split.mesh.F(f, k)));
    for (unsigned char channel : distortion_color(distortion[display.source_face[f]] - 4)) colors.push_back(channel);
  }
  double finite_sum = 0, area_sum = 0;
  int inverted = 0;
  const TriMesh m = unit_extent(content.mesh);
  for (int f = 0; f < m.num_faces(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (std::isfinite(distortion[f])) {
      finite_sum += area * distortion[f];
      area_sum += area;
    } else {
      ++inverted;
    }
  }
  return {{"title", content.title},
          {"note", note},
          {"vertices", content.mesh.num_vertices()},
          {"faces", content.mesh.num_faces()},
          {"mean_distortion", area_sum > 0 ? finite_sum / area_sum : 0.0},
          {"degenerate_or_inverted", inverted},
          {"positions", base64_of(positions)},
          {"uv", base64_of(uv)},
          {"indices", base64_of(indices)},
          {"face_colors", base64_of(colors)},
          {"summary", content.summary}};
}

}  // namespace

Eigen::VectorXd face_symmetric_dirichlet(const TriMesh& mesh, const Eigen::MatrixXd& uv,
                                         const Eigen::MatrixXi& uv_faces) {
  // Both scaled to unit extent first: the value does not depend on either
  // scale, and squares of any coordinate range stay finite.
  const RestTriangles rest = rest_triangles(unit_extent(mesh));
  const double uv_extent = std::max((uv.colwise().maxCoeff() - uv.colwise().minCoeff()).maxCoeff(), 1e-300);
  double uv_area = 0;
  std::vector<Eigen::Matrix2d> Ds(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::RowVector2d p0 = uv.row(uv_faces(f, 0)) / uv_extent;
    Ds[f].col(0) = (uv.row(uv_faces(f, 1)) / uv_extent - p0).transpose();
    Ds[f].col(1) = (uv.row(uv_faces(f, 2)) / uv_extent - p0).transpose();
    uv_area += 0.5 * Ds[f].determinant();
  }
  const double scale = uv_area > 0 ? std::sqrt(rest.total_area / uv_area) : 1;
  Eigen::VectorXd values(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Matrix2d J = scale * Ds[f] * rest.Dm_inv[f];
    const double det = J.determinant();
    // ||J||_F^2 + ||J^-1||_F^2, and ||J^-1||_F = ||J||_F / |det J| in 2D.
    values[f] = det > 0 ? J.squaredNorm() * (1 + 1 / (det * det)) : std::numeric_limits<double>::infinity();
  }
  return values;
}

bool html_view_available() { return embedded::three_js != nullptr && embedded::orbit_controls_js != nullptr; }

void require_html_view() {
  if (!html_view_available())
    throw OptionsError(
        "this build of akvf has no three.js to embed in an HTML view; install Debian's libjs-three (bash "
        "scripts/setup.sh) and rebuild");
}

void write_html_view(const std::string& path, const ViewContent& content) {
  require_html_view();
  const std::string data = script_safe(page_data(content).dump());
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        << "<meta name=\"generator\" content=\"akvf\">\n<title>" << xml_escape(content.title) << "</title>\n<style>\n"
        << embedded::view_page_css << "</style>\n</head>\n<body>\n"
        << "<header><h1>" << xml_escape(content.title) << "</h1><p id=\"note\"></p>"
        << "<label><input type=\"checkbox\" id=\"distortion\"> colour by distortion</label></header>\n"
        << "<main><div id=\"surface\" title=\"drag to orbit, wheel to zoom, right-drag to pan\"></div>"
        << "<canvas id=\"layout\"></canvas><aside id=\"summary\"></aside></main>\n"
        << "<pre id=\"status\">loading</pre>\n"
        << "<script>\n"
        << embedded::three_js << "\n</script>\n"
        << "<script>\n"
        << embedded::orbit_controls_js << "\n</script>\n"
        << "<script type=\"application/json\" id=\"akvf-data\">" << data << "</script>\n"
        << "<script>\n"
        << embedded::view_page_js << "\n</script>\n</body>\n</html>\n";
  });
}

}  // namespace akvf
