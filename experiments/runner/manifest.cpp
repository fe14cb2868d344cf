#include "experiments/runner/manifest.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/option_schema.h"
#include "io/json_text.h"
#include "io/text_utilities.h"

namespace akvf {

namespace {

using Json = nlohmann::ordered_json;

// Errors name the file and the key path.
struct Context {
  std::string file;
  bool allow_outside_data_dir = false;
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(file + ": " + key + ": " + problem);
  }
  // A file the manifest names is read from the data folder; one that would
  // leave it (absolute, or "../" past its top) is refused unless the manifest
  // says "allow_outside_data_dir": true.
  std::string data_file(const Json& value, const std::string& key) const;
};

// Keys of a case that are not options: the problem, its constraints, snapshots.
const std::set<std::string> kCaseOwnKeys = {"problem", "preset", "constraints", "snapshots"};

// Every key a case may have: the options of both problems and its own.
std::set<std::string> case_keys() {
  std::set<std::string> keys = kCaseOwnKeys;
  for (const auto& field : parameterize_option_fields()) keys.insert(field.key);
  for (const auto& field : deform_option_fields()) keys.insert(field.key);
  return keys;
}

std::string text_of(const Context& c, const Json& value, const std::string& key);

std::string Context::data_file(const Json& value, const std::string& key) const {
  const std::string path = text_of(*this, value, key);
  if (!allow_outside_data_dir && !stays_inside_folder(path))
    fail(key, "\"" + path +
                  "\" leaves the data folder (absolute, or \"..\" past its top); give a path inside "
                  "--data-dir, or set \"allow_outside_data_dir\": true in the manifest");
  return path;
}

std::string number_text(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

std::string join(const std::set<std::string>& names) {
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

std::string text_of(const Context& c, const Json& value, const std::string& key) {
  if (!value.is_string()) c.fail(key, "expected a string, found " + value.dump());
  return value.get<std::string>();
}

double number_of(const Context& c, const Json& value, const std::string& key) {
  if (!value.is_number()) c.fail(key, "expected a number, found " + value.dump());
  return value.get<double>();
}

int integer_of(const Context& c, const Json& value, const std::string& key) {
  if (!value.is_number_integer()) c.fail(key, "expected an integer, found " + value.dump());
  return value.get<int>();
}

// The JSON value of an option as the text its schema field parses; the
// JSON type must fit the field's kind.
template <class Options>
std::string option_text(const Context& c, const OptionField<Options>& field, const Json& value,
                        const std::string& where) {
  switch (field.kind) {
    case OptionKind::kText:
      if (value.is_boolean()) return value.get<bool>() ? "on" : "off";  // "flaps": true
      if (value.is_number()) return number_text(value.get<double>());   // "grad_tol": 1e-3 (or "auto")
      return text_of(c, value, where);
    case OptionKind::kNumber:
      return number_text(number_of(c, value, where));
    case OptionKind::kInteger:
      return std::to_string(integer_of(c, value, where));
    case OptionKind::kSwitch:
      if (!value.is_boolean()) c.fail(where, "expected true or false, found " + value.dump());
      return value.get<bool>() ? "true" : "false";
  }
  return "";
}

// Sets `key` on `options` if the schema of that problem has it.
template <class Options>
void apply_option(const Context& c, const std::vector<OptionField<Options>>& fields, const std::string& key,
                  const Json& value, const std::string& where, Options* options) {
  for (const auto& field : fields) {
    if (field.key != key) continue;
    try {
      field.parse(*options, option_text(c, field, value, where));
    } catch (const OptionsError& e) {
      c.fail(where, e.what());
    }
  }
}

// Applies the case keys of `entry` (an object) onto `settings`; other keys
// are allowed only if listed in `own_keys`.
void apply_case_keys(const Context& c, const Json& entry, const std::string& path,
                     const std::set<std::string>& own_keys, CaseSettings* s) {
  if (!entry.is_object()) c.fail(path, "expected an object, found " + entry.dump());
  for (const auto& [key, value] : entry.items()) {
    const std::string where = path + "." + key;
    if (own_keys.count(key)) continue;
    const std::set<std::string> keys = case_keys();
    if (!keys.count(key)) {
      std::set<std::string> valid = keys;
      valid.insert(own_keys.begin(), own_keys.end());
      c.fail(where, "unknown key (valid: " + join(valid) + ")");
    }
    if (key == "problem") s->problem = text_of(c, value, where);
    if (key == "preset") s->preset = text_of(c, value, where);
    if (key == "constraints") s->constraints = c.data_file(value, where);
    apply_option(c, parameterize_option_fields(), key, value, where, &s->param);
    apply_option(c, deform_option_fields(), key, value, where, &s->deform);
    if (key == "snapshots") {
      if (!value.is_array()) c.fail(where, "expected an array of iteration numbers");
      s->snapshots.clear();
      for (std::size_t i = 0; i < value.size(); ++i)
        s->snapshots.push_back(integer_of(c, value[i], where + "[" + std::to_string(i) + "]"));
    }
  }
}

// Checks names and ranges of one resolved case. `origin(key)` is the path of
// the entry that set the key (method, mesh or defaults), so the error points
// at the value that is wrong.
// Runs the schema's check of every option of the case's problem, naming the
// key where the value came from.
template <class Options>
void check_case_options(const Context& c, const std::vector<OptionField<Options>>& fields, const Options& options,
                        const std::function<std::string(const std::string&)>& where) {
  for (const auto& field : fields) {
    try {
      field.check(options, "");
    } catch (const OptionsError& e) {
      c.fail(where(field.key), e.what());
    }
  }
}

void validate(const Context& c, const CaseSettings& s, const std::function<std::string(const std::string&)>& origin) {
  const auto where = [&](const std::string& key) { return origin(key) + "." + key; };
  if (s.problem != "param" && s.problem != "deform")
    c.fail(where("problem"), "expected \"param\" or \"deform\", found \"" + s.problem + "\"");
  if (s.problem == "param") {
    check_case_options(c, parameterize_option_fields(), s.param, where);
  } else {
    check_case_options(c, deform_option_fields(), s.deform, where);
    if (s.preset.empty() == s.constraints.empty())
      c.fail(origin("problem"), "a deform case needs exactly one of \"preset\" and \"constraints\"");
    if (!s.preset.empty() && s.preset != "slim-cube")
      c.fail(where("preset"), "unknown preset \"" + s.preset + "\" (valid: slim-cube)");
  }
}

}  // namespace

std::string slug(const std::string& label) {
  std::string out;
  for (char ch : label) {
    if (std::isalnum(static_cast<unsigned char>(ch)))
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    else if (!out.empty() && out.back() != '-')
      out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.empty() ? "unnamed" : out;
}

Manifest parse_manifest(const std::string& text_as_read, const std::string& file_name) {
  Context c{file_name};
  const Json root = parse_json_text(text_as_read, file_name);
  if (!root.is_object()) c.fail("(top level)", "expected an object with \"meshes\" and \"methods\"");
  for (const auto& [key, value] : root.items())
    if (key != "name" && key != "description" && key != "defaults" && key != "meshes" && key != "methods" &&
        key != "table" && key != "allow_outside_data_dir")
      c.fail(key, "unknown key (valid: name, description, defaults, meshes, methods, table, allow_outside_data_dir)");
  Manifest m;
  m.source_text = text_as_read;
  if (root.contains("allow_outside_data_dir")) {
    if (!root["allow_outside_data_dir"].is_boolean())
      c.fail("allow_outside_data_dir", "expected true or false, found " + root["allow_outside_data_dir"].dump());
    c.allow_outside_data_dir = m.allow_outside_data_dir = root["allow_outside_data_dir"].get<bool>();
  }
  m.name = root.contains("name") ? text_of(c, root["name"], "name") : "experiment";
  if (root.contains("description")) m.description = text_of(c, root["description"], "description");
  if (root.contains("table")) {
    m.table_value = text_of(c, root["table"], "table");
    if (m.table_value != "seconds" && m.table_value != "energy")
      c.fail("table", "expected \"seconds\" or \"energy\", found \"" + m.table_value + "\"");
  }
  CaseSettings defaults;
  if (root.contains("defaults")) apply_case_keys(c, root["defaults"], "defaults", {}, &defaults);
  if (!root.contains("meshes") || !root["meshes"].is_array() || root["meshes"].empty())
    c.fail("meshes", "expected a non-empty array of meshes");
  if (!root.contains("methods") || !root["methods"].is_array() || root["methods"].empty())
    c.fail("methods", "expected a non-empty array of methods");
  const Json& meshes = root["meshes"];
  const Json& methods = root["methods"];
  std::vector<CaseSettings> mesh_settings;
  std::set<std::string> mesh_slugs, method_slugs;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const std::string path = "meshes[" + std::to_string(i) + "]";
    const Json& entry = meshes[i];
    CaseSettings s = defaults;
    apply_case_keys(c, entry, path, {"label", "file", "missing", "note", "paper", "subdivide"}, &s);
    ManifestMesh mesh;
    if (!entry.contains("label")) c.fail(path, "missing \"label\"");
    mesh.label = text_of(c, entry["label"], path + ".label");
    if (!mesh_slugs.insert(slug(mesh.label)).second) c.fail(path + ".label", "duplicate mesh label");
    if (entry.contains("file")) mesh.file = c.data_file(entry["file"], path + ".file");
    if (entry.contains("missing")) mesh.missing = text_of(c, entry["missing"], path + ".missing");
    if (mesh.file.empty() == mesh.missing.empty())
      c.fail(path, "give exactly one of \"file\" and \"missing\" (the reason the mesh is not available)");
    if (entry.contains("note")) mesh.note = text_of(c, entry["note"], path + ".note");
    if (entry.contains("subdivide")) {
      mesh.subdivide = integer_of(c, entry["subdivide"], path + ".subdivide");
      if (mesh.subdivide < 0 || mesh.subdivide > 6) c.fail(path + ".subdivide", "expected 0 to 6 rounds");
    }
    if (entry.contains("paper")) {
      if (!entry["paper"].is_object()) c.fail(path + ".paper", "expected an object of column: number");
      for (const auto& [column, value] : entry["paper"].items())
        mesh.paper.emplace_back(column, number_of(c, value, path + ".paper." + column));
    }
    m.meshes.push_back(mesh);
    mesh_settings.push_back(s);
  }
  for (std::size_t j = 0; j < methods.size(); ++j) {
    const std::string path = "methods[" + std::to_string(j) + "]";
    if (!methods[j].is_object() || !methods[j].contains("label")) c.fail(path, "expected an object with a \"label\"");
    const std::string label = text_of(c, methods[j]["label"], path + ".label");
    if (!method_slugs.insert(slug(label)).second) c.fail(path + ".label", "duplicate method label");
    m.methods.push_back(label);
  }
  for (std::size_t i = 0; i < m.meshes.size(); ++i)
    for (std::size_t j = 0; j < methods.size(); ++j) {
      const std::string path = "methods[" + std::to_string(j) + "]";
      ExperimentCase experiment_case;
      experiment_case.index = static_cast<int>(m.cases.size());
      experiment_case.mesh_label = m.meshes[i].label;
      experiment_case.method_label = m.methods[j];
      experiment_case.id = slug(m.meshes[i].label) + "--" + slug(m.methods[j]);
      experiment_case.settings = mesh_settings[i];
      apply_case_keys(c, methods[j], path, {"label"}, &experiment_case.settings);
      validate(c, experiment_case.settings, [&](const std::string& key) -> std::string {
        if (methods[j].contains(key)) return path;
        if (meshes[i].contains(key)) return "meshes[" + std::to_string(i) + "]";
        return "defaults";
      });
      experiment_case.mesh_index = static_cast<int>(i);
      m.cases.push_back(experiment_case);
    }
  return m;
}

Manifest read_manifest(const std::string& path) { return parse_manifest(read_text_file(path), path); }

bool stays_inside_folder(const std::string& relative) {
  const std::filesystem::path path(relative);
  if (path.is_absolute() || path.has_root_name() || path.has_root_directory()) return false;
  const std::filesystem::path normal = path.lexically_normal();
  return normal.empty() || *normal.begin() != "..";
}

}  // namespace akvf
