#include "io/gltf_writer.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "akvf/error.h"
#include "framework/process/output_file.h"
#include "io/seam_split_mesh.h"

namespace akvf {

namespace {

// glTF constants (glTF 2.0 specification, sections 3.6 and 4.4).
constexpr std::uint32_t kMagic = 0x46546C67;        // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;    // "JSON"
constexpr std::uint32_t kBinaryChunk = 0x004E4942;  // "BIN\0"
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The binary chunk, built view by view, each view 4-byte aligned.
class BinaryBuffer {
 public:
  // Appends the bytes as a new buffer view; returns its index.
  int add_view(const void* data, std::size_t size, int target, nlohmann::json* views) {
    bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", bytes_.size()}, {"byteLength", size}};
    if (target) view["target"] = target;
    const auto* p = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), p, p + size);
    views->push_back(view);
    return static_cast<int>(views->size()) - 1;
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

void put_u32(std::ostream& out, std::uint32_t value) {
  const unsigned char bytes[4] = {static_cast<unsigned char>(value), static_cast<unsigned char>(value >> 8),
                                  static_cast<unsigned char>(value >> 16), static_cast<unsigned char>(value >> 24)};
  out.write(reinterpret_cast<const char*>(bytes), 4);
}

float to_float(double value, const std::string& path) {
  if (!(std::abs(value) <= std::numeric_limits<float>::max()))
    throw OutputError(path + ": coordinate " + std::to_string(value) +
                      " does not fit glTF's 32-bit floats; write an OBJ or PLY instead");
  return static_cast<float>(value);
}

static_assert(std::endian::native == std::endian::little, "the buffers are copied as glTF's little-endian bytes");

}  // namespace

void write_glb(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& UV_faces,
               const RgbImage& texture) {
  const SeamSplitMesh split = split_at_seams(mesh, UV, UV_faces);
  std::vector<float> positions, texcoords;
  std::vector<std::uint32_t> indices;
  for (int v = 0; v < split.mesh.num_vertices(); ++v) {
    for (int c = 0; c < 3; ++c) positions.push_back(to_float(split.mesh.V(v, c), path));
    texcoords.push_back(to_float(split.uv(v, 0), path));
    texcoords.push_back(to_float(1 - split.uv(v, 1), path));
  }
  for (int f = 0; f < split.mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) indices.push_back(static_cast<std::uint32_t>(split.mesh.F(f, k)));
  const Eigen::Vector3d low = split.mesh.V.colwise().minCoeff(), high = split.mesh.V.colwise().maxCoeff();
  std::ostringstream png;
  write_png(png, texture, path + ": the embedded texture");
  const std::string png_bytes = png.str();

  nlohmann::json views = nlohmann::json::array();
  BinaryBuffer buffer;
  const int position_view = buffer.add_view(positions.data(), positions.size() * 4, kArrayBuffer, &views);
  const int texcoord_view = buffer.add_view(texcoords.data(), texcoords.size() * 4, kArrayBuffer, &views);
  const int index_view = buffer.add_view(indices.data(), indices.size() * 4, kElementArrayBuffer, &views);
  const int image_view = buffer.add_view(png_bytes.data(), png_bytes.size(), 0, &views);
  buffer.bytes().resize((buffer.bytes().size() + 3) / 4 * 4, 0);
  const std::size_t vertices = positions.size() / 3;
  const nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "akvf"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}, {"name", "parameterized surface"}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}, {"mode", 4}}}}}}},
      {"materials",
       {{{"name", "checker"},
         {"pbrMetallicRoughness",
          {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}},
         {"doubleSided", true}}}},
      {"textures", {{{"source", 0}, {"sampler", 0}}}},
      {"samplers", {{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}}},
      {"images", {{{"bufferView", image_view}, {"mimeType", "image/png"}}}},
      {"accessors",
       {{{"bufferView", position_view},
         {"componentType", kFloat},
         {"count", vertices},
         {"type", "VEC3"},
         {"min", {static_cast<float>(low[0]), static_cast<float>(low[1]), static_cast<float>(low[2])}},
         {"max", {static_cast<float>(high[0]), static_cast<float>(high[1]), static_cast<float>(high[2])}}},
        {{"bufferView", texcoord_view}, {"componentType", kFloat}, {"count", vertices}, {"type", "VEC2"}},
        {{"bufferView", index_view}, {"componentType", kUnsignedInt}, {"count", indices.size()}, {"type", "SCALAR"}}}},
      {"bufferViews", views},
      {"buffers", {{{"byteLength", buffer.bytes().size()}}}},
  };
  std::string json = gltf.dump();
  json.resize((json.size() + 3) / 4 * 4, ' ');
  const std::size_t total = 12 + 8 + json.size() + 8 + buffer.bytes().size();
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw OutputError(path + ": the mesh is too large for one binary glTF file (4 GiB); write an OBJ or PLY instead");
  write_file_atomically(path, [&](std::ostream& out) {
    put_u32(out, kMagic);
    put_u32(out, 2);
    put_u32(out, static_cast<std::uint32_t>(total));
    put_u32(out, static_cast<std::uint32_t>(json.size()));
    put_u32(out, kJsonChunk);
    out << json;
    put_u32(out, static_cast<std::uint32_t>(buffer.bytes().size()));
    put_u32(out, kBinaryChunk);
    out << buffer.bytes();
  });
}

}  // namespace akvf
