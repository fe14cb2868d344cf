"""init auto's choice between the conformal and the Tutte map, on the jittered
camelhead of scripts/perturbed_meshes.py (the benchmark's mesh)."""
import importlib.util
import pathlib

import akvf


def jittered_camelhead(meshes):
    path = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "perturbed_meshes.py"
    spec = importlib.util.spec_from_file_location("perturbed_meshes", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for name, vertices, triangles in module.perturbed_meshes(str(meshes)):
        if name == "camelhead_jitter.obj":
            return vertices, triangles
    raise AssertionError("perturbed_meshes.py wrote no camelhead_jitter.obj")


def test_auto_compares_the_maps_after_one_local_sweep(meshes):
    """The unfolded conformal map is above Tutte's in energy by the spikes of a
    few stars, which one local sweep removes; auto takes it, and the run from
    it is shorter."""
    V, F = jittered_camelhead(meshes)
    start = {init: akvf.parameterize(V, F, init=init, injectivity="local", max_iters=0).energy
             for init in ["conformal", "tutte"]}
    assert start["conformal"] > start["tutte"]
    runs = {init: akvf.parameterize(V, F, init=init, injectivity="local") for init in ["auto", "conformal", "tutte"]}
    assert runs["auto"].initial_map == "conformal"
    assert runs["conformal"].status == runs["tutte"].status == "converged"
    assert runs["conformal"].iterations < runs["tutte"].iterations
