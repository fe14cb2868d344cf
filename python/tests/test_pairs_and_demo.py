"""The demo bar built in NumPy, every energy with every preconditioner, and
the Python example script."""

import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import akvf
from conftest import bumpy_disk, signed_areas, tet_grid


def bent_bar(nx=61, ny=11, length=6.0, width=1.0, bend_angle=3.0):
    """The demo's bent bar of Figure 2 (akvf/demo_mesh.cpp): a developable strip rolled onto a cylinder."""
    radius = length / bend_angle
    s = np.tile(length * np.arange(nx) / (nx - 1), ny)
    t = np.repeat(width * np.arange(ny) / (ny - 1), nx)
    V = np.stack([radius * np.sin(s / radius), radius * (1 - np.cos(s / radius)), t], axis=1)
    F = []
    for j in range(ny - 1):
        for i in range(nx - 1):
            a = j * nx + i
            b, c, d = a + 1, a + nx, a + nx + 1
            F += [[a, b, d], [a, d, c]] if (i + j) % 2 == 0 else [[a, b, c], [b, d, c]]
    return V, np.array(F)


def test_the_demo_bar_reaches_the_lower_bound_as_the_demo_does(program, tmp_path):
    V, F = bent_bar()
    r = akvf.parameterize(V, F)
    assert r.status == "converged" and (signed_areas(r.uv, F) > 0).all()
    assert r.energy == pytest.approx(4, abs=1e-6)
    subprocess.run([program, "demo", "--out-dir", str(tmp_path), "-q"], check=True, capture_output=True)
    trace = (tmp_path / "demo_trace.csv").read_text().splitlines()
    assert r.iterations == int(trace[-1].split(",")[0])
    # NumPy's sin and cos differ from the C library's in the last bit at most
    # vertices; the demo's own vertices (its OBJ keeps 17 digits) give the
    # demo's run bit for bit.
    V_demo, F_demo = akvf.read_mesh(str(tmp_path / "demo_uv.obj"))
    assert (F_demo == F).all() and np.abs(V_demo - V).max() <= 1e-15
    demo = akvf.parameterize(V_demo, F_demo)
    assert demo.iterations == r.iterations
    assert demo.energy == float(trace[-1].split(",")[2])


@pytest.mark.parametrize("energy", [name for name, _ in akvf.energies()])
@pytest.mark.parametrize("method", [("descent", name) for name, _ in akvf.preconditioners()] + [("lbfgs", "akvf")])
def test_every_energy_with_every_preconditioner_2d(energy, method):
    V, F = bumpy_disk(8, 7)
    solver, precond = method
    r = akvf.parameterize(V, F, energy=energy, solver=solver, precond=precond, max_iters=5, exponent=0.5)
    assert r.status in ("converged", "max-iterations", "stalled"), r.message
    assert (signed_areas(r.uv, F) > 0).all() and (r.trace["flips"] == 0).all()
    warm = r.trace["status"] == "warm-start"
    own = r.trace["energy"][~warm]
    assert own[-1] <= own[0]


@pytest.mark.parametrize("energy", [name for name, _ in akvf.energies(3)])
@pytest.mark.parametrize("precond", [name for name, _ in akvf.preconditioners(3)])
def test_every_energy_with_every_preconditioner_3d(energy, precond):
    V, T = tet_grid(2)
    top = np.flatnonzero(V[:, 2] == 1)
    bottom = np.flatnonzero(V[:, 2] == 0)
    indices = np.concatenate([bottom, top])
    targets = V[indices] + np.outer(V[indices, 2], [0.1, 0, 0.1])
    r = akvf.deform(V, T, (indices, targets), energy=energy, precond=precond, max_iters=5, exponent=0.2)
    assert r.status in ("converged", "max-iterations", "stalled"), r.message
    assert (r.trace["flips"] == 0).all() and r.trace["energy"][-1] <= r.trace["energy"][0]


def test_the_example_script(tmp_path):
    script = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "parameterize.py"
    V, F = bumpy_disk()
    mesh, out = tmp_path / "disk.obj", tmp_path / "uv.obj"
    akvf.write_obj(mesh, V, F, np.zeros((len(V), 2)))
    run = subprocess.run([sys.executable, str(script), str(mesh), "--out", str(out)], capture_output=True, text=True,
                         env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    assert "converged after" in run.stdout and "wrote" in run.stdout
    assert sum(line.startswith("vt ") for line in out.read_text().splitlines()) == len(V)
