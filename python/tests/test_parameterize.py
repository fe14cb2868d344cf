"""akvf.parameterize from Python: shapes, statuses, the trace, options as
keywords, and the same bits as the command line."""

import re
import subprocess

import numpy as np
import pytest

import akvf
from conftest import bumpy_disk, signed_areas


def symmetric_dirichlet(V, F, uv):
    """sum_f A_f (|J_f|^2 + |J_f^-1|^2) / sum_f A_f for the map uv of V, F."""
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    e1, e2 = b - a, c - a
    l1 = np.linalg.norm(e1, axis=1)
    x = e1 / l1[:, None]
    y = np.cross(np.cross(e1, e2), e1)
    y /= np.linalg.norm(y, axis=1)[:, None]
    Dm = np.stack([np.stack([l1, np.zeros_like(l1)], 1), np.stack([(e2 * x).sum(1), (e2 * y).sum(1)], 1)], 2)
    Ds = np.stack([uv[F[:, 1]] - uv[F[:, 0]], uv[F[:, 2]] - uv[F[:, 0]]], 2)
    J = Ds @ np.linalg.inv(Dm)
    area = 0.5 * np.abs(np.linalg.det(Dm))
    density = (J ** 2).sum((1, 2)) + (np.linalg.inv(J) ** 2).sum((1, 2))
    return (area * density).sum() / area.sum()


def test_version_matches_the_program(program):
    out = subprocess.run([program, "--version"], capture_output=True, text=True, check=True).stdout
    assert out.split()[-1] == akvf.__version__


def test_default_run_converges_without_inverted_triangles(disk):
    V, F = disk
    r = akvf.parameterize(V, F)
    assert r.status == "converged"
    assert r.uv.shape == (len(V), 2) and r.uv.dtype == np.float64
    assert (signed_areas(r.uv, F) > 0).all()
    # At the input's scale, the optimized map itself: the input mesh with it
    # has the reported energy.
    assert symmetric_dirichlet(V, F, r.uv) == pytest.approx(r.distortion_energy, rel=1e-9)
    assert r.distortion_energy == r.energy  # no barrier term on this disk
    assert r.boundary_crossings == 0 and r.overlap_fraction == 0
    assert r.grad_norm < 1e-3 and r.iterations == r.trace["iter"][-1]
    assert r.energy == r.trace["energy"][-1] >= 4
    assert r.statistics["factorizations"] >= 1 and r.statistics["symbolic_analyses"] == 1
    assert (r.trace["flips"] == 0).all()


def test_trace_has_the_columns_of_the_trace_csv(disk, program, tmp_path):
    V, F = disk
    mesh = tmp_path / "disk.obj"
    akvf.write_obj(mesh, V, F, np.zeros((len(V), 2)))
    trace = tmp_path / "trace.csv"
    subprocess.run([program, "param", str(mesh), "--trace", str(trace), "-q"], check=True)
    header = trace.read_text().splitlines()[0].split(",")
    r = akvf.parameterize(V, F)
    assert list(r.trace) == header
    assert r.trace["iter"].dtype == np.int64 and r.trace["energy"].dtype == np.float64
    assert r.trace["status"][-1] == "converged" and r.trace["status"][0] == ""


def read_vt(path):
    return np.array([[float(t) for t in line.split()[1:3]] for line in open(path) if line.startswith("vt ")])


@pytest.mark.parametrize("args,keywords", [
    ([], {}),
    (["--precond", "newton", "--energy", "arap"], {"precond": "newton", "energy": "arap"}),
    (["--precond", "slim", "--max-iters", "7", "--flaps", "off", "--init", "cotan"],
     {"precond": "slim", "max_iters": 7, "flaps": False, "init": "cotan"}),
    (["--energy", "exp-symmetric-dirichlet", "--exponent", "0.25", "--grad-tol", "1e-4"],
     {"energy": "exp-symmetric-dirichlet", "exponent": 0.25, "grad_tol": 1e-4}),
])
def test_bitwise_the_command_line(disk, program, tmp_path, args, keywords):
    V, F = disk
    mesh, out = tmp_path / "disk.obj", tmp_path / "uv.obj"
    akvf.write_obj(mesh, V, F, np.zeros((len(V), 2)))
    V_read, F_read = akvf.read_mesh(mesh)
    subprocess.run([program, "param", str(mesh), "--out", str(out), "--texture", "none", "-q"] + args, check=True)
    r = akvf.parameterize(V_read, F_read, **keywords)
    assert np.array_equal(r.uv, read_vt(out))


def test_shared_mesh_bitwise_the_command_line(meshes, program, tmp_path):
    out = tmp_path / "uv.obj"
    subprocess.run([program, "param", str(meshes / "tri" / "camelhead.off"), "--out", str(out), "--texture", "none",
                    "-q"], check=True)
    V, F = akvf.read_mesh(meshes / "tri" / "camelhead.off")
    assert np.array_equal(akvf.parameterize(V, F).uv, read_vt(out))


def test_the_written_map_has_the_reported_energy(meshes, program, tmp_path):
    """--texture none writes the optimized map itself: the file's mesh with its
    vt has the summary's distortion energy; the textured OBJ's vt are it
    scaled into the unit square."""
    import json
    for name in ["camelhead.off", "cow_b.obj"]:
        plain, textured, summary = tmp_path / "plain.obj", tmp_path / "textured.obj", tmp_path / "run.json"
        subprocess.run([program, "param", str(meshes / "tri" / name), "--out", str(plain), "--texture", "none",
                        "--summary", str(summary), "-q"], check=True)
        subprocess.run([program, "param", str(meshes / "tri" / name), "--out", str(textured), "-q"], check=True)
        record = json.loads(summary.read_text())
        V, F = akvf.read_mesh(plain)
        uv = read_vt(plain)
        assert symmetric_dirichlet(V, F, uv) == pytest.approx(record["distortion_energy"], rel=1e-9)
        assert record["final_energy"] >= record["distortion_energy"]
        assert record["overlap"] == {"boundary_crossings": 0, "area_fraction": 0}
        scaled = (uv - uv.min(0)) * (1 / np.ptp(uv, 0).max())
        assert np.allclose(read_vt(textured), scaled, rtol=0, atol=1e-6)  # vt are written with 6 decimals or more


def test_arrays_are_converted_not_refused(disk):
    V, F = disk
    reference = akvf.parameterize(V, F, max_iters=5).uv
    for V2, F2 in [(np.asfortranarray(V), F.astype(np.int32)), (V[:, ::-1][:, ::-1], F.astype(np.uint16)),
                   (V.tolist(), F.tolist())]:
        assert np.array_equal(akvf.parameterize(V2, F2, max_iters=5).uv, reference)


def test_start_map_and_callback(disk):
    V, F = disk
    first = akvf.parameterize(V, F)
    again = akvf.parameterize(V, F, uv0=first.uv)
    assert again.status == "converged" and again.iterations <= 3
    rows, shapes = [], []

    def record(row, uv):
        rows.append(row)
        shapes.append(uv.shape)
        return row["iter"] < 3  # False at iteration 3 stops the run

    stopped = akvf.parameterize(V, F, callback=record, init="tutte")  # more than 3 iterations from the minimum
    assert stopped.status == "user-stopped" and stopped.iterations == 3
    assert [row["iter"] for row in rows] == [0, 1, 2, 3]
    assert shapes == [(len(V), 2)] * 4
    assert set(rows[0]) == set(first.trace) - {"status"} | {"warm_start"}


def test_callback_exception_propagates(disk):
    V, F = disk

    def fail(row, uv):
        if row["iter"] == 2:
            raise ZeroDivisionError("from the callback")

    with pytest.raises(ZeroDivisionError, match="from the callback"):
        akvf.parameterize(V, F, callback=fail)


def test_every_option_of_the_schema_is_a_keyword(disk):
    V, F = disk
    as_python = {"text": str, "number": float, "integer": int, "switch": lambda text: text == "true"}
    reference = akvf.parameterize(V, F, max_iters=2).uv
    for option in akvf.options("parameterize"):
        # Each key accepts its default, as a Python value or as None, with the default's result.
        for value in (as_python[option["kind"]](option["default"]), None):
            keywords = {"max_iters": 2, option["key"]: value} if option["key"] != "max_iters" else {"max_iters": 2}
            assert np.array_equal(akvf.parameterize(V, F, **keywords).uv, reference), option["key"]
    keys = {o["key"] for o in akvf.options("parameterize")}
    assert {"energy", "precond", "solver", "exponent", "line_search", "acceleration", "grad_tol", "max_iters",
            "time_limit", "threads", "akvf_reuse", "ls_rho", "init", "flaps", "warm_start_iters"} <= keys
    assert {"weight", "hard", "cg_tol", "akvf_as_written"} <= {o["key"] for o in akvf.options("deform")}
    assert "grad_tol = auto" in akvf.parameterize.__doc__


def test_registries():
    names = [name for name, _ in akvf.energies()]
    assert names[0] == "symmetric-dirichlet" and "amips" in names
    assert "akvf" in [name for name, _ in akvf.preconditioners()]
    assert "akvf" in [name for name, _ in akvf.preconditioners(3)]
    assert "backtracking" in [name for name, _ in akvf.line_searches()]
    assert [name for name, _ in akvf.solvers()] == ["descent", "lbfgs"]


def test_threads_are_honoured(disk):
    V, F = disk
    one = akvf.parameterize(V, F, threads=1)
    two = akvf.parameterize(V, F, threads=2)
    assert np.array_equal(one.uv, two.uv)  # the assembly is deterministic for any thread count


def test_runs_side_by_side_with_other_thread_counts_give_the_same_bits_as_alone(meshes):
    # The native libraries' settings are process-wide: a run that ends must
    # not restore them under a neighbour still running.
    import threading
    V, F = akvf.read_mesh(meshes / "tri" / "camel_b.obj")
    counts = (1, 2, 3)
    alone = {t: akvf.parameterize(V, F, threads=t, max_iters=30, grad_tol=0).uv for t in counts}
    for trial in range(3):
        together = {}
        def run(t):
            together[t] = akvf.parameterize(V, F, threads=t, max_iters=30, grad_tol=0).uv
        workers = [threading.Thread(target=run, args=(t,)) for t in counts]
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        for t in counts:
            assert np.array_equal(together[t], alone[t]), (trial, t)
        assert np.array_equal(alone[t], alone[1])


def test_a_mesh_file_round_trip(disk, tmp_path):
    V, F = disk
    r = akvf.parameterize(V, F)
    path = tmp_path / "out.obj"
    akvf.write_obj(path, V, F, r.uv)
    text = path.read_text()
    assert len(re.findall(r"^vt ", text, re.M)) == len(V)
    V2, F2 = akvf.read_mesh(path)
    assert np.array_equal(V2, V) and np.array_equal(F2, F)


def test_a_parameterizer_solves_again_with_the_same_bits(disk):
    V, F = disk
    solver = akvf.Parameterizer(V, F, precond="newton")
    first, second = solver.solve(), solver.solve()
    assert np.array_equal(first.uv, second.uv)
    assert np.array_equal(first.uv, akvf.parameterize(V, F, precond="newton").uv)
    assert first.statistics["symbolic_analyses"] == 1 and second.statistics["symbolic_analyses"] == 0
    assert solver.initial_uv.shape == (len(V), 2)
    solver.set_options(energy="arap")
    assert solver.options == {"precond": "newton", "energy": "arap"}
    assert solver.solve(callback=lambda row, uv: row["iter"] < 2).status == "user-stopped"
    assert solver.solve(uv0=first.uv).status == "converged"
    assert np.array_equal(solver.solve().uv, akvf.parameterize(V, F, precond="newton", energy="arap").uv)
    # A solve that fails (an inverted start) leaves the solver as it was, callbacks included.
    flipped = first.uv.copy()
    flipped[:, 0] *= -1
    with pytest.raises(akvf.ValidationError, match="inverts a triangle"):
        solver.solve(uv0=flipped, callback=lambda row, uv: False)
    assert solver.solve().status == "converged"
    with pytest.raises(akvf.OptionsError, match="unknown preconditioner"):
        solver.set_options(precond="nope")
    assert solver.options["precond"] == "newton"


def torus(n=12, m=8):
    """A closed torus (genus 1): refused without the cut."""
    u, v = np.meshgrid(2 * np.pi * np.arange(n) / n, 2 * np.pi * np.arange(m) / m, indexing="ij")
    V = np.stack([((2 + np.cos(v)) * np.cos(u)).ravel(), ((2 + np.cos(v)) * np.sin(u)).ravel(),
                  np.sin(v).ravel()], axis=1)
    F = []
    for i in range(n):
        for j in range(m):
            a, b = i * m + j, ((i + 1) % n) * m + j
            c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            F += [[a, b, c], [a, c, d]]
    return V, np.array(F)


def test_cut_auto_gives_per_corner_uvs_of_a_closed_mesh(tmp_path):
    V, F = torus()
    with pytest.raises(akvf.ValidationError, match="cut auto"):
        akvf.parameterize(V, F)
    r = akvf.parameterize(V, F, cut="auto")
    assert r.status == "converged"
    assert r.uv_faces.shape == F.shape
    assert r.uv.shape[0] > V.shape[0]  # seam vertices once per side
    corners = r.uv[r.uv_faces]  # (m, 3, 2)
    e1, e2 = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    assert np.all(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] > 0)
    assert np.all(r.trace["flips"] == 0)
    akvf.write_obj(tmp_path / "torus.obj", V, F, r.uv, r.uv_faces)
    lines = (tmp_path / "torus.obj").read_text().splitlines()
    assert sum(line.startswith("v ") for line in lines) == V.shape[0]
    assert sum(line.startswith("vt ") for line in lines) == r.uv.shape[0]
    assert sum(line.startswith("f ") for line in lines) == F.shape[0]


def test_cut_seams_bounds_the_distortion_of_every_chart():
    V, F = torus()
    r = akvf.parameterize(V, F, cut="seams", max_distortion=4.1)
    assert r.status == "converged"
    assert r.distortion_bounded and r.seam_stop_reason == ""
    assert max(r.chart_distortion) <= 4.1
    assert r.seam_length > 0 and r.seams_added >= 0
    corners = r.uv[r.uv_faces]
    e1, e2 = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    assert np.all(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] > 0)
    assert not hasattr(akvf.parameterize(V, F, cut="auto"), "seams_added")
    # pieces of the packing's straight cuts too, and of the fallbacks where seams do not do
    assert len(r.chart_distortion) >= 1 + r.packing_splits + r.overlap_pieces + r.parted_charts
    assert isinstance(r.overlap_pieces, int) and isinstance(r.parted_charts, int)
    maps = []
    akvf.parameterize(V, F, cut="seams", max_distortion=4.1, callback=lambda row, uv: maps.append(uv))
    assert maps[0].shape[1] == 2 and maps[-1] is None


def test_uv_faces_is_F_without_the_cut(disk):
    V, F = disk
    r = akvf.parameterize(V, F)
    assert np.array_equal(r.uv_faces, F)


def test_newton_reuse_takes_auto_or_a_number(disk):
    V, F = disk
    plain = akvf.parameterize(V, F, precond="newton")
    assert plain.statistics["reused_solves"] == 0  # auto: newton factors every iteration
    reused = akvf.parameterize(V, F, precond="newton", newton_reuse=0.5)
    assert reused.status == "converged"
    assert np.array_equal(akvf.parameterize(V, F, precond="newton", newton_reuse="0.5").uv, reused.uv)
    with pytest.raises(akvf.OptionsError, match=r"newton_reuse must be auto or in \[0, 1\), found 2"):
        akvf.parameterize(V, F, newton_reuse=2.0)


def test_local_sweep_takes_auto_or_a_number(disk):
    V, F = disk
    default = akvf.parameterize(V, F)
    assert np.array_equal(akvf.parameterize(V, F, local_sweep="auto").uv, default.uv)
    assert akvf.parameterize(V, F, local_sweep=0).status == "converged"
    with pytest.raises(akvf.OptionsError, match=r"local_sweep must be auto or >= 0, found -1"):
        akvf.parameterize(V, F, local_sweep=-1)


def test_linear_solver_amg_reaches_the_cholesky_energy(disk):
    V, F = disk
    cholmod = akvf.parameterize(V, F, linear_solver="cholmod", grad_tol=1e-6)
    assert cholmod.statistics["multigrid_setups"] == 0
    with pytest.raises(akvf.OptionsError, match="unknown linear solver 'lu'"):
        akvf.parameterize(V, F, linear_solver="lu")
    try:
        amg = akvf.parameterize(V, F, linear_solver="amg", grad_tol=1e-6)
    except akvf.OptionsError as error:  # a build without hypre says what to install
        assert "install libhypre-dev" in str(error)
        return
    assert amg.status == "converged"
    assert amg.statistics["multigrid_setups"] >= 1
    assert amg.statistics["factorizations"] == 0
    assert amg.energy == pytest.approx(cholmod.energy, rel=1e-8)
    assert (signed_areas(amg.uv, F) > 0).all()


def test_one_parameterizer_does_one_thing_at_a_time(disk):
    """A second solve, or set_options, while a solve runs (another thread, or
    the solve's own callback) raises OptionsError and changes nothing."""
    import threading
    V, F = disk
    solver = akvf.Parameterizer(V, F)
    reference = solver.solve()
    started, release = threading.Event(), threading.Event()

    def slow(row, uv):
        if row["iter"] == 1:
            started.set()
            release.wait(30)

    results = {}
    worker = threading.Thread(target=lambda: results.setdefault("a", solver.solve(callback=slow)))
    worker.start()
    assert started.wait(30)
    with pytest.raises(akvf.OptionsError, match="this Parameterizer is solving"):
        solver.solve()
    with pytest.raises(akvf.OptionsError, match="this Parameterizer is solving"):
        solver.set_options(energy="arap")
    release.set()
    worker.join()
    assert np.array_equal(results["a"].uv, reference.uv)

    def changes_options(row, uv):
        solver.set_options(energy="arap")

    with pytest.raises(akvf.OptionsError, match="its own callback"):
        solver.solve(callback=changes_options)
    assert solver.options == {} and np.array_equal(solver.solve().uv, reference.uv)
