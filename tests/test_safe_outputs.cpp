// Outputs never lose data: links are followed, devices and FIFOs written in
// place, an output never names an input or another output, a bad output is
// found before any work, temporaries never outlive a run; and the command-line
// consistency items (threads, exit codes, extensions, ranges, aliases).
#include <doctest/doctest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "akvf/error.h"
#include "cli/exit_codes.h"
#include "cli/file_arguments.h"
#include "framework/process/output_file.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;

namespace {

using akvf::test::read_text;
using akvf::test::write_text;
using Outcome = akvf::test::CliOutcome;

Outcome akvf_run(const std::vector<std::string>& args) { return akvf::test::run_cli(args); }

fs::path scratch(const std::string& name) { return akvf::test::scratch_dir("safe_outputs_" + name); }

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0.2\nv 0 1 0\nv 0.5 0.5 0.1\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
const std::string kTets =
    "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
    "Tetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n";

// Files in `dir` whose names contain ".tmp".
int temporaries_in(const fs::path& dir) {
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    count += entry.path().filename().string().find(".tmp") != std::string::npos;
  return count;
}

}  // namespace

TEST_CASE("a symbolic link given as output stays a link, the file it names receives the content") {
  const fs::path dir = scratch("link");
  write_text(dir / "real.txt", "old");
  fs::create_symlink("real.txt", dir / "link.txt");
  akvf::write_file_atomically((dir / "link.txt").string(), [](std::ostream& out) { out << "new"; });
  CHECK(fs::is_symlink(dir / "link.txt"));
  CHECK(read_text(dir / "real.txt") == "new");
  // A dangling link: the file it would name is created, the link kept.
  fs::create_symlink("sub/target.txt", dir / "dangling.txt");
  fs::create_directories(dir / "sub");
  akvf::write_file_atomically((dir / "dangling.txt").string(), [](std::ostream& out) { out << "x"; });
  CHECK(fs::is_symlink(dir / "dangling.txt"));
  CHECK(read_text(dir / "sub" / "target.txt") == "x");
  CHECK(temporaries_in(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("a character device or a FIFO is written in place, never replaced") {
  akvf::write_file_atomically("/dev/null", [](std::ostream& out) { out << "discarded"; });
  struct stat st;
  REQUIRE(::stat("/dev/null", &st) == 0);
  CHECK(S_ISCHR(st.st_mode));

  const fs::path dir = scratch("fifo");
  const std::string fifo = (dir / "pipe").string();
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string received;
  std::thread reader([&] { received = read_text(fifo); });
  akvf::write_file_atomically(fifo, [](std::ostream& out) { out << "through the pipe"; });
  reader.join();
  CHECK(received == "through the pipe");
  CHECK(fs::is_fifo(fifo));
  CHECK(temporaries_in(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("output checks: a folder, a missing folder, a socket-like kind are refused before writing") {
  const fs::path dir = scratch("checks");
  CHECK(akvf::test::error_message([&] { akvf::check_output_writable(dir.string()); }) ==
        "cannot write " + dir.string() + ": it is a folder; give a file name");
  CHECK(akvf::test::error_message([&] { akvf::check_output_writable((dir / "no" / "x").string()); }) ==
        "cannot write " + (dir / "no" / "x").string() + ": folder " + (dir / "no").string() + " does not exist");
  CHECK(akvf::test::error_message([&] { akvf::check_output_writable("/dev/null"); }).empty());
  CHECK(akvf::test::error_message([&] { akvf::check_output_writable((dir / "new.txt").string()); }).empty());
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("the temporary file of a write in progress is removed by the second-signal cleanup") {
  const fs::path dir = scratch("pending");
  bool seen = false, removed = false;
  CHECK_THROWS_AS(akvf::write_file_atomically((dir / "out.txt").string(),
                                              [&](std::ostream& out) {
                                                out << "partial" << std::flush;
                                                seen = temporaries_in(dir) == 1;
                                                akvf::remove_pending_temporary_files();
                                                removed = temporaries_in(dir) == 0;
                                                throw akvf::OutputError("stop");
                                              }),
                  akvf::OutputError);
  CHECK(seen);
  CHECK(removed);
  CHECK_FALSE(fs::exists(dir / "out.txt"));
  fs::remove_all(dir);
}

TEST_CASE("an output that names an input or another output is a command-line error and nothing is written") {
  const fs::path dir = scratch("clash");
  const std::string mesh = (dir / "m.obj").string();
  write_text(mesh, kSquare);
  fs::create_symlink("m.obj", dir / "alias.obj");
  auto param = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"param", mesh, "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    return akvf_run(args);
  };
  Outcome r = param({"--trace", mesh});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err == "error: --trace " + mesh + " is the same file as the input mesh " + mesh +
                     "; an output never replaces an input: choose another name\n");
  CHECK(param({"--out", (dir / "alias.obj").string()}).code == akvf::kExitUsageError);
  CHECK(param({"--svg", (dir / "sub" / ".." / "m.obj").string()}).code == akvf::kExitUsageError);
  const std::string x = (dir / "x.obj").string();
  r = param({"--out", x, "--trace", x, "--svg", x});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err == "error: --out and --trace both name " + x + "; each output needs a file of its own\n");
  CHECK(read_text(mesh) == kSquare);
  CHECK_FALSE(fs::exists(x));
  // Devices may be named by several outputs.
  CHECK(param({"--out", "/dev/null", "--trace", "/dev/null", "--svg", "/dev/null"}).code == akvf::kExitOk);

  const std::string tets = (dir / "t.mesh").string(), constraints = (dir / "c.txt").string();
  write_text(tets, kTets);
  write_text(constraints, "0 0 0 0\n4 1.2 1 1\n");
  r = akvf_run({"deform", tets, "--constraints", constraints, "--out", tets, "-q"});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err.find("--out " + tets + " is the same file as the input mesh") != std::string::npos);
  r = akvf_run({"deform", tets, "--constraints", constraints, "--trace", constraints, "-q"});
  CHECK(r.err.find("--trace " + constraints + " is the same file as --constraints") != std::string::npos);
  CHECK(read_text(tets) == kTets);
  CHECK(read_text(constraints) == "0 0 0 0\n4 1.2 1 1\n");

  const std::string trace = (dir / "t.csv").string();
  write_text(trace, "iter,energy,status\n0,5,\n1,4,converged\n");
  r = akvf_run({"plot", trace + "=run", "--out", trace});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(read_text(trace) == "iter,energy,status\n0,5,\n1,4,converged\n");
  CHECK(temporaries_in(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("an output never replaces the material library or the texture the input OBJ uses") {
  const fs::path dir = scratch("materials");
  const std::string mesh = (dir / "m.obj").string();
  write_text(mesh, "mtllib shared.mtl\n" + kSquare);
  write_text(dir / "shared.mtl", "newmtl a\nmap_Kd out_checker.png\n");
  write_text(dir / "out_checker.png", "image");
  Outcome r = akvf_run({"param", mesh, "-q", "--out", (dir / "shared.obj").string()});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err == "error: the MTL of --out " + (dir / "shared.mtl").string() +
                     " is the same file as the input's material file " + (dir / "shared.mtl").string() +
                     "; an output never replaces an input: choose another name\n");
  r = akvf_run({"param", mesh, "-q", "--out", (dir / "out.obj").string()});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err.find("the checkerboard of --out") != std::string::npos);
  CHECK(read_text(dir / "shared.mtl") == "newmtl a\nmap_Kd out_checker.png\n");
  CHECK(read_text(dir / "out_checker.png") == "image");
  CHECK_FALSE(fs::exists(dir / "shared.obj"));
  // Whatever the output format: the layout image or the summary is checked too.
  r = akvf_run({"param", mesh, "-q", "--png", (dir / "out_checker.png").string()});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err.find("--png " + (dir / "out_checker.png").string() + " is the same file as the input's material file") !=
        std::string::npos);
  r = akvf_run({"param", mesh, "-q", "--out", (dir / "m.ply").string(), "--summary", (dir / "shared.mtl").string()});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(read_text(dir / "out_checker.png") == "image");
  CHECK(read_text(dir / "shared.mtl") == "newmtl a\nmap_Kd out_checker.png\n");
  CHECK_FALSE(fs::exists(dir / "m.ply"));
  // Without a material of its own the output keeps the input's.
  r = akvf_run({"param", mesh, "-q", "--out", (dir / "out.obj").string(), "--texture", "none"});
  CHECK(r.code == akvf::kExitOk);
  CHECK(read_text(dir / "out.obj").find("mtllib shared.mtl\n") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a write that fails says why, and the side files of a failed OBJ go with it") {
  const fs::path dir = scratch("full");
  const std::string mesh = (dir / "m.obj").string();
  akvf::test::write_obj(mesh, akvf::test::bumpy_disk(40, 40));
  // A file size limit the MTL and the checkerboard fit in and the OBJ does not.
  struct rlimit old_limit;
  REQUIRE(::getrlimit(RLIMIT_FSIZE, &old_limit) == 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit limit = old_limit;
  limit.rlim_cur = 20000;
  REQUIRE(::setrlimit(RLIMIT_FSIZE, &limit) == 0);
  const Outcome r = akvf_run({"param", mesh, "-q", "--out", (dir / "x.obj").string()});
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  CHECK(r.code == akvf::kExitOutputError);
  CHECK(r.err == "error: error while writing " + (dir / "x.obj").string() + ": File too large\n");
  CHECK_FALSE(fs::exists(dir / "x.obj"));
  CHECK_FALSE(fs::exists(dir / "x.mtl"));
  CHECK_FALSE(fs::exists(dir / "x_checker.png"));
  CHECK(temporaries_in(dir) == 0);
  // A device in place: the reason too.
  if (fs::exists("/dev/full")) {
    const Outcome full = akvf_run({"param", mesh, "-q", "--out", "/dev/full"});
    CHECK(full.err == "error: error while writing /dev/full: No space left on device\n");
  }
  fs::remove_all(dir);
}

TEST_CASE("output names beyond the file system's limits are refused before any work") {
  const fs::path dir = scratch("names");
  const std::string mesh = (dir / "m.obj").string();
  write_text(mesh, kSquare);
  const std::string stem = (dir / std::string(250, 'a')).string();
  // 250 + ".html" fits; its temporary name is shortened to fit too.
  Outcome r = akvf_run({"param", mesh, "-q", "--view", stem + ".html", "--summary", stem + ".json"});
  CHECK(r.code == akvf::kExitOk);
  CHECK(fs::exists(stem + ".html"));
  r = akvf_run({"param", mesh, "-q", "--out", stem + "x.obj"});  // the checkerboard's name would be too long
  CHECK(r.code == akvf::kExitOutputError);
  CHECK(r.err == "error: the checkerboard of --out: cannot write " + stem +
                     "x_checker.png: its file name is 263 "
                     "bytes long; the file system allows at most 255\n");
  r = akvf_run({"param", mesh, "-q", "--summary", stem + "xxxxxxxxxx.json"});
  CHECK(r.code == akvf::kExitOutputError);
  CHECK(r.err == "error: cannot write " + stem +
                     "xxxxxxxxxx.json: its file name is 265 bytes long; the file system "
                     "allows at most 255\n");
  CHECK(temporaries_in(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("a bad output path is found before the mesh is read (exit 4), in every command") {
  const fs::path dir = scratch("early");
  const std::string folder = (dir / "folder").string();
  fs::create_directories(folder);
  // The input does not even exist: the output is checked first.
  Outcome r = akvf_run({"param", (dir / "missing.obj").string(), "--out", folder});
  CHECK(r.code == akvf::kExitOutputError);
  CHECK(r.err == "error: cannot write " + folder + ": it is a folder; give a file name\n");
  r = akvf_run({"deform", (dir / "missing.mesh").string(), "--preset", "slim-cube", "--trace", folder});
  CHECK(r.code == akvf::kExitOutputError);
  r = akvf_run({"plot", (dir / "missing.csv").string(), "--out", (dir / "no" / "p.svg").string()});
  CHECK(r.code == akvf::kExitOutputError);
  // demo and experiment: the output folder is a file.
  write_text(dir / "file", "x");
  r = akvf_run({"demo", "--out-dir", (dir / "file").string(), "-q"});
  CHECK(r.code == akvf::kExitOutputError);
  CHECK(r.err.find("error: cannot create the output folder " + (dir / "file").string()) == 0);
  write_text(dir / "m.json",
             R"({"name": "e", "meshes": [{"label": "a", "missing": "none"}], "methods": [{"label": "m"}]})");
  r = akvf_run({"experiment", (dir / "m.json").string(), "--out-dir", (dir / "file" / "sub").string()});
  CHECK(r.code == akvf::kExitOutputError);
  CHECK(read_text(dir / "file") == "x");
  fs::remove_all(dir);
}

TEST_CASE("command-line consistency: threads, extensions, ranges, aliases, version, help, empty shards") {
  const fs::path dir = scratch("consistency");
  const std::string mesh = (dir / "m.obj").string();
  write_text(mesh, kSquare);
  CHECK(akvf_run({"param", mesh, "-q", "--threads", "0"}).code == akvf::kExitOk);
  Outcome r = akvf_run({"param", mesh, "-q", "--threads", "-1"});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err == "error: option --threads must be >= 0 (0 = all cores), found -1\n");
  r = akvf_run({"deform", mesh, "--preset", "slim-cube", "--threads", "-2"});
  CHECK(r.code == akvf::kExitUsageError);
  r = akvf_run({"param", mesh, "--out", (dir / "uv.off").string()});
  CHECK(r.code == akvf::kExitUsageError);
  CHECK(r.err == "error: option --out: cannot write '" + (dir / "uv.off").string() +
                     "': no writer produces '.off' (formats: .obj, .ply, .glb)\n");
  r = akvf_run({"param", mesh, "--max-iters", "99999999999999"});
  CHECK(r.err == "error: option --max-iters: 99999999999999 is out of range (-2147483648 to 2147483647)\n");
  r = akvf_run({"param", mesh, "--max-iters", "1e400"});
  CHECK(r.err == "error: option --max-iters: '1e400' is not an integer\n");
  CHECK(akvf_run({"param", "-h"}).out.find("usage: akvf param") == 0);
  r = akvf_run({"param", mesh, "-q"});
  CHECK(r.code == akvf::kExitOk);
  CHECK(r.err.empty());
  r = akvf_run({"--version"});
  CHECK(r.code == akvf::kExitOk);
  CHECK(r.out.rfind("akvf ", 0) == 0);
  CHECK(akvf_run({"list", "--help"}).out.find("usage: akvf list") == 0);
  CHECK(akvf_run({"experiment", "merge", "--help"}).out.find("usage: akvf experiment merge") == 0);
  CHECK(akvf_run({"experiment", "report", "-h"}).out.find("usage: akvf experiment report") == 0);
  write_text(dir / "m.json",
             R"({"name": "e", "meshes": [{"label": "a", "missing": "none"}], "methods": [{"label": "m"}]})");
  r = akvf_run({"experiment", (dir / "m.json").string(), "--shard", "1000/1000", "--out-dir", (dir / "r").string()});
  CHECK(r.code == akvf::kExitOk);
  CHECK(r.err == "e: shard 1000/1000 is empty: the manifest has 1 cases; nothing to run\n");
  CHECK_FALSE(fs::exists(dir / "r"));
  fs::remove_all(dir);
}
