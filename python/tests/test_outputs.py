"""The outputs of the command line from Python: write_mesh, write_view,
write_layout, read_mesh of a MEDIT tet mesh, and the Deformer."""

import json
import struct

import numpy as np
import pytest

import akvf
from conftest import bumpy_disk, tet_grid
from test_deform import twisted, write_medit


@pytest.fixture(scope="module")
def disk_map():
    V, F = bumpy_disk()
    r = akvf.parameterize(V, F)
    return V, F, r


def test_write_mesh_chooses_the_format_by_extension(tmp_path, disk_map):
    V, F, r = disk_map
    assert akvf.write_mesh(tmp_path / "a.obj", V, F, r.uv, texture="none") == 0
    V_obj, F_obj = akvf.read_mesh(tmp_path / "a.obj")
    assert np.array_equal(V_obj, V) and np.array_equal(F_obj, F)
    vt = np.array([[float(t) for t in line.split()[1:3]] for line in open(tmp_path / "a.obj") if line.startswith("vt ")])
    assert np.allclose(vt, r.uv, rtol=0, atol=1e-15)  # as given: the optimized map
    # The checker texture: the MTL and PNG beside, vt in the unit square.
    scale = akvf.write_mesh(tmp_path / "b.obj", V, F, r.uv)
    assert scale > 0 and (tmp_path / "b.mtl").exists() and (tmp_path / "b_checker.png").exists()
    vt = np.array([[float(t) for t in line.split()[1:3]] for line in open(tmp_path / "b.obj") if line.startswith("vt ")])
    assert np.allclose(vt, (r.uv - r.uv.min(axis=0)) * scale, atol=1e-12)
    assert akvf.write_mesh(tmp_path / "c.PLY", V, F, r.uv) == 0
    V_ply, F_ply = akvf.read_mesh(tmp_path / "c.PLY")
    assert np.array_equal(V_ply, V) and np.array_equal(F_ply, F)
    assert akvf.write_mesh(tmp_path / "d.glb", V, F, r.uv) > 0
    magic, version, length = struct.unpack("<4sII", open(tmp_path / "d.glb", "rb").read(12))
    assert magic == b"glTF" and version == 2 and length == (tmp_path / "d.glb").stat().st_size
    with pytest.raises(akvf.OptionsError, match="the extension must be .obj, .ply or .glb"):
        akvf.write_mesh(tmp_path / "e.stl", V, F, r.uv)
    with pytest.raises(akvf.OptionsError, match="texture must be checker or none"):
        akvf.write_mesh(tmp_path / "e.obj", V, F, r.uv, texture="wood")
    with pytest.raises(akvf.InputError, match="uv must have one row per vertex"):
        akvf.write_mesh(tmp_path / "e.obj", V, F, r.uv[:-1])
    assert not (tmp_path / "e.obj").exists()


def test_write_mesh_with_per_corner_uv_of_a_cut(tmp_path):
    from test_parameterize import torus
    V, F = torus()
    r = akvf.parameterize(V, F, cut="auto")
    assert len(r.uv) > len(V)
    akvf.write_mesh(tmp_path / "t.ply", V, F, r.uv, r.uv_faces)
    akvf.write_mesh(tmp_path / "t.obj", V, F, r.uv, r.uv_faces, texture="none")
    lines = open(tmp_path / "t.obj").read().split("\n")
    assert sum(line.startswith("vt ") for line in lines) == len(r.uv)


@pytest.mark.skipif(not akvf.view_available(), reason="this build has no three.js")
def test_write_view_and_layouts(tmp_path, disk_map):
    V, F, r = disk_map
    shown = akvf.write_view(tmp_path / "v.html", V, F, r.uv, summary={"status": r.status, "energy": r.energy},
                            title="bumpy disk")
    assert shown == len(F)
    page = open(tmp_path / "v.html").read()
    assert page.startswith("<!doctype html>") and "bumpy disk" in page
    with pytest.raises(akvf.InputError, match="JSON object"):
        akvf.write_view(tmp_path / "w.html", V, F, r.uv, summary="[1, 2]")
    akvf.write_layout(tmp_path / "l.png", V, F, r.uv, size=256)
    assert open(tmp_path / "l.png", "rb").read(8) == b"\x89PNG\r\n\x1a\n"
    akvf.write_layout(tmp_path / "l.svg", V, F, r.uv, title="layout")
    assert "<svg" in open(tmp_path / "l.svg").read()
    with pytest.raises(akvf.OptionsError, match=".png or .svg"):
        akvf.write_layout(tmp_path / "l.jpg", V, F, r.uv)


def test_read_mesh_reads_a_medit_tet_mesh(tmp_path):
    V, T = tet_grid(2)
    write_medit(tmp_path / "g.mesh", V, T)
    V_read, T_read = akvf.read_mesh(tmp_path / "g.mesh")
    assert np.array_equal(V_read, V) and np.array_equal(T_read, T)


def test_deformer_solves_twice_with_one_symbolic_analysis():
    V, T = tet_grid()
    indices, targets = twisted(V)
    solver = akvf.Deformer(V, T)
    first = solver.solve((indices, targets), max_iters=10, precond="newton")
    assert first.statistics["symbolic_analyses"] > 0
    targets2 = targets.copy()
    targets2[:, 0] += 0.05
    second = solver.solve((indices, targets2), max_iters=10, precond="newton")
    assert second.statistics["symbolic_analyses"] == 0
    # The same as a fresh deform of those constraints.
    fresh = akvf.deform(V, T, (indices, targets2), max_iters=10, precond="newton")
    assert np.array_equal(second.x, fresh.x)
    with pytest.raises(akvf.InputError, match="already constrained"):
        solver.solve(([0, 0], np.zeros((2, 3))))


def test_the_schema_says_which_options_recompute_the_initial_map():
    fields = {f["key"]: f for f in akvf.options("parameterize")}
    assert fields["init"]["recomputes_start"] and fields["energy"]["recomputes_start"]
    assert not fields["max_iters"]["recomputes_start"] and not fields["precond"]["recomputes_start"]
    assert fields["cut"]["values"] == "none|auto|seams" and fields["cut"]["scope"] == "param"
    assert fields["max_iters"]["scope"] == "both"
    with pytest.raises(akvf.OptionsError, match=r"unknown cut 'yes' \(valid: none, auto, seams\)"):
        akvf.parameterize(*bumpy_disk(), cut="yes")
    V, F = bumpy_disk()
    solver = akvf.Parameterizer(V, F)
    first = solver.initial_uv
    solver.set_options(max_iters=5, precond="newton")  # keeps the initial map
    assert np.array_equal(solver.initial_uv, first)
    solver.set_options(init="cotan")  # recomputes it
    assert not np.array_equal(solver.initial_uv, first)
