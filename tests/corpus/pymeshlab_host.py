"""One corpus case in pymeshlab (run by tests/corpus/run_corpus.py with the venv's python,
in its own process under a memory limit): builds the two layers, applies the filter
through samples/map_meshes.py's apply_logged (which captures the log, also on failure) and
writes what happened as JSON.

Usage: pymeshlab_host.py SPEC.json
SPEC: {"plugin": .so, "source": MESH, "target": MESH, "params": {...}, "result": path}
MESH: {"file": path} (loaded with load_new_mesh), or {"arrays": path of JSON {"verts",
"faces"}, "file": the same mesh as a PLY}: a new pymeshlab.Mesh from the arrays (which
bypasses the loader's cleaning), or the PLY when there are no vertices (pymeshlab refuses
an empty vertex matrix).
"""
import json
import os
import sys
import traceback

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "samples"))

import numpy as np  # noqa: E402
import pymeshlab  # noqa: E402

import map_meshes  # noqa: E402


def add_layer(ms, spec, label):
    if "arrays" in spec:
        data = json.load(open(spec["arrays"]))
        if data["verts"]:
            v = np.array(data["verts"], dtype=np.float64).reshape(-1, 3)
            if data["faces"]:
                f = np.array(data["faces"], dtype=np.int32).reshape(-1, 3)
                ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v, face_matrix=f), label)
            else:
                ms.add_mesh(pymeshlab.Mesh(vertex_matrix=v), label)
            return "arrays"
    ms.load_new_mesh(spec["file"])
    return "file"


def snapshot(mesh):
    return mesh.vertex_matrix().copy(), mesh.face_matrix().copy()


def layer_figures(mesh):
    v = mesh.vertex_matrix()
    q = mesh.vertex_scalar_array() if mesh.has_vertex_scalar() else np.zeros(0)
    return {"vertices": int(mesh.vertex_number()), "faces": int(mesh.face_number()),
            "nonfinite_vertices": int((~np.isfinite(v)).any(axis=1).sum()),
            "nonfinite_quality": int((~np.isfinite(q)).sum())}


def main():
    spec = json.load(open(sys.argv[1]))
    result = {"stage": "start"}

    def write():
        with open(spec["result"], "w") as f:
            json.dump(result, f, indent=1)

    try:
        map_meshes.load_plugin(spec["plugin"])
        ms = pymeshlab.MeshSet()
        result["source_from"] = add_layer(ms, spec["source"], "source")
        result["target_from"] = add_layer(ms, spec["target"], "target")
        before = [snapshot(ms.mesh(i)) for i in range(2)]
        result["stage"] = "filter"
        write()  # a crash from here on leaves stage 'filter'
        log = []
        try:
            figures = map_meshes.apply_logged(ms, log, source_mesh=0, target_mesh=1, **spec["params"])
            result.update(outcome="success", figures=figures)
        except pymeshlab.PyMeshLabException as e:
            result.update(outcome="error", message=str(e))
        result["log"] = log
        result["layers"] = ms.mesh_number()
        after = [snapshot(ms.mesh(i)) for i in range(2)]
        result["inputs_unchanged"] = all(
            a[0].shape == b[0].shape and np.array_equal(a[0], b[0], equal_nan=True) and np.array_equal(a[1], b[1])
            for a, b in zip(before, after))
        if result["outcome"] == "success":
            result["cut"] = layer_figures(ms.mesh(2))
            result["mapped"] = layer_figures(ms.mesh(3))
        result["stage"] = "done"
    except Exception:  # the host itself failed (loading a mesh, a bad spec)
        result.update(outcome="host_error", message=traceback.format_exc())
    write()


if __name__ == "__main__":
    main()
