"""An energy compiled by a user (python/tests/extension_energy.cpp, built
against akvf's headers alone) loaded into the module, listed, and run by name
with every preconditioner."""

import shutil

import pytest

import akvf
from conftest import bumpy_disk, signed_areas


def test_a_user_energy_from_cpp_is_listed_and_runs_with_every_preconditioner(extension):
    akvf.load_extension(extension)
    akvf.load_extension(extension)  # loading again does nothing (no "already registered")
    assert "area-symmetric-dirichlet" in dict(akvf.energies())
    V, F = bumpy_disk()
    energies = []
    for precond, _ in akvf.preconditioners():
        r = akvf.parameterize(V, F, energy="area-symmetric-dirichlet", precond=precond, max_iters=5000)
        assert (signed_areas(r.uv, F) > 0).all() and (r.trace["flips"] == 0).all(), precond
        # SLIM's proxy fits this energy poorly: it crawls to the same minimum
        # and stops there, stalled or with a failed line search (steps of
        # 1e-11 of its direction) depending on the last bits of the factor.
        assert r.status == "converged" or (precond == "slim" and r.status in ("stalled", "line-search-failed")), precond
        energies.append(r.energy)
    assert max(energies) - min(energies) < 1e-5
    assert min(energies) >= 4


def test_what_is_not_an_extension_is_refused(tmp_path):
    not_elf = tmp_path / "notes.so"
    not_elf.write_text("hello")
    with pytest.raises(akvf.InputError, match="cannot load extension"):
        akvf.load_extension(not_elf)
    with pytest.raises(akvf.InputError, match="cannot load extension"):
        akvf.load_extension(tmp_path / "missing.so")


def test_a_registration_that_throws_is_an_akvf_error_naming_the_file(extension, throwing_extension, tmp_path):
    with pytest.raises(akvf.InputError, match="registration failed with an exception that is not a std::exception"):
        akvf.load_extension(throwing_extension)
    # The same energy again under another file name: refused, naming that file.
    akvf.load_extension(extension)
    copy = tmp_path / "copy.so"
    shutil.copy(extension, copy)
    with pytest.raises(akvf.OptionsError, match="copy.so: the extension's registration failed: .*area-symmetric"):
        akvf.load_extension(copy)
