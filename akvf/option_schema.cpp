#include "akvf/internal/option_schema.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/preconditioner_settings.h"
#include "framework/mesh/initialization.h"
#include "io/text_reader.h"

namespace akvf {

namespace {

// "NAME must be > 0, found -1"; NAME is how the caller names the option
// ("exponent", "option --exponent", or nothing where the place is named).
[[noreturn]] void out_of_range(const std::string& name, const std::string& rule, double found) {
  throw OptionsError((name.empty() ? "" : name + " ") + "must be " + rule + ", found " + number_text(found));
}

double parse_number(const std::string& text) {
  double value = 0;
  if (text == "inf" || text == "infinity") return std::numeric_limits<double>::infinity();
  if (!parse_real(text, &value)) throw OptionsError("'" + text + "' is not a finite number");
  return value;
}

int parse_int(const std::string& text) {
  long long value = 0;
  double real = 0;
  if (parse_integer(text, &value) && value >= std::numeric_limits<int>::min() &&
      value <= std::numeric_limits<int>::max())
    return static_cast<int>(value);
  if ((parse_integer(text, &value) || (parse_real(text, &real) && real == std::floor(real))))
    throw OptionsError(text + " is out of range (" + std::to_string(std::numeric_limits<int>::min()) + " to " +
                       std::to_string(std::numeric_limits<int>::max()) + ")");
  throw OptionsError("'" + text + "' is not an integer");
}

bool parse_switch(const std::string& text) {
  if (text == "true" || text == "on") return true;
  if (text == "false" || text == "off") return false;
  throw OptionsError("expected on or off, found '" + text + "'");
}

template <class O>
using Check = std::function<void(const O&, const std::string&)>;

template <class O>
OptionField<O> text_field(std::string key, std::string flag, std::string value_name, std::string help,
                          std::string O::*member, std::function<void(const O&)> check) {
  return {std::move(key),
          std::move(flag),
          std::move(value_name),
          OptionKind::kText,
          std::move(help),
          [member](O& o, const std::string& text) { o.*member = text; },
          [member](const O& o) { return o.*member; },
          [check](const O& o, const std::string&) { check(o); }};
}

template <class O>
OptionField<O> number_field(std::string key, std::string flag, std::string value_name, std::string help,
                            double O::*member, std::string rule, std::function<bool(double)> ok) {
  return {std::move(key),
          std::move(flag),
          std::move(value_name),
          OptionKind::kNumber,
          std::move(help),
          [member](O& o, const std::string& text) { o.*member = parse_number(text); },
          [member](const O& o) { return number_text(o.*member); },
          [member, rule, ok](const O& o, const std::string& name) {
            if (!ok(o.*member)) out_of_range(name, rule, o.*member);
          }};
}

// A number or "auto" (std::nullopt: a default that depends on other
// options); `ok` checks the number.
template <class O>
OptionField<O> auto_number_field(std::string key, std::string flag, std::string value_name, std::string help,
                                 std::optional<double> O::*member, std::string rule, std::function<bool(double)> ok) {
  return {std::move(key),
          std::move(flag),
          "auto|" + value_name,
          OptionKind::kText,
          std::move(help),
          [member](O& o, const std::string& text) {
            double value = 0;
            if (text == "auto")
              (o.*member).reset();
            else if (parse_real(text, &value))
              o.*member = value;
            else
              throw OptionsError("'" + text + "' is neither auto nor a number");
          },
          [member](const O& o) { return o.*member ? number_text(*(o.*member)) : std::string("auto"); },
          [member, rule, ok](const O& o, const std::string& name) {
            if (o.*member && !ok(*(o.*member))) out_of_range(name, "auto or " + rule, *(o.*member));
          }};
}

template <class O>
OptionField<O> integer_field(std::string key, std::string flag, std::string value_name, std::string help,
                             int O::*member, std::string rule, std::function<bool(int)> ok) {
  return {std::move(key),
          std::move(flag),
          std::move(value_name),
          OptionKind::kInteger,
          std::move(help),
          [member](O& o, const std::string& text) { o.*member = parse_int(text); },
          [member](const O& o) { return std::to_string(o.*member); },
          [member, rule, ok](const O& o, const std::string& name) {
            if (!ok(o.*member)) out_of_range(name, rule, o.*member);
          }};
}

template <class O>
OptionField<O> switch_field(std::string key, std::string flag, std::string value_name, std::string help,
                            bool O::*member) {
  return {std::move(key),
          std::move(flag),
          std::move(value_name),
          OptionKind::kSwitch,
          std::move(help),
          [member](O& o, const std::string& text) { o.*member = parse_switch(text); },
          [member](const O& o) { return std::string(o.*member ? "true" : "false"); },
          [](const O&, const std::string&) {}};
}

// The words of a choice's names, "a|b|c" (aliases left out).
template <class Choice>
std::string choice_names(const char* separator) {
  std::string names;
  std::vector<Choice> seen;
  for (const ChoiceWord<Choice>& entry : choice_words(Choice{})) {
    if (std::find(seen.begin(), seen.end(), entry.choice) != seen.end()) continue;
    seen.push_back(entry.choice);
    names += (names.empty() ? "" : separator) + std::string(entry.word);
  }
  return names;
}

// A fixed choice (akvf/choices.h), read from its words; `what` names it in
// the error: "unknown cut 'x' (valid: none, auto)".
template <class O, class Choice>
OptionField<O> choice_field(std::string key, std::string flag, std::string what, std::string help, Choice O::*member) {
  return {std::move(key),
          std::move(flag),
          choice_names<Choice>("|"),
          OptionKind::kText,
          std::move(help),
          [member, what](O& o, const std::string& text) {
            for (const ChoiceWord<Choice>& entry : choice_words(Choice{}))
              if (text == entry.word) {
                o.*member = entry.choice;
                return;
              }
            throw OptionsError("unknown " + what + " '" + text + "' (valid: " + choice_names<Choice>(", ") + ")");
          },
          [member](const O& o) { return choice_name(o.*member); },
          [](const O&, const std::string&) {}};
}

// The field, marked as one whose change recomputes the initial map.
template <class O>
OptionField<O> recomputes_start(OptionField<O> field) {
  field.recomputes_start = true;
  return field;
}

// Options both problems have, with the same meaning (scope kBoth).
template <class O>
void add_common_fields(std::vector<OptionField<O>>* fields) {
  fields->push_back(
      recomputes_start(number_field<O>("exponent", "exponent", "K", "exponent k of exp-symmetric-dirichlet and amips",
                                       &O::exponent, "> 0", [](double k) { return k > 0; })));
  fields->push_back(text_field<O>("line_search", "line-search", "NAME", line_searches().names(), &O::line_search,
                                  [](const O& o) { line_searches().require(o.line_search); }));
  fields->push_back(choice_field<O>("acceleration", "acceleration", "acceleration",
                                    "AQP momentum: auto (on for the laplacian preconditioner only), on, off",
                                    &O::acceleration));
  fields->push_back(auto_number_field<O>("grad_tol", "grad-tol", "X",
                                         "stop when the gradient norm drops below X; auto: 1e-3, or 1e-4 for an "
                                         "energy that is 0 at an isometry (arap)",
                                         &O::grad_tol, ">= 0", [](double x) { return x >= 0; }));
  fields->push_back(integer_field<O>("max_iters", "max-iters", "N", "stop after N iterations", &O::max_iters, ">= 0",
                                     [](int n) { return n >= 0; }));
  fields->push_back(number_field<O>("time_limit", "time-limit", "SECONDS", "stop after this much optimizer time",
                                    &O::time_limit, "> 0 seconds", [](double t) { return t > 0; }));
  fields->push_back(choice_field<O>("linear_solver", "linear-solver", "linear solver",
                                    "linear systems: cholmod (sparse Cholesky), amg (CG with hypre's algebraic "
                                    "multigrid), auto (cholmod unless its factor would take more than half the "
                                    "memory, then amg)",
                                    &O::linear_solver));
  fields->push_back(choice_field<O>(
      "eigen_filter", "eigen-filter", "eigenvalue filter",
      "projected Newton (newton, akvf-newton): the element Hessians' negative "
      "eigenvalues clamped to 0, mirrored (abs), adaptive (Chen et al. 2024: clamp "
      "while the last step's decrease matched the quadratic model to 1 %, else mirror), "
      "or exact (not filtered while the Hessian is positive definite, else only partly: each element's "
      "negative eigenvalues scaled by 15/16, 3/4 or 0: the least filtering that factors, more after a step "
      "the flip-free bound set; ARAP's elements within its collapse barrier's range and the boundary barrier's "
      "terms clamped until they settle); "
      "auto: clamp for newton, exact for akvf-newton's Newton phase",
      &O::eigen_filter));
  fields->push_back(integer_field<O>("threads", "threads", "N", "worker threads (0 = all cores)", &O::threads,
                                     ">= 0 (0 = all cores)", [](int n) { return n >= 0; }));
}

// Marks the fields outside [common_begin, common_end), the ones
// add_common_fields did not add, as `scope`'s own.
template <class O>
std::vector<OptionField<O>> mark_own(OptionScope scope, std::vector<OptionField<O>> fields, std::size_t common_begin,
                                     std::size_t common_end) {
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (i < common_begin || i >= common_end) fields[i].scope = scope;
  return fields;
}

}  // namespace

const std::vector<OptionField<ParameterizeOptions>>& parameterize_option_fields() {
  using O = ParameterizeOptions;
  static const std::vector<OptionField<O>> fields = [] {
    std::vector<OptionField<O>> f;
    f.push_back(
        recomputes_start(text_field<O>("energy", "energy", "NAME", "distortion energy: " + energies_2d().names(),
                                       &O::energy, [](const O& o) { energies_2d().require(o.energy); })));
    f.push_back(choice_field<O>("solver", "solver", "solver",
                                "descent (Algorithm 1 with --precond) or lbfgs (L-BFGS through Ceres)", &O::solver));
    f.push_back(text_field<O>("precond", "precond", "NAME",
                              preconditioners_2d().names() + " (or lbfgs, an alias of --solver lbfgs)",
                              &O::preconditioner, [](const O& o) { require_method(o.preconditioner); }));
    const std::size_t common_begin = f.size();
    add_common_fields(&f);
    const std::size_t common_end = f.size();
    f.push_back(number_field<O>("akvf_reuse", "akvf-reuse", "TAU",
                                "AKVF: reuse the last factorization through CG to relative residual TAU "
                                "(0 = factor K every iteration, as in Algorithm 1)",
                                &O::akvf_reuse, "in [0, 1)", [](double t) { return t >= 0 && t < 1; }));
    f.push_back(auto_number_field<O>("newton_reuse", "newton-reuse", "TAU",
                                     "projected Newton: reuse the last factorization through CG to relative residual "
                                     "TAU; auto: 0 for newton (factor every iteration), --akvf-reuse for the Newton "
                                     "phase of akvf-newton",
                                     &O::newton_reuse, "in [0, 1)", [](double t) { return t >= 0 && t < 1; }));
    f.push_back(number_field<O>("ls_rho", "ls-rho", "X", "backtracking shrink factor (the paper's text says 0.9)",
                                &O::ls_rho, "in (0, 1)", [](double r) { return r > 0 && r < 1; }));
    f.push_back(auto_number_field<O>("local_sweep", "local-sweep", "X",
                                     "after each AKVF step the flip-free bound set, move each vertex whose squared "
                                     "gradient is above X times the mean by its own projected Newton step, the others "
                                     "held (interior vertices only with --injectivity global; 0 = off); auto: 4 for "
                                     "akvf-newton on an energy with a barrier at collapse (not arap), 0 for the others",
                                     &O::local_sweep, ">= 0", [](double x) { return x >= 0; }));
    f.push_back(auto_number_field<O>("akvf_compression", "akvf-compression", "X",
                                     "plain AKVF (--precond akvf): each face along whose compression K curves more "
                                     "than X times the energy takes the energy's Hessian, negative eigenvalues "
                                     "mirrored, instead of K (0 = off: K everywhere, as in the paper); auto: 1 on an "
                                     "energy without a barrier at collapse (arap), 0 for the others",
                                     &O::akvf_compression, ">= 0", [](double x) { return x >= 0; }));
    f.push_back(recomputes_start(choice_field<O>(
        "init", "init", "initialization",
        "initial map: auto (of Tutte's, the conformal and the boundary-first map, the lowest in energy after "
        "one local sweep, of those that are flip-free and, with --injectivity global, do not overlap "
        "themselves), tutte (uniform weights), cotan, conformal (the least-squares conformal map), "
        "boundary-first (the conformal map that keeps the boundary's lengths, Sawhney and Crane 2017), the "
        "two with their folds undone by moving single vertices, Tutte's where they stay, or file (the mesh "
        "file's texture coordinates: OBJ vt, PLY u,v); conformal maps "
        "and files at the energy's best uniform scale; several charts start at Tutte's",
        &O::init)));
    f.push_back(recomputes_start(
        choice_field<O>("cut", "cut", "cut",
                        "auto cuts a closed, multi-boundary, higher-genus or multi-component mesh into disks "
                        "(one chart per component, side by side); seams cuts so, then adds seams (and charts where "
                        "seams do not do) until every chart's symmetric Dirichlet energy is at most "
                        "--max-distortion; none refuses such meshes",
                        &O::cut)));
    f.push_back(number_field<O>("max_distortion", "max-distortion", "E",
                                "with --cut seams: the bound on each chart's symmetric Dirichlet energy (4 is an "
                                "isometry)",
                                &O::max_distortion, "> 4", [](double e) { return e > 4; }));
    f.push_back(number_field<O>("min_coverage", "min-coverage", "C",
                                "with --cut: charts are split by straight cuts across the map (every triangle "
                                "keeps its distortion; with seams, every piece its bound, by more seams where a cut "
                                "alone would not) until the packing covers this share of the UV square, or no cut "
                                "raises it (one chart: only if its pieces reach it); below it the packing also "
                                "turns charts by eighth turns; 0: never",
                                &O::min_coverage, "in [0, 1)", [](double c) { return c >= 0 && c < 1; }));
    f.push_back(integer_field<O>("texture_size", "texture-size", "N",
                                 "several charts: the texture they are packed for, N texels per side (the unit "
                                 "of --gutter)",
                                 &O::texture_size, ">= 16", [](int n) { return n >= 16; }));
    f.push_back(number_field<O>("gutter", "gutter", "T",
                                "several charts: the least gap between packed charts, in texels of "
                                "--texture-size",
                                &O::gutter, "in [0, 64]", [](double t) { return t >= 0 && t <= 64; }));
    f.push_back(recomputes_start(
        choice_field<O>("repair", "repair", "repair",
                        "auto welds vertices at the same position in separate pieces, sets aside zero-area and "
                        "repeated faces (kept in the outputs), opens edges shared "
                        "by three or more faces, splits non-manifold vertices into one copy per fan of faces "
                        "(reported; the UV is then per corner) and reverses faces wound against their "
                        "neighbours (with cut auto or seams, cuts a surface no winding makes agree where they "
                        "disagree); none refuses such meshes",
                        &O::repair)));
    f.push_back(recomputes_start(
        choice_field<O>("injectivity", "injectivity", "injectivity",
                        "global keeps every chart's boundary from crossing itself (no overlap in UV: a "
                        "contact-free step and a boundary barrier, Smith & Schaefer 2015); local keeps "
                        "only every triangle positive, the paper's Algorithm 1",
                        &O::injectivity)));
    OptionField<O> flaps =
        switch_field<O>("flaps", "flaps", "on|off", "flap optimization of Sec. 5.4 after the Tutte map", &O::flaps);
    flaps.kind = OptionKind::kText;  // --flaps on|off on the command line
    flaps.format = [](const O& o) { return std::string(o.flaps ? "on" : "off"); };
    f.push_back(recomputes_start(flaps));
    f.push_back(recomputes_start(integer_field<O>("warm_start_iters", "warm-start-iters", "N",
                                                  "iteration limit of the warm start (symmetric Dirichlet, then "
                                                  "the energy with its exponent halved) of energies that overflow "
                                                  "at the initial map",
                                                  &O::warm_start_iters, ">= 0", [](int n) { return n >= 0; })));
    return mark_own(OptionScope::kParam, std::move(f), common_begin, common_end);
  }();
  return fields;
}

const std::vector<OptionField<DeformOptions>>& deform_option_fields() {
  using O = DeformOptions;
  static const std::vector<OptionField<O>> fields = [] {
    std::vector<OptionField<O>> f;
    f.push_back(text_field<O>("energy", "energy", "NAME", "3D distortion energy: " + energies_3d().names(), &O::energy,
                              [](const O& o) { energies_3d().require(o.energy); }));
    f.push_back(text_field<O>("precond", "precond", "NAME", preconditioners_3d().names() + " (akvf: K + 1e-4 I)",
                              &O::preconditioner, [](const O& o) { preconditioners_3d().require(o.preconditioner); }));
    const std::size_t common_begin = f.size();
    add_common_fields(&f);
    const std::size_t common_end = f.size();
    f.push_back(number_field<O>("weight", "weight", "W", "soft constraint weight w (at rest volume 1)", &O::weight,
                                "> 0", [](double w) { return w > 0; }));
    f.push_back(switch_field<O>("hard", "hard", "",
                                "hard constraints: the constrained vertices start at their targets and stay "
                                "(refused when that inverts a tet)",
                                &O::hard));
    f.push_back(number_field<O>("cg_tol", "cg-tol", "X",
                                "solve with Jacobi-preconditioned CG to relative residual X instead of factoring "
                                "(the paper uses 0.01; 0 = factor)",
                                &O::cg_tol, "in [0, 1)", [](double t) { return t >= 0 && t < 1; }));
    f.push_back(switch_field<O>("akvf_as_written", "akvf-as-written", "",
                                "AKVF as Sec. 6.2 states it: K + c I without the constraints' Hessian or the "
                                "energy scale (slow; for comparison, docs/design.md)",
                                &O::akvf_as_written));
    return mark_own(OptionScope::kDeform, std::move(f), common_begin, common_end);
  }();
  return fields;
}

namespace {

// A '|' inside a table cell would end it.
std::string cell(std::string text) {
  for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.insert(at, "\\");
  return text;
}

std::string default_text(const std::string& value) { return value == "inf" ? "none" : value; }

// The rows of `fields` in `scope`; `other` (the deform fields, for the common
// table) gives a second default where the two problems' defaults differ.
template <class O, class Other = O>
void reference_rows(std::ostream& out, const std::vector<OptionField<O>>& fields, OptionScope scope,
                    const std::vector<OptionField<Other>>* other = nullptr) {
  const O defaults;
  const Other other_defaults;
  out << "| key (API field, manifest, Python) | command line | default | meaning |\n|---|---|---|---|\n";
  for (const auto& field : fields) {
    if (field.scope != scope) continue;
    std::string value = default_text(field.format(defaults));
    if (other) {
      for (const auto& o : *other)
        if (o.key == field.key && default_text(o.format(other_defaults)) != value)
          value += " (param), " + default_text(o.format(other_defaults)) + " (deform)";
    }
    out << "| `" << field.key << "` | `--" << field.flag << cell(field.value_name.empty() ? "" : " " + field.value_name)
        << "` | " << value << " | " << cell(field.help) << (field.recomputes_start ? " (*)" : "") << " |\n";
  }
}

}  // namespace

std::string options_reference_markdown() {
  std::ostringstream out;
  out << "# Options reference\n\n"
         "Generated from the options schema (`akvf/option_schema.cpp`) by `akvf list --options`; a test "
         "checks that this file is what the command prints. Each key is a field of the API's options "
         "(`akvf::ParameterizeOptions`, `akvf::DeformOptions`; the API field for `precond` is `preconditioner`, "
         "and fixed choices are the enums of `<akvf/choices.h>`), a manifest key, a Python keyword and a "
         "command-line flag.\n\n"
         "## Both problems (`akvf param` and `akvf deform`)\n\n";
  reference_rows(out, parameterize_option_fields(), OptionScope::kBoth, &deform_option_fields());
  out << "\n## `akvf param` only\n\n";
  reference_rows(out, parameterize_option_fields(), OptionScope::kParam);
  out << "\n(*) Changing it in `Parameterizer::set_options` recomputes the initial map; other options keep it.\n"
         "\n## `akvf deform` only\n\n";
  reference_rows(out, deform_option_fields(), OptionScope::kDeform);
  out << "\nManifests use the same keys (`docs/experiments.md`); their `time_limit` defaults to 60 s.\n";
  return out.str();
}

}  // namespace akvf
