"""Runs every code block of README.md and the reference docs, as written.

From a scratch folder that looks like the repository root (its top-level
entries linked, `../shared` beside it when the meshes are there), so that
outputs land in the scratch folder:
  ```sh      run by bash -euo pipefail (each must take under a minute)
  ```python  run by this interpreter with the built module on PYTHONPATH
  ```cpp     a complete program (with main), built against a fresh
             `cmake --install` prefix with find_package(akvf) and run
Other languages (cmake, json, bibtex, text) are not run. A block right
after a line `<!-- fragment -->` (a piece of a larger program) or
`<!-- not run: REASON -->` (minutes of work, or it writes into the
repository) is skipped; every other block must run and exit 0.
Usage: /usr/bin/python3 tests/doc_blocks.py SOURCE_DIR BUILD_DIR CMAKE
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

REFERENCE_DOCS = ["README.md", "docs/api.md", "docs/cli.md", "docs/deformation.md", "docs/design.md",
                  "docs/energies.md", "docs/experiments.md", "docs/extending.md", "docs/options.md", "docs/pairs.md",
                  "docs/paper_map.md", "docs/performance.md", "docs/python.md", "docs/results.md",
                  "docs/robustness.md"]
RUN = {"sh", "python", "cpp"}


def blocks(source, name):
    """(line, language, text, skip reason or None) of every fenced block."""
    lines = open(os.path.join(source, name), encoding="utf-8").read().split("\n")
    i, found = 0, []
    while i < len(lines):
        m = re.match(r"^```(\w*)\s*$", lines[i])
        if not m:
            i += 1
            continue
        end = i + 1
        while end < len(lines) and not lines[end].startswith("```"):
            end += 1
        before = lines[i - 1].strip() if i > 0 else ""
        skip = None
        marker = re.match(r"<!-- (fragment|not run: .*) -->", before)
        if marker:
            skip = marker.group(1)
        found.append((i + 1, m.group(1), "\n".join(lines[i + 1:end]) + "\n", skip))
        i = end + 1
    return found


def main():
    source, build = (os.path.abspath(a) for a in sys.argv[1:3])
    cmake = shutil.which(sys.argv[3]) or sys.argv[3]
    shared = os.path.join(os.path.dirname(source), "shared")
    work = tempfile.mkdtemp(prefix="akvf_doc_blocks_")
    root = os.path.join(work, "repo")
    os.mkdir(root)
    for entry in os.listdir(source):
        if not entry.startswith("."):
            os.symlink(os.path.join(source, entry), os.path.join(root, entry))
    if os.path.isdir(shared):
        os.symlink(shared, os.path.join(work, "shared"))
    env = dict(os.environ, PYTHONPATH=os.path.join(build, "python"))
    failures, ran, skipped = [], 0, 0
    programs = []  # (where, source text)
    try:
        for name in REFERENCE_DOCS:
            for line, language, text, skip in blocks(source, name):
                where = "%s:%d" % (name, line)
                if language not in RUN:
                    continue
                if skip:
                    skipped += 1
                    continue
                if "../shared" in text and not os.path.isdir(shared):
                    print("SKIPPED %s: ../shared is absent" % where)
                    skipped += 1
                    continue
                if language == "cpp":
                    if "int main(" not in text:
                        failures.append("%s: a cpp block without main() must be marked <!-- fragment -->" % where)
                    else:
                        programs.append((where, text))
                    continue
                command = ["bash", "-euo", "pipefail", "-c", text] if language == "sh" else [sys.executable, "-c", text]
                try:
                    result = subprocess.run(command, cwd=root, env=env, capture_output=True, text=True, timeout=60)
                    ok = result.returncode == 0
                    detail = result.stdout[-2000:] + result.stderr[-2000:]
                except subprocess.TimeoutExpired:
                    ok, detail = False, "took more than a minute (mark it <!-- not run: ... -->)"
                ran += 1
                print("%s %s (%s)" % ("ok  " if ok else "FAIL", where, language))
                if not ok:
                    failures.append("%s: %s" % (where, detail))
        if programs:
            prefix = os.path.join(work, "prefix")
            subprocess.run([cmake, "--install", build, "--prefix", prefix], check=True, capture_output=True)
            project = os.path.join(work, "cpp")
            os.mkdir(project)
            names = []
            with open(os.path.join(project, "CMakeLists.txt"), "w") as out:
                out.write("cmake_minimum_required(VERSION 3.25)\nproject(doc_blocks LANGUAGES CXX)\n"
                          "set(CMAKE_CXX_STANDARD 20)\nfind_package(akvf 0.2 CONFIG REQUIRED)\n")
                for k, (where, text) in enumerate(programs):
                    names.append("block%d" % k)
                    with open(os.path.join(project, "block%d.cpp" % k), "w") as cpp:
                        cpp.write("// %s\n%s" % (where, text))
                    out.write("add_executable(block%d block%d.cpp)\n"
                              "target_link_libraries(block%d PRIVATE akvf::akvf)\n" % (k, k, k))
            configured = subprocess.run([cmake, "-S", project, "-B", project + "/build", "-DCMAKE_BUILD_TYPE=Release",
                                         "-DCMAKE_PREFIX_PATH=" + prefix], capture_output=True, text=True)
            if configured.returncode != 0:
                failures.append("the cpp blocks' project: " + configured.stdout[-3000:] + configured.stderr[-3000:])
            for k, (where, _) in enumerate(programs):
                built = subprocess.run([cmake, "--build", project + "/build", "--target", names[k], "-j", "2"],
                                       capture_output=True, text=True)
                ok = built.returncode == 0
                detail = built.stdout[-3000:] + built.stderr[-3000:]
                if ok:
                    result = subprocess.run([os.path.join(project, "build", names[k])], cwd=root, capture_output=True,
                                            text=True, timeout=60)
                    ok = result.returncode == 0
                    detail = result.stdout[-2000:] + result.stderr[-2000:]
                ran += 1
                print("%s %s (cpp)" % ("ok  " if ok else "FAIL", where))
                if not ok:
                    failures.append("%s: %s" % (where, detail))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("%d blocks ran, %d skipped (fragments, not run, or no ../shared)" % (ran, skipped))
    for failure in failures:
        print("FAIL " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
