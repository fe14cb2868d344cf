// The Python module akvf._akvf: the public C++ API (akvf/akvf.h) for NumPy
// arrays. Options arrive as keyword arguments named by the options schema
// (akvf/internal/option_schema.h), so every option of the command line is a keyword
// with the same checks and messages. The package akvf/__init__.py wraps this
// module (results as objects, docstrings from the schema).
//
// While a run optimizes, the GIL is released and SIGINT (Ctrl-C) raises the
// library's interrupt flag, which the optimizer checks once per iteration;
// the run then ends and KeyboardInterrupt is raised. Callbacks take the GIL
// for their call.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <csignal>
#include <optional>

#include "akvf/akvf.h"
#include "akvf/internal/option_schema.h"
#include "framework/optimization/trace_columns.h"
#include "framework/process/interrupt.h"
#include "io/mesh_text.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "python/extensions.h"
#include "python/keyword_options.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

extern "C" void on_interrupt_signal(int) { akvf::request_interrupt(); }

// For the lifetime of a run from the main thread: SIGINT sets the library's
// interrupt flag instead of running Python's handler (which cannot run while
// the GIL is released). The previous handler is restored afterwards.
class InterruptScope {
 public:
  InterruptScope() : active_(is_main_thread()) {
    if (!active_) return;
    akvf::clear_interrupt();
    struct sigaction ours {};
    ours.sa_handler = on_interrupt_signal;
    sigemptyset(&ours.sa_mask);
    sigaction(SIGINT, &ours, &previous_);
  }
  ~InterruptScope() {
    if (active_) sigaction(SIGINT, &previous_, nullptr);
  }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  // KeyboardInterrupt if a SIGINT arrived during the run (call with the GIL).
  void raise_if_interrupted() const {
    if (!active_ || !akvf::interrupt_requested()) return;
    akvf::clear_interrupt();
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }

 private:
  static bool is_main_thread() {
    const py::module_ threading = py::module_::import("threading");
    return threading.attr("current_thread")().is(threading.attr("main_thread")());
  }
  bool active_;
  struct sigaction previous_ {};
};

// One trace row as a dict with the trace CSV's columns.
py::dict row_dict(const akvf::IterationSummary& row) {
  py::dict d;
  for (const akvf::TraceColumn* column : akvf::present_trace_columns(row)) {
    const double value = column->value(row);
    if (column->integer)
      d[column->name] = static_cast<long long>(value);
    else
      d[column->name] = value;
  }
  d["warm_start"] = row.warm_start;
  return d;
}

// The user's callback(row, x) as an iteration callback: x converted by
// `to_map`; a false return value (not None) stops the run; an exception in
// the callback stops it too and is raised when the run has ended.
class PythonCallback {
 public:
  PythonCallback(py::object callback, std::function<py::object(const Eigen::VectorXd&)> to_map)
      : callback_(std::move(callback)), to_map_(std::move(to_map)) {}

  std::vector<akvf::IterationCallback> callbacks() {
    if (callback_.is_none()) return {};
    return {[this](const akvf::IterationSummary& row, const Eigen::VectorXd& x) {
      const py::gil_scoped_acquire gil;
      try {
        const py::object answer = callback_(row_dict(row), to_map_(x));
        if (!answer.is_none() && !py::bool_(answer)) return akvf::CallbackAction::kStop;
        return akvf::CallbackAction::kContinue;
      } catch (py::error_already_set& e) {
        error_.emplace(std::move(e));
        return akvf::CallbackAction::kStop;
      }
    }};
  }
  // Raises the callback's exception, if there was one (call with the GIL).
  void raise_if_failed() {
    if (error_) {
      py::error_already_set e = std::move(*error_);
      error_.reset();
      throw e;
    }
  }

 private:
  py::object callback_;
  std::function<py::object(const Eigen::VectorXd&)> to_map_;
  std::optional<py::error_already_set> error_;
};

// The fields ParameterizeResult and DeformResult share, as a dict for
// akvf/__init__.py's Result.
template <class Result>
py::dict result_dict(const Result& r) {
  py::dict d;
  d["status"] = akvf::to_string(r.status);
  d["message"] = r.message;
  d["iterations"] = r.iterations();
  d["energy"] = r.energy();
  d["grad_norm"] = r.grad_norm();
  const std::string final_status = akvf::status_with_reason({Eigen::VectorXd(), r.trace, r.status, r.message});
  py::dict trace;
  const auto rows = static_cast<py::ssize_t>(r.trace.size());
  for (const akvf::TraceColumn* column : akvf::present_trace_columns(r.trace)) {
    if (column->integer) {
      py::array_t<long long> values(rows);
      for (py::ssize_t i = 0; i < rows; ++i) values.mutable_at(i) = static_cast<long long>(column->value(r.trace[i]));
      trace[column->name] = values;
    } else {
      py::array_t<double> values(rows);
      for (py::ssize_t i = 0; i < rows; ++i) values.mutable_at(i) = column->value(r.trace[i]);
      trace[column->name] = values;
    }
  }
  py::list status;
  for (std::size_t i = 0; i < r.trace.size(); ++i) status.append(akvf::trace_status_cell(r.trace, i, final_status));
  trace["status"] = py::module_::import("numpy").attr("array")(status, "dtype"_a = "object");
  d["trace"] = trace;
  const akvf::RunStatistics& s = r.statistics;
  py::dict statistics;
  statistics["iterations"] = s.iterations;
  statistics["seconds"] = s.seconds;
  statistics["preconditioner_seconds"] = s.preconditioner_seconds;
  statistics["line_search_seconds"] = s.line_search_seconds;
  statistics["factorizations"] = s.preconditioner.factorizations;
  statistics["reused_solves"] = s.preconditioner.reused_solves;
  statistics["cg_solves"] = s.preconditioner.cg_solves;
  statistics["cg_iterations"] = s.preconditioner.cg_iterations;
  statistics["symbolic_analyses"] = s.preconditioner.symbolic_analyses;
  statistics["multigrid_setups"] = s.preconditioner.multigrid_setups;
  d["statistics"] = statistics;
  d["preconditioner_report"] = r.preconditioner_report;
  d["warnings"] = py::cast(r.warnings);
  return d;
}

// A solve of `solver` from its initial map or from `uv0`, with the GIL
// released, `callback` called per iteration and Ctrl-C as KeyboardInterrupt.
py::dict solve(akvf::Parameterizer& solver, const py::object& uv0, const py::object& callback) {
  std::optional<Eigen::MatrixXd> start;
  if (!uv0.is_none()) start = akvf::python::float_matrix(uv0, "uv0", 2);
  // With cut "seams", a later round's x is of the mesh its seams opened: None.
  PythonCallback hooks(callback, [&solver](const Eigen::VectorXd& x) -> py::object {
    try {
      return py::cast(solver.uv_of(x));
    } catch (const akvf::OptionsError&) {
      return py::none();
    }
  });
  akvf::ParameterizeResult result;
  const InterruptScope interrupts;
  {
    const py::gil_scoped_release release;
    result = start ? solver.solve(*start, hooks.callbacks()) : solver.solve(hooks.callbacks());
  }
  interrupts.raise_if_interrupted();
  hooks.raise_if_failed();
  py::dict d = result_dict(result);
  d["uv"] = result.uv;
  d["uv_faces"] = result.uv_faces;
  d["initial_map"] = std::string(akvf::choice_name(result.initial_map));
  d["boundary_crossings"] = result.boundary_crossings;
  d["overlap_fraction"] = result.overlap_fraction;
  d["distortion_energy"] = result.distortion_energy;
  if (solver.options().cut != akvf::Cut::kNone) d["packing_splits"] = result.packing_splits;
  if (solver.options().cut == akvf::Cut::kSeams) {
    d["seams_added"] = result.seams_added;
    d["seam_length"] = result.seam_length;
    d["overlap_pieces"] = result.overlap_pieces;
    d["parted_charts"] = result.parted_charts;
    d["chart_distortion"] = result.chart_distortion;
    d["distortion_bounded"] = result.distortion_bounded;
    d["seam_stop_reason"] = result.seam_stop_reason;
  }
  return d;
}

// Validation, normalization and the initial map, with the GIL released.
std::unique_ptr<akvf::Parameterizer> make_parameterizer(const py::handle& V, const py::handle& F,
                                                        const py::dict& keywords) {
  const Eigen::MatrixXd vertices = akvf::python::float_matrix(V, "V", 3);
  const Eigen::MatrixXi faces = akvf::python::index_matrix(F, "F", 3);
  const akvf::ParameterizeOptions options =
      akvf::python::options_from_keywords(keywords, akvf::parameterize_option_fields(), "parameterize");
  const InterruptScope interrupts;
  std::unique_ptr<akvf::Parameterizer> solver;
  {
    const py::gil_scoped_release release;
    solver = std::make_unique<akvf::Parameterizer>(vertices, faces, options);
  }
  interrupts.raise_if_interrupted();
  return solver;
}

py::dict parameterize(const py::handle& V, const py::handle& F, const py::object& uv0, const py::object& callback,
                      const py::dict& keywords) {
  const std::unique_ptr<akvf::Parameterizer> solver = make_parameterizer(V, F, keywords);
  return solve(*solver, uv0, callback);
}

std::unique_ptr<akvf::Deformer> make_deformer(const py::handle& V, const py::handle& T) {
  const Eigen::MatrixXd vertices = akvf::python::float_matrix(V, "V", 3);
  const Eigen::MatrixXi tets = akvf::python::index_matrix(T, "T", 4);
  const py::gil_scoped_release release;
  return std::make_unique<akvf::Deformer>(vertices, tets);
}

// A solve of `solver` for the constraints (indices, targets), as
// solve(Parameterizer) does.
py::dict solve_deformation(const akvf::Deformer& solver, const py::handle& indices, const py::handle& targets,
                           const py::object& callback, const py::dict& keywords, const char* caller) {
  akvf::PositionConstraints constraints;
  const Eigen::MatrixXi constrained = akvf::python::index_vector(indices, "constraints[0] (vertex indices)");
  constraints.vertices.assign(constrained.data(), constrained.data() + constrained.size());
  constraints.targets = akvf::python::float_matrix(targets, "constraints[1] (targets)", 3);
  if (constraints.targets.rows() != constrained.size())
    throw akvf::InputError("constraints: " + std::to_string(constrained.size()) + " vertex indices but " +
                           std::to_string(constraints.targets.rows()) + " targets");
  akvf::DeformOptions options = akvf::python::options_from_keywords(keywords, akvf::deform_option_fields(), caller);
  PythonCallback hooks(callback, [](const Eigen::VectorXd& x) -> py::object {
    return py::cast(Eigen::MatrixXd(
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(x.data(), x.size() / 3, 3)));
  });
  options.callbacks = hooks.callbacks();
  const InterruptScope interrupts;
  akvf::DeformResult result;
  {
    const py::gil_scoped_release release;
    result = solver.solve(constraints, options);
  }
  interrupts.raise_if_interrupted();
  hooks.raise_if_failed();
  py::dict d = result_dict(result);
  d["x"] = result.x;
  return d;
}

py::dict deform(const py::handle& V, const py::handle& T, const py::handle& indices, const py::handle& targets,
                const py::object& callback, const py::dict& keywords) {
  return solve_deformation(*make_deformer(V, T), indices, targets, callback, keywords, "deform");
}

// (V, F) of a triangle mesh or (V, T) of a tet mesh, with the readers of the
// command line; their warnings are returned for Python's warnings module.
py::tuple read_mesh(const std::string& path, const std::string& kind) {
  akvf::Warnings warnings;
  if (kind == "triangles") {
    const akvf::TriMesh mesh = akvf::read_triangle_mesh(path, &warnings);
    return py::make_tuple(mesh.V, mesh.F, warnings);
  }
  if (kind == "tets") {
    const akvf::TetMesh mesh = akvf::read_tet_mesh(path, &warnings);
    return py::make_tuple(mesh.V, mesh.T, warnings);
  }
  throw akvf::OptionsError("kind must be 'triangles' or 'tets', found '" + kind + "'");
}

// A map given as arrays: the mesh, its uv and the rows of uv each face
// corner uses (uv_faces, or F when None).
struct ArrayMap {
  akvf::TriMesh mesh;
  Eigen::MatrixXd uv;
  Eigen::MatrixXi uv_faces;
};

ArrayMap array_map(const py::handle& V, const py::handle& F, const py::handle& uv, const py::object& uv_faces) {
  ArrayMap map;
  map.mesh.V = akvf::python::float_matrix(V, "V", 3);
  map.mesh.F = akvf::python::index_matrix(F, "F", 3);
  map.uv = akvf::python::float_matrix(uv, "uv", 2);
  map.uv_faces = uv_faces.is_none() ? map.mesh.F : akvf::python::index_matrix(uv_faces, "uv_faces", 3);
  if (map.uv_faces.rows() != map.mesh.F.rows() ||
      (map.uv_faces.size() > 0 && (map.uv_faces.minCoeff() < 0 || map.uv_faces.maxCoeff() >= map.uv.rows())))
    throw akvf::InputError(uv_faces.is_none()
                               ? "uv must have one row per vertex (" + std::to_string(map.mesh.V.rows()) + "), found " +
                                     std::to_string(map.uv.rows()) + "; pass uv_faces for per-corner uv"
                               : "uv_faces must have one row per face (" + std::to_string(map.mesh.F.rows()) +
                                     ") of indices into uv's " + std::to_string(map.uv.rows()) + " rows");
  return map;
}

template <class Options>
py::list option_list(const std::vector<akvf::OptionField<Options>>& fields) {
  static const char* kinds[] = {"text", "number", "integer", "switch"};
  static const char* scopes[] = {"param", "deform", "both"};
  py::list list;
  const Options defaults;
  for (const auto& field : fields)
    list.append(py::dict("key"_a = field.key, "kind"_a = kinds[static_cast<int>(field.kind)],
                         "default"_a = field.format(defaults), "flag"_a = "--" + field.flag, "help"_a = field.help,
                         "values"_a = field.value_name, "scope"_a = scopes[static_cast<int>(field.scope)],
                         "recomputes_start"_a = field.recomputes_start));
  return list;
}

}  // namespace

PYBIND11_MODULE(_akvf, m) {
  m.doc() = "akvf's C++ library for NumPy arrays; use the package `akvf`, which wraps this module.";
  m.attr("__version__") = akvf::kVersion;
  akvf::python::register_errors(m);

  m.def("parameterize", &parameterize, py::arg("V"), py::arg("F"), py::arg("uv0"), py::arg("callback"),
        py::arg("keywords"));
  m.def("deform", &deform, py::arg("V"), py::arg("T"), py::arg("indices"), py::arg("targets"), py::arg("callback"),
        py::arg("keywords"));
  py::class_<akvf::Parameterizer>(m, "Parameterizer")
      .def(py::init(&make_parameterizer), py::arg("V"), py::arg("F"), py::arg("keywords"))
      .def("solve", &solve, py::arg("uv0"), py::arg("callback"))
      .def("set_options",
           [](akvf::Parameterizer& solver, const py::dict& keywords) {
             solver.set_options(akvf::python::options_from_keywords(keywords, akvf::parameterize_option_fields(),
                                                                    "Parameterizer.set_options"));
           })
      .def("initial_uv", &akvf::Parameterizer::initial_uv);
  m.def("read_mesh", &read_mesh, py::arg("path"), py::arg("kind"));
  m.def(
      "write_mesh",
      [](const std::string& path, const py::handle& V, const py::handle& F, const py::handle& uv,
         const py::object& uv_faces, const std::string& texture) {
        const ArrayMap map = array_map(V, F, uv, uv_faces);
        akvf::MeshWriteOptions options;
        options.texture = texture;
        return akvf::write_mesh(path, map.mesh, map.uv, map.uv_faces, options);
      },
      py::arg("path"), py::arg("V"), py::arg("F"), py::arg("uv"), py::arg("uv_faces"), py::arg("texture"));
  m.def(
      "write_view",
      [](const std::string& path, const py::handle& V, const py::handle& F, const py::handle& uv,
         const py::object& uv_faces, const std::string& title, const std::string& summary) {
        const ArrayMap map = array_map(V, F, uv, uv_faces);
        return akvf::write_view(path, map.mesh, map.uv, map.uv_faces, title, summary);
      },
      py::arg("path"), py::arg("V"), py::arg("F"), py::arg("uv"), py::arg("uv_faces"), py::arg("title"),
      py::arg("summary"));
  m.def(
      "write_layout",
      [](const std::string& path, const py::handle& V, const py::handle& F, const py::handle& uv,
         const py::object& uv_faces, int size, const std::string& title) {
        const ArrayMap map = array_map(V, F, uv, uv_faces);
        const std::string kind = akvf::lowercase_extension(path);
        if (kind == ".svg") {
          akvf::write_layout_svg(path, map.mesh, map.uv, map.uv_faces, title);
        } else if (kind == ".png") {
          akvf::write_layout_png(path, map.mesh, map.uv, map.uv_faces, size);
        } else {
          throw akvf::OptionsError("cannot write " + path + ": the extension must be .png or .svg");
        }
      },
      py::arg("path"), py::arg("V"), py::arg("F"), py::arg("uv"), py::arg("uv_faces"), py::arg("size"),
      py::arg("title"));
  m.def("view_available", &akvf::view_available);
  py::class_<akvf::Deformer>(m, "Deformer")
      .def(py::init(&make_deformer), py::arg("V"), py::arg("T"))
      .def(
          "solve",
          [](const akvf::Deformer& solver, const py::handle& indices, const py::handle& targets,
             const py::object& callback, const py::dict& keywords) {
            return solve_deformation(solver, indices, targets, callback, keywords, "Deformer.solve");
          },
          py::arg("indices"), py::arg("targets"), py::arg("callback"), py::arg("keywords"));
  m.def("energies", [](int dimension) {
    if (dimension != 2 && dimension != 3) throw akvf::OptionsError("dimension must be 2 or 3");
    return dimension == 2 ? akvf::energies_2d().entries() : akvf::energies_3d().entries();
  });
  m.def("preconditioners", [](int dimension) {
    if (dimension != 2 && dimension != 3) throw akvf::OptionsError("dimension must be 2 or 3");
    return dimension == 2 ? akvf::preconditioners_2d().entries() : akvf::preconditioners_3d().entries();
  });
  m.def("load_extension", &akvf::python::load_extension, py::arg("path"));
  m.def("line_searches", [] { return akvf::line_searches().entries(); });
  m.def("solvers", [] { return akvf::solvers(); });
  m.def("options", [](const std::string& problem) {
    if (problem == "parameterize") return option_list(akvf::parameterize_option_fields());
    if (problem == "deform") return option_list(akvf::deform_option_fields());
    throw akvf::OptionsError("problem must be 'parameterize' or 'deform', found '" + problem + "'");
  });
}
