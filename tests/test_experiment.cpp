// The experiment runner: manifest validation, a tiny end-to-end manifest,
// shard + merge equal to one run, resume.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "cli/akvf_cli.h"
#include "cli/exit_codes.h"
#include "experiments/runner/manifest.h"
#include "io/text_utilities.h"
#include "solvers/algebraic_multigrid.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;

namespace {

std::string manifest_error(const std::string& text) {
  return akvf::test::error_message([&] { akvf::parse_manifest(text, "m.json"); });
}

fs::path scratch(const std::string& name) { return akvf::test::scratch_dir("experiment_test_" + name); }

using akvf::test::read_text;
using akvf::test::write_obj;

int akvf_run(const std::vector<std::string>& args, std::string* out = nullptr, std::string* err = nullptr) {
  std::ostringstream o, e;
  const int code = akvf::run_akvf(args, o, e);
  if (out) *out = o.str();
  if (err) *err = e.str();
  return code;
}

// The comparable part of a summary: everything but times, memory and the machine.
std::string result_of(const fs::path& summary) {
  auto j = nlohmann::json::parse(read_text(summary));
  j.erase("seconds");
  j.erase("machine");
  j.erase("peak_memory_mb");
  return j.dump();
}

// Bumpy small is solved by multigrid where the build has it (as Figure 6's
// largest mesh names its linear solver), so shards are checked with both
// linear solvers.
std::string tiny_manifest() {
  const std::string small_solver = akvf::AlgebraicMultigrid::available() ? "amg" : "cholmod";
  return R"({
  "name": "tiny",
  "defaults": {"grad_tol": 1e-6, "max_iters": 40, "time_limit": 20},
  "meshes": [
    {"label": "Bumpy", "file": "bumpy.obj", "paper": {"AKVF": 0.5}},
    {"label": "Gone", "missing": "not in the test data"},
    {"label": "Bumpy small", "file": "small.obj", "subdivide": 1, "linear_solver": ")" +
         small_solver + R"("}
  ],
  "methods": [
    {"label": "AKVF", "precond": "akvf", "snapshots": [2]},
    {"label": "SLIM", "precond": "slim"}
  ]
})";
}

// A Markdown table with its times ("0.0019 s") masked.
std::string without_seconds(const std::string& table) {
  return std::regex_replace(table, std::regex(R"([0-9][0-9.e+-]* s\b)"), "(time) s");
}

// table.csv without its clock column (seconds), which differs between runs.
std::string table_without_clock(const fs::path& csv) {
  std::istringstream in(read_text(csv));
  std::string line, out;
  int seconds_column = -1;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (seconds_column < 0)
      seconds_column = static_cast<int>(std::find(cells.begin(), cells.end(), "seconds") - cells.begin());
    if (seconds_column < static_cast<int>(cells.size())) cells.erase(cells.begin() + seconds_column);
    for (const auto& cell : cells) out += cell + ",";
    out += "\n";
  }
  return out;
}

}  // namespace

TEST_CASE("manifest errors point at the offending key") {
  const std::string base_mesh = R"("meshes": [{"label": "A", "file": "a.obj"}])";
  CHECK(
      manifest_error(R"({"meshes": [{"label": "A", "file": "a.obj"}], "methods": [{"label": "X", "precond": "slm"}]})")
          .find("m.json: methods[0].precond: unknown preconditioner 'slm'") == 0);
  CHECK(manifest_error("{" + base_mesh + R"(, "methods": [{"label": "X", "energi": "arap"}]})")
            .find("m.json: methods[0].energi: unknown key (valid: ") == 0);
  CHECK(manifest_error("{" + base_mesh + R"(, "defaults": {"energy": "nope"}, "methods": [{"label": "X"}]})")
            .find("m.json: defaults.energy: unknown energy 'nope'") == 0);
  CHECK(manifest_error("{" + base_mesh + R"(, "methods": [{"label": "X", "max_iters": 1.5}]})") ==
        "m.json: methods[0].max_iters: expected an integer, found 1.5");
  CHECK(manifest_error(R"({"meshes": [{"label": "A"}], "methods": [{"label": "X"}]})") ==
        "m.json: meshes[0]: give exactly one of \"file\" and \"missing\" (the reason the mesh is not available)");
  CHECK(manifest_error("{" + base_mesh + R"(, "methods": [{"label": "X"}, {"label": "x"}]})") ==
        "m.json: methods[1].label: duplicate method label");
  CHECK(manifest_error("{" + base_mesh + R"(, "methods": [{"label": "X", "problem": "deform"}]})") ==
        "m.json: methods[0]: a deform case needs exactly one of \"preset\" and \"constraints\"");
  CHECK(manifest_error("{\n\"meshes\": [\n,]}").find("line 3 of m.json: invalid JSON") == 0);
  CHECK(manifest_error(R"({"meshes": []})") == "m.json: meshes: expected a non-empty array of meshes");
  // Found by fuzz_manifest: a number beyond double's range escaped as nlohmann's out_of_range.
  CHECK(manifest_error("{\"meshes\": [{\"label\": \"A\",\n\"file\": \"a.obj\", \"subdivide\": 4e999}]}") ==
        "line 2 of m.json: invalid JSON: number 4e999 is out of range");
  // A key given twice: refused, not the last one silently kept.
  CHECK(manifest_error("{" + base_mesh +
                       R"(, "methods": [{"label": "Newton", "precond": "newton", "precond": "identity"}]})") ==
        "m.json: key \"precond\" appears twice in one object (name each key once)");
  CHECK(manifest_error("{" + base_mesh + R"(, "methods": [{"label": "X"}], "methods": [{"label": "Y"}]})") ==
        "m.json: key \"methods\" appears twice in one object (name each key once)");
  // Nesting 100 000 deep is refused before it can exhaust the stack.
  CHECK(manifest_error(std::string(100000, '[') + std::string(100000, ']')) ==
        "m.json: JSON nested deeper than 256 levels");
}

TEST_CASE("a tiny manifest runs end to end, shards merged give the same results as one run, resume skips") {
  const fs::path dir = scratch("tiny");
  const fs::path data = dir / "data";
  fs::create_directories(data);
  write_obj(data / "bumpy.obj", akvf::test::bumpy_disk(8, 8));
  write_obj(data / "small.obj", akvf::test::bumpy_disk(5, 5));
  std::ofstream(dir / "tiny.json") << tiny_manifest();
  const std::string manifest = (dir / "tiny.json").string();

  std::string table, log;
  REQUIRE(akvf_run({"experiment", manifest, "--data-dir", data.string(), "--out-dir", (dir / "all").string()}, &table,
                   &log) == akvf::kExitOk);
  CHECK(log.find("[1/6] Bumpy / AKVF: converged") != std::string::npos);
  CHECK(log.find("[3/6] Gone / AKVF: missing (not in the test data)") != std::string::npos);
  CHECK(log.find("left") != std::string::npos);
  CHECK(table.find("| Gone |  | mesh not available | mesh not available | ") != std::string::npos);
  CHECK(table.find("| paper AKVF |") != std::string::npos);
  CHECK(fs::exists(dir / "all" / "table.md"));
  CHECK(read_text(dir / "all" / "table.csv").find("mesh,method,status,reached,iterations,seconds") == 0);
  CHECK(fs::exists(dir / "all" / "plots" / "bumpy-iterations.svg"));
  CHECK(fs::exists(dir / "all" / "plots" / "bumpy-small-seconds.svg"));
  // Two mesh sizes (bumpy and bumpy small subdivided): the scaling plot, one line per method.
  const std::string scaling = read_text(dir / "all" / "plots" / "seconds-per-iteration.svg");
  CHECK(scaling.find("seconds per iteration") != std::string::npos);
  CHECK(scaling.find(">AKVF<") != std::string::npos);
  CHECK(scaling.find(">SLIM<") != std::string::npos);
  CHECK(fs::exists(dir / "all" / "cases" / "bumpy--akvf" / "iter-2.svg"));
  // index.html: the table, the plots and per case its links (no views without --views).
  const std::string index = read_text(dir / "all" / "index.html");
  CHECK(index.find("<th>paper AKVF</th>") != std::string::npos);
  CHECK(index.find("<img src=\"plots/bumpy-iterations.svg\"") != std::string::npos);
  CHECK(index.find("<a href=\"cases/bumpy--akvf/final.svg\">") != std::string::npos);
  CHECK(index.find("view.html") == std::string::npos);
  const auto summary = nlohmann::json::parse(read_text(dir / "all" / "cases" / "bumpy--akvf" / "summary.json"));
  CHECK(summary["reached"] == true);
  CHECK(summary["max_flips"] == 0);
  CHECK(summary["machine"]["cores"].get<int>() >= 1);
  CHECK(summary["machine"]["versions"].contains("cholmod"));
  CHECK(summary["peak_memory_mb"].get<double>() > 0);
  // small.obj is a 5 x 5 grid (32 triangles), subdivided once.
  const auto small = nlohmann::json::parse(read_text(dir / "all" / "cases" / "bumpy-small--slim" / "summary.json"));
  CHECK(small["elements"] == 128);

  // A corrupt summary: the report names the file, as a malformed input.
  fs::copy(dir / "all", dir / "corrupt", fs::copy_options::recursive);
  std::ofstream(dir / "corrupt" / "cases" / "bumpy--akvf" / "summary.json") << "{\"status\": ";
  std::string report_out, report_err;
  CHECK(akvf_run({"experiment", "report", (dir / "corrupt").string()}, &report_out, &report_err) ==
        akvf::kExitInputError);
  CHECK(report_err.find((dir / "corrupt" / "cases" / "bumpy--akvf" / "summary.json").string() + ": invalid JSON") !=
        std::string::npos);

  for (const char* shard : {"1/2", "2/2"})
    REQUIRE(akvf_run({"experiment", manifest, "--data-dir", data.string(), "--out-dir",
                      (dir / (std::string("shard") + shard[0])).string(), "--shard", shard}) == akvf::kExitOk);
  CHECK(fs::exists(dir / "shard1" / "cases" / "bumpy--akvf" / "summary.json"));
  CHECK_FALSE(fs::exists(dir / "shard1" / "cases" / "bumpy--slim" / "summary.json"));
  REQUIRE(akvf_run({"experiment", "merge", (dir / "shard1").string(), (dir / "shard2").string(), "--out-dir",
                    (dir / "merged").string()}) == akvf::kExitOk);
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(dir / "all" / "cases")) {
    CAPTURE(entry.path().filename().string());
    CHECK(result_of(entry.path() / "summary.json") ==
          result_of(dir / "merged" / "cases" / entry.path().filename() / "summary.json"));
    ++compared;
  }
  CHECK(compared == 6);
  // The merged tables are the one run's but for the clocks: times masked in
  // table.md's cells, the seconds column dropped from table.csv.
  CHECK(without_seconds(read_text(dir / "merged" / "table.md")) ==
        without_seconds(read_text(dir / "all" / "table.md")));
  CHECK(table_without_clock(dir / "merged" / "table.csv") == table_without_clock(dir / "all" / "table.csv"));
  CHECK(table_without_clock(dir / "all" / "table.csv").find(",seconds,") == std::string::npos);
  if (akvf::AlgebraicMultigrid::available()) {  // the small mesh's cases were solved by multigrid
    const auto merged =
        nlohmann::json::parse(read_text(dir / "merged" / "cases" / "bumpy-small--akvf" / "summary.json"));
    CHECK(merged["settings"]["linear_solver"] == "amg");
    CHECK(merged["linear_algebra"]["multigrid_setups"].get<int>() > 0);
    CHECK(merged["linear_algebra"]["factorizations"] == 0);
  }
  // --views: a view per parameterization case, linked from index.html.
  REQUIRE(akvf_run({"experiment", manifest, "--data-dir", data.string(), "--out-dir", (dir / "views").string(),
                    "--views", "--shard", "1/2"}) == akvf::kExitOk);
  CHECK(fs::exists(dir / "views" / "cases" / "bumpy--akvf" / "view.html"));
  CHECK(read_text(dir / "views" / "cases" / "bumpy--akvf" / "view.html").find("\"final_energy\"") != std::string::npos);
  CHECK(read_text(dir / "views" / "index.html").find("<a href=\"cases/bumpy--akvf/view.html\">") != std::string::npos);

  REQUIRE(
      akvf_run({"experiment", manifest, "--data-dir", data.string(), "--out-dir", (dir / "all").string(), "--resume"},
               nullptr, &log) == akvf::kExitOk);
  CHECK(log.find("6 skipped") != std::string::npos);
  std::ofstream(dir / "other.json")
      << R"({"name": "tiny", "meshes": [{"label": "A", "missing": "x"}], "methods": [{"label": "X"}]})";
  CHECK(akvf_run({"experiment", (dir / "other.json").string(), "--out-dir", (dir / "all").string()}, nullptr, &log) ==
        akvf::kExitOutputError);
  CHECK(log.find("holds the results of a different manifest") != std::string::npos);
  CHECK(akvf_run({"experiment", manifest, "--shard", "3/2"}, nullptr, &log) == akvf::kExitUsageError);
  fs::remove_all(dir);
}
