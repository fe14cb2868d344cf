"""The layers of docs/design.md, read from the #include lines: every include
of a project header goes from a part to itself or to a part below it, and
the public headers (akvf/*.h, the installed ones) include only public headers.
Usage: /usr/bin/python3 tests/check_layers.py [REPOSITORY_ROOT]"""
import os
import re
import sys

# The public headers every part may include: the vocabulary (types,
# interfaces, errors, file formats) that the facade's signatures use.
# akvf/*.h that are not listed here are the facade, the top of the library.
VOCABULARY = {"autodiff_density.h", "backtracking_line_search.h", "choices.h", "constrained_objective.h", "distortion_density.h",
              "error.h", "line_search.h", "mesh.h", "mesh_io.h", "mesh_objective.h", "motion_bases.h",
              "obj_passthrough.h", "objective.h", "optimizer.h", "position_constraints.h", "preconditioner.h",
              "registry.h", "rest_geometry.h", "tet_mesh_io.h", "version.h"}

# What each part may include besides itself and the vocabulary; a part not
# listed includes nothing else of the project.
BELOW = {
    "akvf/vocabulary": [],
    "akvf/public": [],
    "framework/process": [],
    "framework/mesh": ["framework/process"],
    "framework/optimization": ["framework/mesh", "framework/process"],
    "energies": ["framework/optimization", "framework/mesh", "framework/process"],
    "solvers": ["framework/optimization", "framework/mesh", "framework/process"],
    "preconditioners": ["solvers", "energies", "framework/optimization", "framework/mesh", "framework/process"],
    "io": ["framework/mesh", "framework/process"],
}
LIBRARY = ["preconditioners", "solvers", "energies", "io", "framework/optimization", "framework/mesh",
           "framework/process"]
BELOW["akvf"] = ["akvf/public"] + LIBRARY
FACADE = ["akvf", "akvf/public"]
BELOW["pictures"] = FACADE + LIBRARY
BELOW["experiments/report"] = FACADE + LIBRARY
BELOW["experiments/runner"] = ["experiments/report", "pictures"] + FACADE + LIBRARY
BELOW["experiments/bench"] = ["experiments/runner", "experiments/report", "pictures"] + FACADE + LIBRARY
BELOW["cli"] = ["experiments/runner", "experiments/report", "pictures"] + FACADE + LIBRARY
BELOW["python"] = ["pictures"] + FACADE + LIBRARY


def part_of(path):
    segments = path.split("/")
    if len(segments) == 2 and segments[0] == "akvf" and segments[1].endswith(".h"):
        return "akvf/vocabulary" if segments[1] in VOCABULARY else "akvf/public"
    return "/".join(segments[:2]) if segments[0] in ("framework", "experiments") else segments[0]


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    wrong = []
    for top in [p for p in BELOW if not p.startswith("akvf/")]:
        for folder, _, files in os.walk(os.path.join(root, top)):
            for name in sorted(files):
                if not name.endswith((".h", ".cpp")):
                    continue
                path = os.path.relpath(os.path.join(folder, name), root)
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = re.match(r'#include "([^"]+/[^"]+)"', line)
                        if not m or m.group(1).endswith("git_version.h"):
                            continue
                        source, target = part_of(path), part_of(m.group(1))
                        if target != source and target != "akvf/vocabulary" and target not in BELOW[source]:
                            wrong.append(f"{path}:{number}: {source} includes {m.group(1)} ({target} is not below it)")
    for line in wrong:
        print(line)
    print(f"{len(wrong)} include(s) against the layers")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
