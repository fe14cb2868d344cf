// The options schema drives the command line, the manifests and the API:
// every key is accepted by all three with the same effect, and the options
// reference in docs/options.md is what `akvf list --options` prints.
#include <doctest/doctest.h>

#include <fstream>

#include "akvf/internal/option_schema.h"
#include "akvf/internal/options.h"
#include "cli/command_line.h"
#include "cli/schema_options.h"
#include "experiments/runner/manifest.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace {

// A valid value other than the default for each kind of field.
template <class Options>
std::string other_value(const akvf::OptionField<Options>& field, const Options& defaults) {
  const std::string current = field.format(defaults);
  if (field.key == "energy") return "mips";
  if (field.key == "precond") return "slim";
  if (field.key == "solver") return "lbfgs";
  if (field.key == "line_search") return "wolfe-bisection";
  if (field.key == "acceleration") return "on";
  if (field.key == "init") return "cotan";
  if (field.key == "flaps") return "off";
  if (field.key == "cut") return "auto";
  if (field.key == "repair") return "none";
  if (field.key == "injectivity") return "local";
  if (field.key == "linear_solver") return "cholmod";
  if (field.key == "eigen_filter") return "adaptive";
  if (field.kind == akvf::OptionKind::kSwitch) return "true";
  if (field.key == "texture_size") return "2048";
  if (field.kind == akvf::OptionKind::kInteger) return "7";
  if (field.key == "time_limit") return "12.5";
  if (field.key == "max_distortion") return "4.5";
  return current == "0.25" ? "0.5" : "0.25";
}

// The manifest's JSON for that value.
template <class Options>
std::string json_value(const akvf::OptionField<Options>& field, const std::string& text) {
  if (field.kind == akvf::OptionKind::kText) return "\"" + text + "\"";
  return text;  // numbers, and true/false for switches
}

// For every field: the command line (--flag), a manifest ("key": value) and
// the API (parse into the options) give the same options.
template <class Options>
void walk(const std::vector<akvf::OptionField<Options>>& fields, const std::string& problem,
          const Options& manifest_defaults, const std::function<Options(const akvf::CaseSettings&)>& case_options) {
  const Options defaults;
  for (const auto& field : fields) {
    CAPTURE(field.key);
    const std::string text = other_value(field, defaults);
    // API
    Options api = defaults;
    field.parse(api, text);
    CHECK(field.format(api) != field.format(defaults));
    akvf::check_options(api);
    // Command line
    akvf::CommandLine cl("test", akvf::schema_option_specs(fields));
    std::vector<std::string> args = {"--" + field.flag};
    if (field.kind != akvf::OptionKind::kSwitch) args.push_back(text);
    cl.parse(args);
    const Options from_cli = akvf::schema_options_from(cl, fields);
    CHECK(field.format(from_cli) == field.format(api));
    // Manifest
    std::string manifest = R"({"meshes": [{"label": "A", "file": "a.obj"}], "methods": [{"label": "X", "problem": ")" +
                           problem + "\", " + (problem == "deform" ? R"("preset": "slim-cube", )" : "") + "\"" +
                           field.key + "\": " + json_value(field, text) + "}]}";
    const akvf::Manifest m = akvf::parse_manifest(manifest, "m.json");
    CHECK(field.format(case_options(m.cases[0].settings)) == field.format(api));
    // Only that field differs from the manifest's defaults.
    for (const auto& other : fields)
      if (other.key != field.key)
        CHECK(other.format(case_options(m.cases[0].settings)) == other.format(manifest_defaults));
  }
}

}  // namespace

TEST_CASE("every option of param is accepted by the command line, a manifest and the API alike") {
  walk<akvf::ParameterizeOptions>(akvf::parameterize_option_fields(), "param", akvf::CaseSettings{}.param,
                                  [](const akvf::CaseSettings& s) { return s.param; });
}

TEST_CASE("every option of deform is accepted by the command line, a manifest and the API alike") {
  walk<akvf::DeformOptions>(akvf::deform_option_fields(), "deform", akvf::CaseSettings{}.deform,
                            [](const akvf::CaseSettings& s) { return s.deform; });
}

TEST_CASE("every field of the options has a schema entry: a range error names it") {
  akvf::ParameterizeOptions p;
  p.ls_rho = 2;
  CHECK(akvf::test::error_message([&] { akvf::check_options(p); }) == "ls_rho must be in (0, 1), found 2");
  akvf::DeformOptions d;
  d.cg_tol = -1;
  CHECK(akvf::test::error_message([&] { akvf::check_options(d); }) == "cg_tol must be in [0, 1), found -1");
  const akvf::test::CliOutcome r = akvf::test::run_cli({"param", "m.obj", "--ls-rho", "2"});
  CHECK(r.err == "error: option --ls-rho must be in (0, 1), found 2\n");
}

TEST_CASE("docs/options.md is the reference `akvf list --options` prints") {
  const akvf::test::CliOutcome r = akvf::test::run_cli({"list", "--options"});
  CHECK(r.code == 0);
  CHECK(akvf::test::read_text(std::string(AKVF_SOURCE_DIR) + "/docs/options.md") == r.out);
}

TEST_CASE("akvf_compression auto: on for an energy without a barrier at collapse, off for the others") {
  akvf::ParameterizeOptions options;
  options.energy = "arap";
  CHECK(akvf::param_config(options).preconditioner_settings.akvf.compression_stiffness == 1.0);
  options.akvf_compression = 0;
  CHECK(!akvf::param_config(options).preconditioner_settings.akvf.compression_stiffness);
  options.akvf_compression = 2;
  CHECK(akvf::param_config(options).preconditioner_settings.akvf.compression_stiffness == 2.0);
  options.akvf_compression.reset();
  for (const char* barrier : {"symmetric-dirichlet", "mips", "amips", "exp-symmetric-dirichlet"}) {
    options.energy = barrier;
    CHECK(!akvf::param_config(options).preconditioner_settings.akvf.compression_stiffness);
  }
}
