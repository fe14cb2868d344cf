"""The layers of docs/design.md, read from the #include lines: every include
of a project header goes from a part to itself or to a part below it.
Usage: /usr/bin/python3 tests/check_layers.py [REPOSITORY_ROOT]"""
import os
import re
import sys

# What each part may include besides itself; a part not listed includes nothing of the project.
BELOW = {
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
BELOW["akvf"] = LIBRARY
BELOW["pictures"] = ["akvf"] + LIBRARY
BELOW["experiments/report"] = ["akvf"] + LIBRARY
BELOW["experiments/runner"] = ["experiments/report", "pictures", "akvf"] + LIBRARY
BELOW["experiments/bench"] = ["experiments/runner", "experiments/report", "pictures", "akvf"] + LIBRARY
BELOW["cli"] = ["experiments/runner", "experiments/report", "pictures", "akvf"] + LIBRARY
BELOW["python"] = ["pictures", "akvf"] + LIBRARY


def part_of(path):
    segments = path.split("/")
    return "/".join(segments[:2]) if segments[0] in ("framework", "experiments") else segments[0]


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    wrong = []
    for top in BELOW:
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
                        if target != source and target not in BELOW[source]:
                            wrong.append(f"{path}:{number}: {source} includes {m.group(1)} ({target} is not below it)")
    for line in wrong:
        print(line)
    print(f"{len(wrong)} include(s) against the layers")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
