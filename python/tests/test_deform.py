"""akvf.deform from Python, against the command line."""

import subprocess

import numpy as np
import pytest

import akvf
from conftest import tet_grid


def twisted(V):
    bottom = np.flatnonzero(V[:, 2] == 0)
    top = np.flatnonzero(V[:, 2] == 1)
    indices = np.concatenate([bottom, top])
    targets = V[indices].copy()
    targets[len(bottom):, 2] += 0.2
    return indices, targets


def write_medit(path, V, T):
    with open(path, "w") as out:
        out.write("MeshVersionFormatted 1\nDimension 3\nVertices\n%d\n" % len(V))
        for p in V:
            out.write("%.17g %.17g %.17g 0\n" % tuple(p))
        out.write("Tetrahedra\n%d\n" % len(T))
        for t in T:
            out.write("%d %d %d %d 0\n" % tuple(t + 1))
        out.write("End\n")


def read_medit_vertices(path):
    lines = open(path).read().split("\n")
    start = lines.index("Vertices")
    n = int(lines[start + 1])
    return np.array([[float(v) for v in line.split()[:3]] for line in lines[start + 2:start + 2 + n]])


def test_deform_pulls_the_top_up():
    V, T = tet_grid()
    indices, targets = twisted(V)
    r = akvf.deform(V, T, (indices, targets), max_iters=30)
    assert r.x.shape == V.shape and r.status in ("converged", "max-iterations")
    assert r.x[:, 2].max() > 1.15
    assert (r.trace["flips"] == 0).all()
    # How far the constrained vertices are from their targets, per row.
    distance = r.trace["constraint_distance"]
    assert len(distance) == len(r.trace["iter"])
    assert distance[0] == pytest.approx(0.2) and distance[-1] < distance[0]


@pytest.mark.parametrize("args,keywords", [([], {}), (["--precond", "newton", "--hard"], {"precond": "newton", "hard": True}),
                                           (["--weight", "1000", "--energy", "arap"], {"weight": 1000, "energy": "arap"})])
def test_bitwise_the_command_line(program, tmp_path, args, keywords):
    V, T = tet_grid()
    indices, targets = twisted(V)
    mesh, constraints, out = tmp_path / "grid.mesh", tmp_path / "c.txt", tmp_path / "out.mesh"
    write_medit(mesh, V, T)
    with open(constraints, "w") as f:
        for i, p in zip(indices, targets):
            f.write("%d %.17g %.17g %.17g\n" % (i, *p))
    subprocess.run([program, "deform", str(mesh), "--constraints", str(constraints), "--out", str(out),
                    "--max-iters", "20", "-q"] + args, check=True)
    V_read, T_read = akvf.read_mesh(mesh)
    r = akvf.deform(V_read, T_read, (indices, targets), max_iters=20, **keywords)
    assert np.array_equal(r.x, read_medit_vertices(out))


def test_constraints_are_checked():
    V, T = tet_grid(2)
    with pytest.raises(akvf.InputError, match="3 vertex indices but 2 targets"):
        akvf.deform(V, T, ([0, 1, 2], np.zeros((2, 3))))
    with pytest.raises(akvf.InputError, match="out of range"):
        akvf.deform(V, T, ([0, 999], np.zeros((2, 3))))
    # A vertex given two targets is refused, as in a constraints file, not averaged.
    with pytest.raises(akvf.InputError, match="constraint 2: vertex 0 is already constrained by constraint 0"):
        akvf.deform(V, T, ([0, 1, 0], np.array([[0, 0, 0], [1, 0, 0], [0, 0, 1.0]])))
    with pytest.raises(akvf.OptionsError, match="weight"):
        akvf.deform(V, T, ([0], np.zeros((1, 3))), weight=-1)
