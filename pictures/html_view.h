#pragma once
// `akvf view`: one self-contained HTML page (three.js and the data embedded,
// nothing fetched when opened) with the surface under the checkerboard
// (orbit, zoom), the UV layout beside it, a switch to colour both by
// distortion, and the run's summary.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

#include "akvf/mesh.h"

namespace akvf {

// A view shows at most this many faces; larger meshes are decimated for
// display (display_decimation.h) and the page says so. A face costs about
// 70 bytes of the page (positions, UVs, indices and colours in base64), so
// 500 000 faces make a page of about 35 MB, which browsers still open in
// seconds.
inline constexpr long long kViewFaceLimit = 500000;

struct ViewContent {
  TriMesh mesh;              // the surface in 3D
  Eigen::MatrixXd uv;        // #T by 2, any scale
  Eigen::MatrixXi uv_faces;  // #F by 3 rows of uv
  std::string title;
  nlohmann::ordered_json summary;  // a run's summary (docs/experiments.md), or null
  std::string note;                // shown under the title, e.g. what was left out
};

// True when this build embeds three.js (libjs-three was found).
bool html_view_available();
// OptionsError saying what to install unless html_view_available().
void require_html_view();

// Writes the page atomically and returns the number of faces it shows
// (fewer than the mesh's when decimated). OptionsError when three.js is not
// embedded (require_html_view), OutputError when the file cannot be written.
int write_html_view(const std::string& path, const ViewContent& content);

}  // namespace akvf
