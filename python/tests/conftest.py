"""Shared fixtures of the Python tests: small generated meshes, the akvf
program (AKVF_PROGRAM, set by ctest) and the shared meshes folder."""

import os
import pathlib

import numpy as np
import pytest


def bumpy_disk(nx=12, ny=10):
    """A curved grid (a disk): the same kind of mesh the C++ tests use."""
    xs, ys = np.meshgrid(np.linspace(0, 1, nx), np.linspace(0, 1, ny), indexing="ij")
    V = np.stack([xs.ravel(), ys.ravel(), 0.3 * np.sin(3 * xs.ravel()) * np.cos(2 * ys.ravel())], axis=1)
    F = []
    for i in range(nx - 1):
        for j in range(ny - 1):
            a, b, c, d = i * ny + j, (i + 1) * ny + j, (i + 1) * ny + j + 1, i * ny + j + 1
            F += [[a, b, c], [a, c, d]]
    return V, np.array(F, dtype=np.int64)


def tet_grid(n=3):
    """The unit cube cut into n^3 cells of 6 positively oriented tets each."""
    g = np.linspace(0, 1, n + 1)
    V = np.array([[x, y, z] for x in g for y in g for z in g])
    index = lambda i, j, k: (i * (n + 1) + j) * (n + 1) + k  # noqa: E731
    T = []
    for i in range(n):
        for j in range(n):
            for k in range(n):
                c = [index(i + a, j + b, k + d) for a in (0, 1) for b in (0, 1) for d in (0, 1)]
                for path in ([1, 3], [1, 5], [2, 3], [2, 6], [4, 5], [4, 6]):  # Kuhn's six tets
                    t = [c[0], c[path[0]], c[path[1]], c[7]]
                    p = V[t]
                    if np.linalg.det(np.stack([p[1] - p[0], p[2] - p[0], p[3] - p[0]])) < 0:
                        t[1], t[2] = t[2], t[1]
                    T.append(t)
    return V, np.array(T, dtype=np.int32)


def signed_areas(uv, F):
    a, b, c = uv[F[:, 0]], uv[F[:, 1]], uv[F[:, 2]]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


@pytest.fixture
def disk():
    return bumpy_disk()


def built_file(variable, what):
    """The path in environment variable `variable` (set by ctest), or skip the test."""
    path = os.environ.get(variable)
    if not path or not os.path.exists(path):
        pytest.skip("%s (%s) is not set; ctest sets it" % (variable, what))
    return path


@pytest.fixture
def program():
    return built_file("AKVF_PROGRAM", "the akvf program")


@pytest.fixture
def extension():
    return built_file("AKVF_TEST_EXTENSION", "the test extension")


@pytest.fixture
def throwing_extension():
    return built_file("AKVF_THROWING_EXTENSION", "the test extension whose registration throws")


@pytest.fixture
def meshes():
    folder = os.environ.get("AKVF_DATA_DIR") or str(pathlib.Path(__file__).resolve().parents[3] / "shared" / "meshes")
    if not os.path.isdir(folder):
        pytest.skip("the shared meshes folder is absent (%s)" % folder)
    return pathlib.Path(folder)
