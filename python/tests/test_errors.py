"""Errors: the library's typed exceptions with the command line's messages,
and messages that name the argument and the shape found."""

import subprocess

import numpy as np
import pytest

import akvf
from conftest import bumpy_disk


def test_exception_hierarchy():
    assert issubclass(akvf.InputError, ValueError) and issubclass(akvf.InputError, akvf.Error)
    assert issubclass(akvf.ValidationError, ValueError)
    assert issubclass(akvf.OptionsError, ValueError)
    assert issubclass(akvf.NumericalError, RuntimeError)
    assert issubclass(akvf.OutputError, OSError)


def test_shapes_and_dtypes_are_named():
    V, F = bumpy_disk()
    with pytest.raises(akvf.InputError, match=r"V must be an \(n, 3\) array of reals, found shape \(120, 2\)"):
        akvf.parameterize(V[:, :2], F)
    with pytest.raises(akvf.InputError, match=r"F must be an \(n, 3\) array of integers, found shape \(198,\)"):
        akvf.parameterize(V, F[:, 0])
    with pytest.raises(akvf.InputError, match="F must hold integers .* found dtype float64"):
        akvf.parameterize(V, F.astype(float))
    with pytest.raises(akvf.InputError, match=r"uv0 must be an \(n, 2\) array"):
        akvf.parameterize(V, F, uv0=np.zeros(3))


def test_non_finite_coordinates_are_input_errors():
    V, F = bumpy_disk()
    V[7, 1] = np.inf
    with pytest.raises(akvf.InputError, match="V: row 7 has a coordinate that is not finite"):
        akvf.parameterize(V, F)


def test_bad_meshes_are_validation_errors():
    V, F = bumpy_disk()
    F[3] = [0, 0, 1]
    with pytest.raises(akvf.ValidationError, match="face 3 uses the same vertex twice"):
        akvf.parameterize(V, F, repair="none")
    # The default repair sets the face aside, says so, and keeps it in uv_faces.
    with pytest.warns(UserWarning, match="set aside 1 face"):
        result = akvf.parameterize(V, F)
    assert result.uv_faces.shape == F.shape


def test_options_as_the_command_line_says(program, tmp_path):
    V, F = bumpy_disk()
    mesh = tmp_path / "disk.obj"
    akvf.write_obj(mesh, V, F, np.zeros((len(V), 2)))
    cli = subprocess.run([program, "param", str(mesh), "--grad-tol", "-1"], capture_output=True, text=True)
    assert cli.returncode != 0
    with pytest.raises(akvf.OptionsError) as python:
        akvf.parameterize(V, F, grad_tol=-1)
    assert str(python.value) == "grad_tol must be auto or >= 0, found -1"
    assert "must be auto or >= 0, found -1" in cli.stderr
    with pytest.raises(akvf.OptionsError, match="unknown preconditioner 'nope'"):
        akvf.parameterize(V, F, precond="nope")
    with pytest.raises(akvf.OptionsError, match="max_iters must be an integer, found float 1.5"):
        akvf.parameterize(V, F, max_iters=1.5)
    with pytest.raises(TypeError, match="unexpected keyword argument 'gradtol'"):
        akvf.parameterize(V, F, gradtol=1)


def test_reader_messages_name_file_and_line(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    with pytest.raises(akvf.InputError, match="bad.obj") as error:
        akvf.read_mesh(bad)
    assert "line 4" in str(error.value)
    with pytest.raises(akvf.InputError):
        akvf.read_mesh(tmp_path / "missing.off")


def test_outputs_are_never_half_written(tmp_path):
    V, F = bumpy_disk()
    with pytest.raises(akvf.OutputError):
        akvf.write_obj(tmp_path / "no" / "such" / "folder.obj", V, F, np.zeros((len(V), 2)))
    with pytest.raises(akvf.InputError, match="uv must have one row per vertex"):
        akvf.write_obj(tmp_path / "x.obj", V, F, np.zeros((3, 2)))
    assert not (tmp_path / "x.obj").exists()


def test_an_interpreter_without_numpy_is_told_which_to_use(tmp_path):
    # A stand-in numpy that fails to import, first on the path.
    (tmp_path / "numpy").mkdir()
    (tmp_path / "numpy" / "__init__.py").write_text("raise ImportError('no numpy here')\n")
    import os
    import sys
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), os.path.dirname(os.path.dirname(akvf.__file__))]))
    run = subprocess.run([sys.executable, "-c", "import akvf"], capture_output=True, text=True, env=env)
    assert run.returncode != 0
    assert "akvf needs NumPy" in run.stderr and "/usr/bin/python3" in run.stderr
