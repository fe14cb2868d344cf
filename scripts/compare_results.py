#!/usr/bin/python3
"""Compares two runs of experiment manifests case by case (results as the
contract, docs/robustness.md): status, iterations and final energy of each
(mesh, method) in the runner's table.csv. A case keeps its result when its
status is the same and, for converged runs, its final energy agrees to
--tolerance relative (default 1e-9); iteration counts and other energies
are reported as they moved.

Usage:
  /usr/bin/python3 scripts/compare_results.py OLD_DIR NEW_DIR
  /usr/bin/python3 scripts/compare_results.py --rev REV [DIR ...]
The second form compares DIR/table.csv as committed at REV with the working
tree's (default DIR: every docs/results/*). Prints a Markdown table per
folder; exits 1 with --strict if a converged case's result moved or a
status changed.
"""
import argparse
import csv
import glob
import io
import os
import subprocess
import sys


def read_table(text):
    return {(row["mesh"], row["method"]): row for row in csv.DictReader(io.StringIO(text))}


def committed(rev, path):
    try:
        return subprocess.run(["git", "show", f"{rev}:{path}"], check=True, capture_output=True, text=True).stdout
    except subprocess.CalledProcessError:
        return None


def relative(old, new):
    a, b = float(old), float(new)
    if a == b:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b))


def compare(name, old_text, new_text, tolerance):
    """Prints one folder's comparison; returns the number of moved results."""
    old, new = read_table(old_text), read_table(new_text)
    print(f"## {name}\n")
    print("| mesh | method | status | iterations | final energy | relative change | result |")
    print("|---|---|---|---|---|---|---|")
    moved = 0
    for key in sorted(set(old) | set(new)):
        a, b = old.get(key), new.get(key)
        if a is None or b is None:
            print(f"| {key[0]} | {key[1]} | {'only new' if a is None else 'only old'} | | | | moved |")
            moved += 1
            continue
        if not a["final_energy"] or not b["final_energy"]:  # not run (mesh not available)
            continue
        change = relative(a["final_energy"], b["final_energy"])
        same_status = a["status"] == b["status"]
        kept = same_status and (a["status"] != "converged" or change <= tolerance)
        moved += not kept
        iterations = a["iterations"] if a["iterations"] == b["iterations"] else f"{a['iterations']} -> {b['iterations']}"
        status = a["status"] if same_status else f"{a['status']} -> {b['status']}"
        energy = f"{float(b['final_energy']):.10g}"
        print(f"| {key[0]} | {key[1]} | {status} | {iterations} | {energy} | {change:.1e} | {'kept' if kept else 'moved'} |")
    print()
    return moved


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dirs", nargs="*", help="OLD_DIR NEW_DIR, or with --rev the result folders")
    parser.add_argument("--rev", help="compare the folders' table.csv committed at REV with the working tree's")
    parser.add_argument("--tolerance", type=float, default=1e-9, help="relative energy change a converged case keeps")
    parser.add_argument("--strict", action="store_true", help="exit 1 if a result moved")
    args = parser.parse_args()
    moved = 0
    if args.rev:
        folders = args.dirs or sorted(glob.glob("docs/results/*/"))
        for folder in folders:
            path = os.path.join(os.path.normpath(folder), "table.csv")
            old = committed(args.rev, path)
            if old is None:
                print(f"{path}: not in {args.rev}", file=sys.stderr)
                continue
            with open(path) as f:
                moved += compare(os.path.normpath(folder), old, f.read(), args.tolerance)
    else:
        if len(args.dirs) != 2:
            parser.error("give OLD_DIR and NEW_DIR, or --rev REV")
        texts = []
        for folder in args.dirs:
            path = os.path.join(folder, "table.csv")
            if not os.path.isfile(path):
                parser.error(f"{path}: no such file (a folder the experiment runner wrote)")
            with open(path) as f:
                texts.append(f.read())
        moved += compare(f"{args.dirs[0]} -> {args.dirs[1]}", texts[0], texts[1], args.tolerance)
    print(f"{moved} result(s) moved")
    return 1 if args.strict and moved else 0


if __name__ == "__main__":
    sys.exit(main())
