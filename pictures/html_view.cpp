#include "pictures/html_view.h"

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "akvf/error.h"
#include "akvf/rest_geometry.h"
#include "framework/process/output_file.h"
#include "io/checker_texture.h"
#include "io/seam_split_mesh.h"
#include "io/text_utilities.h"
#include "pictures/display_decimation.h"
#include "pictures/distortion_color.h"
#include "pictures/map_distortion.h"

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

// JSON text that can sit inside a <script> element: no '<' at all (only
// strings can hold one, and "\u003c" is the same JSON string), so neither
// "</script>" nor "<!--", which would change how the browser reads the
// element, can appear.
std::string script_safe(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (char c : json) {
    if (c == '<')
      out += "\\u003c";
    else
      out += c;
  }
  return out;
}

// The mesh moved and scaled into the unit box: areas of any coordinate
// range stay finite, their ratios do not change, and the page's 32-bit
// floats hold every coordinate.
TriMesh unit_extent(const TriMesh& mesh) {
  TriMesh unit = mesh;
  const Eigen::RowVector3d low = mesh.V.colwise().minCoeff();
  unit.V = (mesh.V.rowwise() - low) / std::max((mesh.V.colwise().maxCoeff() - low).maxCoeff(), 1e-300);
  return unit;
}

// The seams: edges of two faces whose corners there take different UV rows,
// as segments (6 floats each) of `mesh`, at most kMaxSeamSegments of them.
constexpr std::size_t kMaxSeamSegments = 1 << 18;
std::vector<float> seam_segments(const TriMesh& mesh, const Eigen::MatrixXi& uv_faces) {
  std::map<std::pair<int, int>, std::array<int, 2>> first_side;  // edge -> the UV rows of its first face
  std::vector<float> segments;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      const int ua = uv_faces(f, k), ub = uv_faces(f, (k + 1) % 3);
      const auto key = std::minmax(a, b);
      const std::array<int, 2> rows = a < b ? std::array<int, 2>{ua, ub} : std::array<int, 2>{ub, ua};
      const auto [it, first] = first_side.emplace(key, rows);
      if (first || it->second == rows || segments.size() >= 6 * kMaxSeamSegments) continue;
      for (const int v : {a, b})
        for (int c = 0; c < 3; ++c) segments.push_back(static_cast<float>(mesh.V(v, c)));
    }
  return segments;
}

nlohmann::json page_data(const ViewContent& content) {
  const TriMesh mesh = unit_extent(content.mesh);
  const Eigen::MatrixXd uv = unit_square_uv(content.uv);
  const MapDistortion distortion = map_distortion(mesh, uv, content.uv_faces);
  const DisplayMesh display = decimate_for_display(split_at_seams(mesh, uv, content.uv_faces), kViewFaceLimit);
  const SeamSplitMesh& split = display.mesh;
  std::string note = content.note;
  if (split.mesh.num_faces() < mesh.num_faces())
    note += (note.empty() ? "" : " ") + std::string("Decimated for display: ") +
            std::to_string(split.mesh.num_faces()) + " of " + std::to_string(mesh.num_faces()) +
            " faces shown (vertex clustering); the distortion colours and mean are the original faces'.";
  std::vector<float> positions, texcoords;
  std::vector<std::uint32_t> indices;
  std::vector<unsigned char> colors;
  for (int v = 0; v < split.mesh.num_vertices(); ++v) {
    for (int c = 0; c < 3; ++c) positions.push_back(static_cast<float>(split.mesh.V(v, c)));
    for (int c = 0; c < 2; ++c) texcoords.push_back(static_cast<float>(split.uv(v, c)));
  }
  for (int f = 0; f < split.mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<std::uint32_t>(split.mesh.F(f, k)));
    for (unsigned char channel : distortion_color(distortion.value[display.source_face[f]] - 4))
      colors.push_back(channel);
  }
  double finite_sum = 0, area_sum = 0;
  int inverted = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (std::isfinite(distortion.value[f])) {
      finite_sum += distortion.area[f] * distortion.value[f];
      area_sum += distortion.area[f];
    } else {
      ++inverted;
    }
  }
  return {{"title", content.title},
          {"note", note},
          {"vertices", mesh.num_vertices()},
          {"faces", mesh.num_faces()},
          {"faces_shown", split.mesh.num_faces()},
          {"mean_distortion", area_sum > 0 ? finite_sum / area_sum : 0.0},
          {"degenerate_or_inverted", inverted},
          {"positions", base64_of(positions)},
          {"uv", base64_of(texcoords)},
          {"indices", base64_of(indices)},
          {"face_colors", base64_of(colors)},
          {"seams", base64_of(seam_segments(mesh, content.uv_faces))},
          {"summary", content.summary}};
}

}  // namespace

bool html_view_available() { return embedded::three_js != nullptr && embedded::orbit_controls_js != nullptr; }

void require_html_view() {
  if (!html_view_available())
    throw OptionsError(
        "this build of akvf has no three.js to embed in an HTML view; install Debian's libjs-three (bash "
        "scripts/setup.sh) and rebuild");
}

int write_html_view(const std::string& path, const ViewContent& content) {
  require_html_view();
  const nlohmann::json page = page_data(content);
  const std::string data = script_safe(page.dump());
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
  return page["faces_shown"].get<int>();
}

}  // namespace akvf
