"""Every --summary (param, param with the cut, deform) and every case
summary of the experiment runner validates against the documented schema,
docs/run_summary.schema.json (Debian's python3-jsonschema)."""

import json
import pathlib
import subprocess

import pytest

from conftest import bumpy_disk, tet_grid
from test_deform import twisted, write_medit
from test_parameterize import torus

jsonschema = pytest.importorskip("jsonschema")

SCHEMA = json.loads((pathlib.Path(__file__).resolve().parents[2] / "docs" / "run_summary.schema.json").read_text())


def validate(path):
    summary = json.loads(pathlib.Path(path).read_text())
    jsonschema.Draft202012Validator(SCHEMA).validate(summary)
    return summary


def write_obj(path, V, F):
    with open(path, "w") as out:
        for v in V:
            out.write("v %.17g %.17g %.17g\n" % tuple(v))
        for f in F:
            out.write("f %d %d %d\n" % tuple(f + 1))


def test_the_schema_is_a_valid_schema():
    jsonschema.Draft202012Validator.check_schema(SCHEMA)


def test_param_summaries_validate(program, tmp_path):
    V, F = bumpy_disk()
    write_obj(tmp_path / "disk.obj", V, F)
    subprocess.run([program, "param", str(tmp_path / "disk.obj"), "--summary", str(tmp_path / "a.json"), "-q"],
                   check=True, capture_output=True)
    summary = validate(tmp_path / "a.json")
    assert summary["problem"] == "param" and "cut" not in summary
    # The default method factors at least once and its report names AKVF's phase.
    linear_algebra = summary["linear_algebra"]
    assert linear_algebra["factorizations"] >= 1 and linear_algebra["symbolic_analyses"] == 1
    assert linear_algebra["report"].startswith("akvf: ")
    V, F = torus()
    write_obj(tmp_path / "torus.obj", V, F)
    subprocess.run([program, "param", str(tmp_path / "torus.obj"), "--cut", "auto", "--summary",
                    str(tmp_path / "b.json"), "-q"], check=True, capture_output=True)
    summary = validate(tmp_path / "b.json")
    # One chart, split by straight cuts for the packing: each piece keeps its component's genus.
    cut = summary["cut"]
    assert cut["packing_splits"] >= 1 and cut["charts"] >= 1 + cut["packing_splits"]
    assert cut["genus"] == [1] * cut["charts"] and summary["uv_coverage"] > 0.5
    # A run that cannot start (the energy overflows at the Tutte map, no warm
    # start): numerical-failure, its infinite energy or gradient null, still valid.
    run = subprocess.run([program, "param", str(tmp_path / "disk.obj"), "--energy", "exp-symmetric-dirichlet",
                          "--exponent", "50", "--warm-start-iters", "0", "--init", "tutte", "--summary",
                          str(tmp_path / "c.json"), "-q"],
                         capture_output=True)
    assert run.returncode == 3
    summary = validate(tmp_path / "c.json")
    assert summary["status"] == "numerical-failure" and None in (summary["final_energy"], summary["grad_norm"])


def test_deform_summary_validates(program, tmp_path):
    V, T = tet_grid()
    indices, targets = twisted(V)
    write_medit(tmp_path / "grid.mesh", V, T)
    with open(tmp_path / "c.txt", "w") as f:
        for i, p in zip(indices, targets):
            f.write("%d %.17g %.17g %.17g\n" % (i, *p))
    subprocess.run([program, "deform", str(tmp_path / "grid.mesh"), "--constraints", str(tmp_path / "c.txt"),
                    "--max-iters", "5", "--summary", str(tmp_path / "d.json"), "-q"], check=True, capture_output=True)
    assert validate(tmp_path / "d.json")["problem"] == "deform"


def test_experiment_case_summaries_validate(program, tmp_path):
    V, F = bumpy_disk()
    write_obj(tmp_path / "disk.obj", V, F)
    (tmp_path / "m.json").write_text(json.dumps({
        "name": "schema", "meshes": [{"label": "disk", "file": "disk.obj"}, {"label": "gone", "missing": "absent"}],
        "methods": [{"label": "akvf", "max_iters": 5}]}))
    subprocess.run([program, "experiment", str(tmp_path / "m.json"), "--data-dir", str(tmp_path), "--out-dir",
                    str(tmp_path / "results")], check=True, capture_output=True)
    assert validate(tmp_path / "results" / "cases" / "disk--akvf" / "summary.json")["id"] == "disk--akvf"
    assert validate(tmp_path / "results" / "cases" / "gone--akvf" / "summary.json")["status"] == "missing"


def test_the_schema_rejects_what_it_does_not_describe(program, tmp_path):
    V, F = bumpy_disk()
    write_obj(tmp_path / "disk.obj", V, F)
    subprocess.run([program, "param", str(tmp_path / "disk.obj"), "--summary", str(tmp_path / "a.json"), "-q"],
                   check=True, capture_output=True)
    summary = json.loads((tmp_path / "a.json").read_text())
    for broken in ({k: v for k, v in summary.items() if k != "iterations"}, dict(summary, max_flips=3),
                   dict(summary, surprise=1), dict(summary, status="fine")):
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.Draft202012Validator(SCHEMA).validate(broken)
