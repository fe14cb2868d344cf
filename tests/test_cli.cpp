// The akvf command line in-process: exit codes, messages, output files.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "akvf/internal/demo_mesh.h"
#include "akvf/tet_mesh_io.h"
#include "cli/exit_codes.h"
#include "experiments/report/trace_csv.h"
#include "pictures/html_view.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;

namespace {

using akvf::test::read_text;
using akvf::test::write_text;
using Outcome = akvf::test::CliOutcome;

Outcome akvf_run(const std::vector<std::string>& args) { return akvf::test::run_cli(args); }

fs::path scratch_dir(const std::string& name) { return akvf::test::scratch_dir("cli_test_" + name); }

}  // namespace

TEST_CASE("demo writes the UV OBJ, the trace and the SVG and reaches the lower bound") {
  const fs::path dir = scratch_dir("demo");
  const Outcome r = akvf_run({"demo", "--out-dir", dir.string(), "--quiet"});
  CHECK(r.code == akvf::kExitOk);
  CHECK(r.out.find("status converged") != std::string::npos);
  const std::string trace = read_text(dir / "demo_trace.csv");
  CHECK(trace.rfind("iter,seconds,energy,grad_norm,step,ls_evals,flips,", 0) == 0);
  CHECK(trace.find("\n0,") != std::string::npos);
  CHECK(trace.find(",converged\n") != std::string::npos);
  const std::string obj = read_text(dir / "demo_uv.obj");
  CHECK(obj.find("\nvt ") != std::string::npos);
  CHECK(read_text(dir / "demo_layout.svg").find("<svg") == 0);
  fs::remove_all(dir);
}

TEST_CASE("param on a malformed mesh exits 1, names file and line, and writes nothing") {
  const fs::path dir = scratch_dir("bad");
  write_text(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 1 2 x\n");
  const fs::path out = dir / "uv.obj", trace = dir / "trace.csv";
  const Outcome r = akvf_run({"param", (dir / "bad.obj").string(), "--out", out.string(), "--trace", trace.string()});
  CHECK(r.code == akvf::kExitInputError);
  CHECK(r.err.find("line 6 of " + (dir / "bad.obj").string() +
                   ": face corner 'x' does not start with a vertex index") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(trace));
  fs::remove_all(dir);
}

TEST_CASE("param on a closed mesh exits 1 with the topology message") {
  const fs::path dir = scratch_dir("closed");
  write_text(dir / "tet.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  const Outcome r = akvf_run({"param", (dir / "tet.off").string(), "--out", (dir / "uv.obj").string()});
  CHECK(r.code == akvf::kExitInputError);
  CHECK(r.err.find("mesh is closed (no boundary loop); it must be cut to a disk first: use the option cut auto (akvf "
                   "param --cut auto)") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "uv.obj"));
  fs::remove_all(dir);
}

TEST_CASE("bad command lines exit 2 with a message") {
  CHECK(akvf_run({"param"}).code == akvf::kExitUsageError);
  const Outcome unknown = akvf_run({"param", "m.obj", "--bogus"});
  CHECK(unknown.code == akvf::kExitUsageError);
  CHECK(unknown.err == "error: unknown option --bogus (see --help)\n");
  const Outcome bad_value = akvf_run({"param", "m.obj", "--exponent", "abc"});
  CHECK(bad_value.err == "error: option --exponent: 'abc' is not a finite number\n");
  const Outcome bad_tolerance = akvf_run({"param", "m.obj", "--grad-tol", "abc"});
  CHECK(bad_tolerance.err == "error: option --grad-tol: 'abc' is neither auto nor a number\n");
  const Outcome precond = akvf_run({"demo", "--precond", "slim2", "--quiet", "--out-dir", scratch_dir("x").string()});
  CHECK(precond.code == akvf::kExitUsageError);
  CHECK(precond.err ==
        "error: unknown preconditioner 'slim2' (valid: akvf, newton, akvf-newton, laplacian, slim, identity, lbfgs)\n");
  CHECK(akvf_run({"frobnicate"}).code == akvf::kExitUsageError);
}

TEST_CASE("a missing output directory is reported before any work") {
  const fs::path dir = scratch_dir("missing");
  write_text(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const fs::path out = dir / "no-such-dir" / "uv.obj";
  const Outcome r = akvf_run({"param", (dir / "tri.obj").string(), "--quiet", "--out", out.string()});
  CHECK(r.code == akvf::kExitOutputError);
  CHECK(r.err ==
        "error: cannot write " + out.string() + ": folder " + (dir / "no-such-dir").string() + " does not exist\n");
  CHECK(r.out.empty());
  fs::remove_all(dir);
}

TEST_CASE("help and list describe the commands") {
  const Outcome help = akvf_run({"param", "--help"});
  CHECK(help.code == akvf::kExitOk);
  for (const char* option : {"--energy", "--precond", "--init", "--grad-tol", "--max-iters", "--time-limit", "--out",
                             "--trace", "--svg", "--threads", "--quiet"})
    CHECK(help.out.find(option) != std::string::npos);
  const Outcome list = akvf_run({"list"});
  CHECK(list.out.find("symmetric-dirichlet") != std::string::npos);
  CHECK(list.out.find("akvf") != std::string::npos);
  CHECK(list.out.find("backtracking") != std::string::npos);
}

TEST_CASE("deform: bad constraints files exit 1 naming the line, outputs are not written") {
  const fs::path dir = scratch_dir("deform");
  write_text(dir / "tet.mesh",
             "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
             "Tetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n");
  write_text(dir / "bad_index.txt", "0 0 0 0\n9 1 1 1\n");
  write_text(dir / "bad_columns.txt", "0 0 0\n");
  const fs::path out = dir / "out.mesh";
  for (const auto& [file, message] :
       {std::pair<std::string, std::string>{"bad_index.txt", ": vertex index 9 out of range (5 vertices, 0-based)"},
        {"bad_columns.txt", ": expected 4 columns `vertex_index x y z`, found 3"}}) {
    const Outcome r = akvf_run({"deform", (dir / "tet.mesh").string(), "--constraints", (dir / file).string(), "--out",
                                out.string(), "--quiet"});
    CHECK(r.code == akvf::kExitInputError);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  write_text(dir / "good.txt", "0 0 0 0\n4 1.1 1 1\n");
  const Outcome ok = akvf_run({"deform", (dir / "tet.mesh").string(), "--constraints", (dir / "good.txt").string(),
                               "--out", out.string(), "--max-iters", "5", "--quiet"});
  CHECK(ok.code == akvf::kExitOk);
  CHECK(fs::exists(out));
  CHECK(akvf_run({"deform", (dir / "tet.mesh").string(), "--quiet"}).err ==
        "error: give exactly one of --constraints and --preset\n");
  // Hard constraints: a small displacement runs; one that inverts a tet at the start is refused.
  const Outcome hard = akvf_run({"deform", (dir / "tet.mesh").string(), "--constraints", (dir / "good.txt").string(),
                                 "--hard", "--precond", "slim", "--max-iters", "5", "--quiet"});
  CHECK(hard.code == akvf::kExitOk);
  write_text(dir / "inverting.txt", "0 0 0 0\n4 -1 -1 -1\n");
  const Outcome refused = akvf_run({"deform", (dir / "tet.mesh").string(), "--constraints",
                                    (dir / "inverting.txt").string(), "--hard", "--out", out.string(), "--quiet"});
  CHECK(refused.code == akvf::kExitInputError);
  CHECK(refused.err.find("hard constraints need a start without inverted tets") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("plot draws trace files as SVG lines, a malformed trace names its line") {
  const fs::path dir = scratch_dir("plot");
  write_text(dir / "a.csv", "iter,seconds,energy,status\n0,0,10,\n1,0.5,5,\n2,1.0,4.5,converged\n");
  write_text(dir / "bad.csv", "iter,seconds,energy,status\n0,0,10,\n1,x,5,\n");
  const fs::path svg = dir / "plot.svg";
  const Outcome ok = akvf_run({"plot", (dir / "a.csv").string() + "=first method", (dir / "a.csv").string(), "--x",
                               "seconds", "--minus", "4", "--out", svg.string()});
  CHECK(ok.code == akvf::kExitOk);
  const std::string text = read_text(svg);
  CHECK(text.find("<svg") == 0);
  CHECK(text.find(">first method</text>") != std::string::npos);
  CHECK(text.find(">a.csv</text>") != std::string::npos);
  CHECK(text.find(">energy - 4</text>") != std::string::npos);
  const Outcome bad = akvf_run({"plot", (dir / "bad.csv").string(), "--out", (dir / "bad.svg").string()});
  CHECK(bad.code == akvf::kExitInputError);
  CHECK(bad.err.find("line 3 of") != std::string::npos);
  CHECK(bad.err.find("column seconds: 'x' is not a number") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "bad.svg"));
  write_text(dir / "header_only.csv", "iter,seconds,energy,status\n");
  const Outcome empty = akvf_run({"plot", (dir / "header_only.csv").string(), "--out", (dir / "e.svg").string()});
  CHECK(empty.code == akvf::kExitInputError);
  CHECK(empty.err.find("header_only.csv: the trace has a header but no rows") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE(
    "the same run twice, with 1 and with 2 threads: byte-identical UV OBJ and SVG, identical traces but for the "
    "clocks") {
  const fs::path dir = scratch_dir("determinism");
  // A 24 x 24 bumpy grid written as OBJ.
  std::ostringstream obj;
  obj.precision(17);
  const int n = 24;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      obj << "v " << i / double(n - 1) << ' ' << j / double(n - 1) << ' '
          << 0.2 * std::sin(5.0 * i / n) * std::cos(4.0 * j / n) << '\n';
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i + 1, b = a + 1, c = a + n, d = c + 1;
      obj << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
    }
  write_text(dir / "grid.obj", obj.str());
  // The trace without its clock columns (seconds, precond_seconds, line_search_seconds).
  auto trace_without_clocks = [](const std::string& text) {
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line)) {
      std::vector<std::string> cells;
      std::istringstream row(line);
      for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
      REQUIRE(cells.size() >= 10);
      for (std::size_t k = 0; k < cells.size(); ++k)
        if (k != 1 && k != 8 && k != 9) out += cells[k] + ',';
      out += '\n';
    }
    return out;
  };
  std::vector<std::string> uv, svg, trace;
  for (const char* threads : {"1", "1", "2", "2"}) {
    const std::string tag = std::string("t") + threads + "_" + std::to_string(uv.size());
    const Outcome r = akvf_run({"param", (dir / "grid.obj").string(), "--threads", threads, "--max-iters", "12",
                                "--out", (dir / (tag + ".obj")).string(), "--svg", (dir / (tag + ".svg")).string(),
                                "--trace", (dir / (tag + ".csv")).string(), "--texture", "none", "--quiet"});
    REQUIRE(r.code == akvf::kExitOk);
    uv.push_back(read_text(dir / (tag + ".obj")));
    svg.push_back(read_text(dir / (tag + ".svg")));
    trace.push_back(trace_without_clocks(read_text(dir / (tag + ".csv"))));
  }
  REQUIRE(trace[0].find("precond_seconds") == std::string::npos);  // the clock columns are the ones dropped
  CHECK(trace[0].find("energy,grad_norm,step,ls_evals,flips,max_step,") != std::string::npos);
  for (std::size_t r = 1; r < uv.size(); ++r) {
    CHECK(uv[r] == uv[0]);
    CHECK(svg[r] == svg[0]);
    CHECK(trace[r] == trace[0]);
  }
}

TEST_CASE("a deformation's trace has the constraints' distance from their targets, a parameterization's has not") {
  const fs::path dir = scratch_dir("constraint_distance");
  const akvf::TetMesh cube = akvf::test::tet_grid(3);
  akvf::write_medit((dir / "cube.mesh").string(), cube);
  // For --hard (the preset's twist inverts tets when placed at once): the
  // bottom face held, the top face lifted by 0.05.
  std::ofstream lift(dir / "lift.txt");
  lift << std::setprecision(17);
  for (int v = 0; v < cube.num_vertices(); ++v)
    if (cube.V(v, 2) == 0 || cube.V(v, 2) == 1)
      lift << v << ' ' << cube.V(v, 0) << ' ' << cube.V(v, 1) << ' ' << cube.V(v, 2) * 1.05 << '\n';
  lift.close();
  for (const bool hard : {false, true}) {
    std::vector<std::string> args = {"deform",  (dir / "cube.mesh").string(), "--max-iters", "5",
                                     "--trace", (dir / "d.csv").string(),     "-q"};
    for (const std::string& arg : hard
                                      ? std::vector<std::string>{"--constraints", (dir / "lift.txt").string(), "--hard"}
                                      : std::vector<std::string>{"--preset", "slim-cube"})
      args.push_back(arg);
    REQUIRE(akvf_run(args).code == akvf::kExitOk);
    const akvf::TraceTable trace = akvf::read_trace_csv((dir / "d.csv").string());
    const std::vector<double>& distance = trace.column("constraint_distance", "d.csv");
    REQUIRE(distance.size() == trace.column("iter", "d.csv").size());
    if (hard) {
      for (const double d : distance) CHECK(d == 0);
      continue;
    }
    // The preset rotates two vertical edges by 0.3 pi and scales the other
    // two by 0.75 (slim_cube.h): far from their targets at the start, drawn
    // in by the soft constraints.
    CHECK(distance.front() > 0.1);
    CHECK(distance.back() < 0.1 * distance.front());
  }
  akvf::test::write_obj(dir / "bar.obj", akvf::bent_bar(21, 5));
  REQUIRE(akvf_run({"param", (dir / "bar.obj").string(), "--max-iters", "3", "--trace", (dir / "p.csv").string(), "-q"})
              .code == akvf::kExitOk);
  CHECK(read_text(dir / "p.csv").find("constraint_distance") == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("--summary writes the run's options, outcome and machine as JSON, for param and deform") {
  const fs::path dir = scratch_dir("summary");
  akvf::test::write_obj(dir / "bar.obj", akvf::bent_bar(21, 5));
  const Outcome param = akvf_run({"param", (dir / "bar.obj").string(), "--summary", (dir / "run.json").string(),
                                  "--max-iters", "7", "--precond", "newton", "-q"});
  CHECK(param.code == akvf::kExitOk);
  const nlohmann::json p = nlohmann::json::parse(read_text(dir / "run.json"));
  CHECK(p["problem"] == "param");
  CHECK(p["settings"]["precond"] == "newton");
  CHECK(p["settings"]["max_iters"] == 7);
  CHECK(p["settings"]["time_limit"] == "inf");
  CHECK(p["iterations"].get<int>() <= 7);
  CHECK(p["lower_bound"] == 4.0);
  CHECK(p["max_flips"] == 0);
  CHECK(p["elements"] == 2 * 20 * 4);
  for (const char* key : {"status", "message", "reached", "seconds", "final_energy", "grad_norm", "vertices",
                          "peak_memory_mb", "machine"})
    CHECK(p.contains(key));
  // Deformation, with the preset in its settings.
  const akvf::TetMesh cube = akvf::test::tet_grid(3);
  std::ofstream mesh(dir / "cube.mesh");
  mesh << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << cube.num_vertices() << "\n";
  for (int v = 0; v < cube.num_vertices(); ++v) mesh << cube.V.row(v) << " 0\n";
  mesh << "Tetrahedra\n" << cube.num_tets() << "\n";
  for (int t = 0; t < cube.num_tets(); ++t) mesh << (cube.T.row(t).array() + 1) << " 0\n";
  mesh << "End\n";
  mesh.close();
  const Outcome deform = akvf_run({"deform", (dir / "cube.mesh").string(), "--preset", "slim-cube", "--summary",
                                   (dir / "d.json").string(), "--max-iters", "3", "-q"});
  CHECK(deform.code == akvf::kExitOk);
  const nlohmann::json d = nlohmann::json::parse(read_text(dir / "d.json"));
  CHECK(d["problem"] == "deform");
  CHECK(d["settings"]["preset"] == "slim-cube");
  CHECK(d["lower_bound"] == 6.0);
  CHECK(d["elements"] == cube.num_tets());
  // A summary that names another output is refused before any work.
  const Outcome clash = akvf_run({"param", (dir / "bar.obj").string(), "--summary", (dir / "t.csv").string(), "--trace",
                                  (dir / "t.csv").string(), "-q"});
  CHECK(clash.code == akvf::kExitUsageError);
  CHECK(clash.err.find("--summary") != std::string::npos);
  CHECK(!fs::exists(dir / "t.csv"));
  fs::remove_all(dir);
}

TEST_CASE("--init file starts from the mesh file's texture coordinates, or says why it cannot") {
  const fs::path dir = scratch_dir("init_file");
  const akvf::TriMesh bar = akvf::bent_bar(21, 5);
  akvf::test::write_obj(dir / "bar.obj", bar);
  const fs::path uv = dir / "uv.obj";
  REQUIRE(akvf_run({"param", (dir / "bar.obj").string(), "--out", uv.string(), "-q"}).code == akvf::kExitOk);
  // From its own result: converged at once.
  const Outcome again = akvf_run({"param", uv.string(), "--init", "file", "-q"});
  CHECK(again.code == akvf::kExitOk);
  CHECK(again.out.find("status converged after 0 iterations") != std::string::npos);
  // Without texture coordinates.
  const Outcome none = akvf_run({"param", (dir / "bar.obj").string(), "--init", "file", "-q"});
  CHECK(none.code == akvf::kExitInputError);
  CHECK(none.err.find("has no texture coordinates (OBJ vt, PLY u,v or texcoord) for --init file") != std::string::npos);
  // Mirrored (every triangle inverted): mirrored back, with a warning.
  std::string text = read_text(uv), mirrored;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("vt ", 0) == 0) {
      std::istringstream v(line.substr(3));
      double a, b;
      v >> a >> b;
      std::ostringstream m;
      m << std::setprecision(17) << "vt " << -a << ' ' << b;
      line = m.str();
    }
    mirrored += line + "\n";
  }
  write_text(dir / "mirrored.obj", mirrored);
  const Outcome mirror = akvf_run({"param", (dir / "mirrored.obj").string(), "--init", "file", "-q"});
  CHECK(mirror.code == akvf::kExitOk);
  CHECK(mirror.err.find("invert every triangle (the other orientation convention): mirrored") != std::string::npos);
  // An interior vertex (row 1, column 1 of the grid) moved far away: the
  // first inverted triangle is named.
  std::string folded = text;
  std::size_t vt = folded.find("\nvt ") + 1;
  for (int k = 0; k < 22; ++k) vt = folded.find("\nvt ", vt) + 1;
  folded.replace(vt, folded.find('\n', vt) - vt, "vt 100 100");
  write_text(dir / "folded.obj", folded);
  const Outcome fold = akvf_run({"param", (dir / "folded.obj").string(), "--init", "file", "-q"});
  CHECK(fold.code == akvf::kExitInputError);
  CHECK(fold.err.find("the texture coordinates invert a triangle: triangle") != std::string::npos);
  // A seam: vertex 1 with two different UVs.
  std::string seam = text;
  seam.insert(seam.find("\nf ") + 1, "vt 5 5\n");
  const std::size_t face = seam.find("\nf 1/1 ");
  REQUIRE(face != std::string::npos);
  seam.replace(face, 7, "\nf 1/" + std::to_string(bar.num_vertices() + 1) + " ");
  write_text(dir / "seam.obj", seam);
  const Outcome seamed = akvf_run({"param", (dir / "seam.obj").string(), "--init", "file", "-q"});
  CHECK(seamed.code == akvf::kExitInputError);
  CHECK(seamed.err.find("vertex 1 has two different UVs") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a saved map restarts at the energy it ended with: --init file takes the energy's best uniform scale") {
  const fs::path dir = scratch_dir("restart");
  akvf::test::write_obj(dir / "bumpy.obj", akvf::test::bumpy_disk(12, 10));
  for (const std::string energy : {"symmetric-dirichlet", "arap", "mips"}) {
    CAPTURE(energy);
    // The textured OBJ's vt are in the unit square: not the optimizer's scale.
    // The first run ends near a minimum (a gradient of 1e-7), where its own
    // scale is the best one to well within 1e-9 of the energy.
    REQUIRE(akvf_run({"param", (dir / "bumpy.obj").string(), "--energy", energy, "--out", (dir / "uv.obj").string(),
                      "--grad-tol", "1e-7", "--summary", (dir / "first.json").string(), "-q"})
                .code == akvf::kExitOk);
    REQUIRE(akvf_run({"param", (dir / "uv.obj").string(), "--energy", energy, "--init", "file", "--trace",
                      (dir / "again.csv").string(), "-q"})
                .code == akvf::kExitOk);
    const nlohmann::json first = nlohmann::json::parse(read_text(dir / "first.json"));
    const double ended = first["final_energy"].get<double>();
    const double started = akvf::read_trace_csv((dir / "again.csv").string()).column("energy", "again.csv")[0];
    CHECK(std::abs(started - ended) <= 1e-9 * ended);
  }
  fs::remove_all(dir);
}

TEST_CASE("--out writes UV.mtl and a checkerboard beside the OBJ, vt in the unit square, --texture none does not") {
  const fs::path dir = scratch_dir("texture");
  akvf::test::write_obj(dir / "bar.obj", akvf::bent_bar(21, 5));
  REQUIRE(akvf_run({"param", (dir / "bar.obj").string(), "--out", (dir / "uv.obj").string(), "-q"}).code ==
          akvf::kExitOk);
  const std::string obj = read_text(dir / "uv.obj");
  CHECK(obj.find("\nmtllib uv.mtl\n") != std::string::npos);
  CHECK(obj.find("\nusemtl checker\n") != std::string::npos);
  CHECK(read_text(dir / "uv.mtl").find("map_Kd uv_checker.png") != std::string::npos);
  CHECK(read_text(dir / "uv_checker.png").rfind("\x89PNG", 0) == 0);
  double lo = 1e300, hi = -1e300;
  std::istringstream lines(obj);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("vt ", 0) == 0) {
      std::istringstream v(line.substr(3));
      double a, b;
      v >> a >> b;
      lo = std::min({lo, a, b});
      hi = std::max({hi, a, b});
    }
  CHECK(lo == doctest::Approx(0.0));
  CHECK(hi == doctest::Approx(1.0));  // the longer side spans the texture
  // --texture none: vt at the input's scale, no MTL.
  REQUIRE(
      akvf_run({"param", (dir / "bar.obj").string(), "--out", (dir / "plain.obj").string(), "--texture", "none", "-q"})
          .code == akvf::kExitOk);
  CHECK(read_text(dir / "plain.obj").find("mtllib") == std::string::npos);
  CHECK(!fs::exists(dir / "plain.mtl"));
  // The files beside the OBJ are outputs too: one that is the input is refused.
  akvf::test::write_obj(dir / "clash_checker.png", akvf::bent_bar(21, 5));
  const Outcome clash =
      akvf_run({"param", (dir / "clash_checker.png").string(), "--out", (dir / "clash.obj").string(), "-q"});
  CHECK(clash.code == akvf::kExitUsageError);
  CHECK(clash.err.find("the checkerboard of --out") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("an OBJ named with spaces gets side files without them (readers split mtllib and map_Kd on spaces)") {
  const fs::path dir = scratch_dir("spaces");
  akvf::test::write_obj(dir / "bar.obj", akvf::bent_bar(11, 3));
  REQUIRE(akvf_run({"param", (dir / "bar.obj").string(), "--out", (dir / "my uv.obj").string(), "-q"}).code ==
          akvf::kExitOk);
  CHECK(read_text(dir / "my uv.obj").find("mtllib my_uv.mtl\n") != std::string::npos);
  CHECK(read_text(dir / "my_uv.mtl").find("map_Kd my_uv_checker.png\n") != std::string::npos);
  CHECK(fs::exists(dir / "my_uv_checker.png"));
  fs::remove_all(dir);
}

TEST_CASE("counts read as a person writes them: 1 face, 3 vertices") {
  const fs::path dir = scratch_dir("one_face");
  write_text(dir / "one.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0.2\nf 1 2 3\n");
  const Outcome r = akvf_run({"param", (dir / "one.obj").string(), "-q"});
  CHECK(r.code == akvf::kExitOk);
  CHECK(r.out.find("one.obj: 3 vertices, 1 face; energy") != std::string::npos);
}

TEST_CASE("view says what is wrong with its inputs: a vt out of range, an integer texcoord, a summary not an object") {
  if (!akvf::html_view_available()) return akvf::test::skip("three.js was not found at configure time");
  const fs::path dir = scratch_dir("view_inputs");
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n";
  write_text(dir / "a.obj", square + "f 1/1 2/2 3/3\nf 1/1 3/3 4/9\n");
  Outcome r = akvf_run({"view", (dir / "a.obj").string()});
  CHECK(r.code == akvf::kExitInputError);
  CHECK(r.err == "error: " + (dir / "a.obj").string() +
                     ": corner 3 of face 2 names a texture coordinate the file does not have (its `vt` index is out "
                     "of range) (numbered from 1, as in the file); the view (write them with akvf param --out) needs "
                     "one at every corner\n");
  write_text(dir / "b.obj", square + "f 1/1 2/2 3/3\nf 1/1 3/3 4\n");
  r = akvf_run({"view", (dir / "b.obj").string()});
  CHECK(r.err.find("corner 3 of face 2 has no texture coordinate (numbered from 1") != std::string::npos);
  write_text(dir / "c.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar int texcoord\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 6 0 0 1 0 0 1\n");
  r = akvf_run({"view", (dir / "c.ply").string()});
  CHECK(r.code == akvf::kExitInputError);
  CHECK(r.err == "error: line 7 of " + (dir / "c.ply").string() +
                     ": the face property 'texcoord' is a list of integers; texture coordinates are a float or double "
                     "list (u, v per corner)\n");
  write_text(dir / "d.obj", square + "f 1/1 2/2 3/3\n");
  write_text(dir / "array.json", "[1, 2]");
  r = akvf_run({"view", (dir / "d.obj").string(), "--summary", (dir / "array.json").string()});
  CHECK(r.code == akvf::kExitInputError);
  CHECK(r.err == "error: " + (dir / "array.json").string() +
                     ": not a run summary: a JSON object was expected, found an array\n");
  r = akvf_run({"view", (dir / "d.obj").string()});
  CHECK(r.code == akvf::kExitOk);
  CHECK(r.out == "wrote " + (dir / "d.html").string() + " (1 face)\n");
  fs::remove_all(dir);
}
