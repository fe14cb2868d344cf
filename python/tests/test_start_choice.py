"""init auto's choice between the conformal maps and the Tutte map, on the
jittered camelhead of scripts/perturbed_meshes.py (the benchmark's mesh)."""
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
    """Both unfolded conformal maps are above Tutte's in energy by the spikes
    of a few stars, which one local sweep removes; auto takes one of them, and
    the run from it is shorter."""
    V, F = jittered_camelhead(meshes)
    conformal = ["conformal", "boundary-first"]
    start = {init: akvf.parameterize(V, F, init=init, injectivity="local", max_iters=0).energy
             for init in conformal + ["tutte"]}
    assert min(start[init] for init in conformal) > start["tutte"]
    runs = {init: akvf.parameterize(V, F, init=init, injectivity="local") for init in ["auto", "tutte"]}
    assert runs["auto"].initial_map in conformal
    assert runs["auto"].status == runs["tutte"].status == "converged"
    assert runs["auto"].iterations < runs["tutte"].iterations
