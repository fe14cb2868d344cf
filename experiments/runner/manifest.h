#pragma once
// Experiment manifests (docs/experiments.md has the schema): JSON files that
// list meshes and methods; every mesh x method pair is one case. Keys of a
// mesh or a method entry override the manifest's "defaults" (a method's
// override a mesh's). Parsing validates every name and number up front and
// reports the offending key as a path, e.g.
//   "table1.json: methods[2].precond: unknown preconditioner 'slm' (valid: ...)".
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "akvf/deform.h"
#include "akvf/parameterize.h"

namespace akvf {

// What one case runs: a mesh (from the data folder) with one method.
struct CaseSettings {
  std::string problem = "param";  // param (2D) or deform (3D)
  // The options of the problem, set from the keys of the options schema
  // (akvf/internal/option_schema.h: every `akvf param` / `akvf deform` option); the
  // time limit defaults to 60 s of optimizer time here.
  ParameterizeOptions param = [] {
    ParameterizeOptions o;
    o.time_limit = 60;
    return o;
  }();
  DeformOptions deform = [] {
    DeformOptions o;
    o.time_limit = 60;
    o.max_iters = 1000;
    return o;
  }();
  std::string preset;          // deform: "slim-cube"
  std::string constraints;     // deform: a constraints file, relative to the data folder
  std::vector<int> snapshots;  // param: write the UV layout (SVG) after these iterations
};

struct ManifestMesh {
  std::string label;
  std::string file;                                   // relative to the data folder; empty when missing
  std::string missing;                                // why the mesh is not available ("" when it is)
  std::string note;                                   // e.g. "stand-in for ..."
  int subdivide = 0;                                  // rounds of midpoint subdivision after reading (faces x 4 each)
  std::vector<std::pair<std::string, double>> paper;  // the paper's figures for this mesh: (column, value), in order
};

struct ExperimentCase {
  int index = 0;   // position in the manifest's case order
  std::string id;  // "<mesh>--<method>", file-name safe
  std::string mesh_label, method_label;
  int mesh_index = 0;  // into Manifest::meshes
  CaseSettings settings;
};

struct Manifest {
  std::string name, description;
  std::string table_value = "seconds";  // report cell: "seconds" to the stopping rule, or "energy"
  std::vector<ManifestMesh> meshes;
  std::vector<std::string> methods;   // labels, in order
  std::vector<ExperimentCase> cases;  // meshes x methods, mesh-major
  std::string source_text;            // the JSON as read (copied into result folders)
  // Mesh and constraint files may lie outside --data-dir (absolute or "../").
  bool allow_outside_data_dir = false;
};

// Throws InputError naming the file and the key path (or the line for a
// JSON syntax error).
Manifest read_manifest(const std::string& path);
Manifest parse_manifest(const std::string& text, const std::string& file_name);

// False for an absolute path or one whose "../" climbs above its start.
bool stays_inside_folder(const std::string& relative);

// "Camel Head" -> "camel-head": letters, digits and dashes only.
std::string slug(const std::string& label);

}  // namespace akvf
