"""pymeshlab tests of the Eulerian Surface Map plugin's MeshLab 2025.07 flavour (issue 5).

Run with the venv's pytest after building (tests/pymeshlab/run does both):
    .venv/bin/python -m pytest tests/pymeshlab -v -s

What it checks, in PyPI's pymeshlab 2025.7.post1 (.venv):
  - pymeshlab.load_plugin() takes build/filter_eulermap/libfilter_eulermap_2025.so, and
    pymeshlab lists and finds the filter, with the parameters of parameters.h;
  - the sample runs of the MeshLab tests that pymeshlab shares (sphere -> torus, spot -> cow
    with anchors), through samples/map_meshes.py's map_meshes(): the same checks as
    tests/meshlab/meshlab_host.py (cut topology, >= 99% of the mapped vertices within 0.5% of
    the target's diagonal, before and after the final projection, the log, the input layers
    and files unchanged), and that the figures the filter returns agree with the files;
  - samples/map_meshes.py as a command, with and without a failure;
  - every bad input of the MeshLab tests, and layer ids that do not exist, raise
    pymeshlab's PyMeshLabException carrying the filter's message.
Outputs go to out/pymeshlab/ (kept).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np
import pymeshlab
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path[:0] = [os.path.join(ROOT, "samples"), os.path.join(ROOT, "tests", "meshlab")]
import map_meshes  # noqa: E402  the sample script, as a module
import meshes  # noqa: E402  the MeshLab tests' mesh reader and measures
import meshlab_host  # noqa: E402  shared with the MeshLab tests: the sample expectations and bad inputs

SAMPLES = os.path.join(ROOT, "samples")
OUT = os.path.join(ROOT, "out", "pymeshlab")
FILTER = map_meshes.FILTER
SAMPLE_RUNS = [run for run in meshlab_host.SAMPLE_RUNS if run[0] in ("sphere_to_torus", "spot_to_cow")]


@pytest.fixture(scope="session", autouse=True)
def plugin():
    map_meshes.load_plugin()


def mesh_set(*files):
    ms = pymeshlab.MeshSet()
    for f in files:
        ms.load_new_mesh(f)
    ms.set_current_mesh(0)
    return ms


def test_plugin_lists_filter(capfd):
    assert FILTER in pymeshlab.filter_list()
    pymeshlab.search("eulerian")
    assert FILTER in capfd.readouterr().out, "pymeshlab.search('eulerian') does not find the filter"
    ms = mesh_set(os.path.join(SAMPLES, "sphere.ply"))
    assert list(ms.filter_parameter_values(FILTER)) == meshlab_host.plugin_parameter_names()


@pytest.mark.parametrize("name,source,target,expect", SAMPLE_RUNS, ids=[run[0] for run in SAMPLE_RUNS])
def test_sample(name, source, target, expect):
    outdir = os.path.join(OUT, name)
    shutil.rmtree(outdir, ignore_errors=True)
    before = meshlab_host.sample_checksums()
    src, tgt = os.path.join(SAMPLES, source), os.path.join(SAMPLES, target)
    ms, figures, log = map_meshes.map_meshes(src, tgt, outdir)
    assert meshlab_host.sample_checksums() == before, "the run changed files in samples/"

    base = os.path.splitext(source)[0]
    for line in ("Eulerian Surface Map: ", "grid: ", "times (s): ", "map quality: ", f"new layer {base}_cut: ",
                 f"new layer {base}_mapped: "):
        assert any(l.startswith(line) for l in log), f"the log lacks a '{line}...' line"
    if "anchors" in expect:  # every active point of the .pp beside the source, at least 6
        n = len(re.findall(r'<point [^>]*active="1"', open(os.path.join(SAMPLES, expect["anchors"])).read()))
        assert n >= 6 and figures["anchors"] == n, f"{figures['anchors']} anchors used, {expect['anchors']} has {n}"
        assert any(l.startswith(f"anchors: {n} named pairs") for l in log), f"the log does not report {n} pairs"
        # Per anchor (report.h, AnchorFigure): its error in the log, and within a cell for those the grid resolves.
        names = re.findall(r'<point [^>]*active="1"[^>]*name="([^"]*)"', open(os.path.join(SAMPLES, expect["anchors"])).read())
        per_anchor = next((l for l in log if l.startswith("anchors (error in cells")), "")
        assert names and all(f" {a} " in per_anchor for a in names), f"the log's per-anchor line lacks some of {names}"
        assert figures["anchor_error_resolved_cells"] <= min(figures["anchor_error_cells"], 1.0)

    for layer, path in ((0, src), (1, tgt)):
        a, m = meshes.read_mesh(path), ms.mesh(layer)
        assert [tuple(f) for f in m.face_matrix()] == a.faces and np.allclose(m.vertex_matrix(), a.verts, atol=1e-6), \
            f"the input layer {os.path.basename(path)} was changed by the filter"

    c = meshes.read_mesh(os.path.join(outdir, "cut.ply"))
    m = meshes.read_mesh(os.path.join(outdir, "mapped.ply"))
    assert len(c.verts) == len(m.verts) and c.faces == m.faces, "cut.ply and mapped.ply differ in vertices or faces"
    assert "quality" in c.vertex, "the cut layer has no vertex quality"
    assert np.allclose(c.vertex["TargetPosition"], m.verts, atol=1e-5), "TargetPosition is not the mapped position"
    if "texture" in expect:
        assert "texcoord" in c.face_props, "the cut layer has no wedge texture coordinates"
        assert f"TextureFile {expect['texture']}" in c.comments, f"the cut layer does not name {expect['texture']}"
        assert os.path.isfile(os.path.join(outdir, expect["texture"])), "the texture image was not saved"
    if expect.get("mapped_texture"):  # the forward method: the source's own coordinates and image
        s = meshes.read_mesh(src)
        assert "texcoord" in m.face_props and np.allclose(m.face_props["texcoord"], s.face_props["texcoord"], atol=1e-6), \
            "the mapped layer lacks the source's coordinates"
        assert f"TextureFile {expect['mapped_texture']}" in m.comments, f"mapped.ply does not name {expect['mapped_texture']}"
    for line in (expect.get("note"), expect.get("log")):
        assert not line or any(l.startswith(line) for l in log), f"the log lacks a '{line}...' line"

    t = meshes.read_mesh(tgt)
    rate = meshes.on_surface_rate(m.verts, t, 0.005 * meshes.diagonal(t.verts))
    topo = meshes.topology(c)
    print(f"\n    {name}: {figures['time_total_s']:.0f} s in the core; cut {len(c.verts)} v {len(c.faces)} f, "
          f"components/loops/chi {topo}; mapped on target {100 * rate:.2f}%, before projection "
          f"{100 * figures['on_surface_rate']:.2f}%, coverage {100 * figures['coverage']:.2f}%, "
          f"anchor error {figures['anchor_error_cells']:.2f} cells")
    assert rate >= 0.99, f"only {100 * rate:.2f}% of the mapped vertices lie within 0.5% of the target's diagonal"
    # The report's rate measures the tracked images before the final projection (report.h).
    assert figures["on_surface_rate"] >= 0.99, f"on-surface rate before projection {figures['on_surface_rate']}"
    assert topo == (expect["components"], expect["loops"], expect["chi"]), f"cut layer: {topo}, expected {expect}"
    assert (figures["cut_components"], figures["cut_boundary_loops"], figures["cut_euler_characteristic"]) == topo
    assert (figures["cut_vertices"], figures["cut_faces"]) == (len(c.verts), len(c.faces))


def test_colour_and_quality_follow_the_map():
    """transfer_color_quality: the cut sphere takes the torus's vertex colour and quality
    (linear functions of the position, set by pymeshlab's own filters) at each vertex's
    image; without them on the target, a note and the distortion stays the quality."""
    ms = mesh_set(_SPHERE, _TORUS)
    ms.set_current_mesh(1)
    ms.compute_color_by_function_per_vertex(x="127+90*x", y="50", z="200")
    ms.compute_scalar_by_function_per_vertex(q="3*x+2*y-z")
    ms.set_current_mesh(0)
    log = []
    map_meshes.apply_logged(ms, log, target_mesh=1, grid_resolution=32, steps=20, transfer_color_quality=True)
    cut, mapped = ms.mesh(2), ms.mesh(3)
    p = mapped.vertex_matrix()
    assert cut.has_vertex_color() and cut.has_vertex_scalar()
    red = cut.vertex_color_matrix()[:, 0] * 255
    colour_error = np.abs(red - (127 + 90 * p[:, 0])).max()
    quality_error = np.abs(cut.vertex_scalar_array() - (3 * p[:, 0] + 2 * p[:, 1] - p[:, 2])).max()
    print(f"\n    largest colour error {colour_error:.2f} levels, quality error {quality_error:.1e}")
    # MeshLab's function filter truncates the target's channels to 8 bits (up to 1 level
    # off), the interpolated colour is rounded again: 2 levels at most, far from a wrong image.
    assert colour_error <= 2.5 and np.allclose(cut.vertex_color_matrix()[:, 1:3] * 255, [50, 200], atol=0.5)
    assert quality_error <= 1e-4

    ms, log = mesh_set(_SPHERE, _TORUS), []
    map_meshes.apply_logged(ms, log, target_mesh=1, grid_resolution=24, steps=8, transfer_color_quality=True)
    assert any(l.startswith("note: transfer_color_quality: the target 'torus.ply' has no per-vertex colour or quality")
               for l in log), log
    assert ms.mesh(2).vertex_scalar_array().min() >= 0, "the cut's quality is not the distortion (>= 0)"


def test_per_vertex_texcoords_of_the_target():
    """A target with per-vertex texture coordinates (set by pymeshlab's own filter to a
    linear function of the position): the cut spot takes them per wedge, equal to that
    function at each vertex's image; the mapped layer keeps spot's own coordinates."""
    ms = mesh_set(os.path.join(SAMPLES, "spot.ply"), _SPHERE)
    ms.set_current_mesh(1)
    ms.compute_texcoord_by_function_per_vertex(u="0.5+0.3*x", v="0.5+0.3*y")
    assert ms.current_mesh().has_vertex_tex_coord() and not ms.current_mesh().has_wedge_tex_coord()
    ms.set_current_mesh(0)
    log = []
    map_meshes.apply_logged(ms, log, target_mesh=1, grid_resolution=32, steps=20)
    assert any(l.startswith("texture: pulled per wedge from the target's per-vertex coordinates") for l in log), log
    cut, mapped = ms.mesh(2), ms.mesh(3)
    assert cut.has_wedge_tex_coord()
    p = mapped.vertex_matrix()[cut.face_matrix()].reshape(-1, 3)  # the images of the corners, wedge order
    uv = cut.wedge_tex_coord_matrix()
    error = np.abs(uv - np.stack([0.5 + 0.3 * p[:, 0], 0.5 + 0.3 * p[:, 1]], axis=1)).max()
    print(f"\n    per-vertex target: largest UV error {error:.1e} over {len(uv)} wedges")
    assert error <= 1e-5
    # The mapped layer's faces that are spot's own (the cut's corners, which lie on spot, at a
    # face of spot's: the ones refinement left whole) keep that face's coordinates, corner by corner.
    source = ms.mesh(0)
    own = {}
    for corners, uvs in zip(source.vertex_matrix()[source.face_matrix()], source.wedge_tex_coord_matrix().reshape(-1, 3, 2)):
        own[frozenset(map(tuple, np.round(corners, 9)))] = {tuple(c): uv for c, uv in zip(np.round(corners, 9), uvs)}
    kept = 0
    for corners, uvs in zip(cut.vertex_matrix()[cut.face_matrix()], mapped.wedge_tex_coord_matrix().reshape(-1, 3, 2)):
        corners = np.round(corners, 9)
        face = own.get(frozenset(map(tuple, corners)))
        if face is None:
            continue
        kept += 1
        for c, uv in zip(corners, uvs):
            assert np.allclose(uv, face[tuple(c)], atol=1e-7), "the mapped layer lost the source's own coordinates"
    print(f"    {kept} of spot's {len(source.face_matrix())} faces kept whole, their coordinates kept")
    assert kept >= len(source.face_matrix()) // 2


def test_map_meshes_command():
    outdir = os.path.join(OUT, "map_meshes")
    shutil.rmtree(outdir, ignore_errors=True)
    # Started by a python3 without pymeshlab, the script runs itself again with the venv's.
    command = ["python3", os.path.join(SAMPLES, "map_meshes.py"), os.path.join(SAMPLES, "torus.ply"),
               os.path.join(SAMPLES, "sphere.ply"), outdir]
    p = subprocess.run(command + ["--grid", "24", "--steps", "8"], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, f"map_meshes.py failed ({p.returncode}): {p.stderr[-500:]}"
    report = open(os.path.join(outdir, "report.txt")).read()
    assert "steps: 8" in report and report in p.stdout, "report.txt lacks --steps 8, or was not printed"
    c = meshes.read_mesh(os.path.join(outdir, "cut.ply"))
    m = meshes.read_mesh(os.path.join(outdir, "mapped.ply"))
    assert len(c.verts) == len(m.verts) and c.faces == m.faces
    stated = re.search(r"cut source: (\d+) components?, (\d+) boundary loops?, Euler characteristic (-?\d+); "
                       r"(\d+) vertices .*, (\d+) faces", report)
    assert stated, "report.txt has no 'cut source: ...' line"
    assert meshes.topology(c) + (len(c.verts), len(c.faces)) == tuple(map(int, stated.groups()))
    sphere = meshes.read_mesh(os.path.join(SAMPLES, "sphere.ply"))
    assert meshes.on_surface_rate(m.verts, sphere, 0.005 * meshes.diagonal(sphere.verts)) >= 0.99

    p = subprocess.run(command + ["--grid", "2"], capture_output=True, text=True, timeout=300)
    assert p.returncode == 1 and "grid_resolution 2 is out of range" in p.stderr, p.stderr[-500:]


# The MeshLab tests' bad inputs (their parameter names are pymeshlab's keyword arguments;
# a new MeshSet's layer ids are the load order, as the .mlx scripts' layer numbers), and
# what only pymeshlab can pass: ids of no layer.
_BAD_DIR = tempfile.mkdtemp(prefix="eulermap-pymeshlab-")
_SPHERE, _TORUS = os.path.join(SAMPLES, "sphere.ply"), os.path.join(SAMPLES, "torus.ply")
BAD_INPUTS = meshlab_host.bad_inputs(_BAD_DIR) + [
    ("no_target_by_default", [_SPHERE], {}, "no target mesh"),
    ("target_id_missing", [_SPHERE, _TORUS], dict(target_mesh=99), "target_mesh: layer 99 does not exist"),
    ("source_id_missing", [_SPHERE, _TORUS], dict(source_mesh=7), "source_mesh: layer 7 does not exist"),
    ("target_id_negative", [_SPHERE, _TORUS], dict(target_mesh=-1), "no target mesh"),
]


@pytest.fixture(scope="module")
def bad_dir():
    yield _BAD_DIR
    shutil.rmtree(_BAD_DIR, ignore_errors=True)


@pytest.mark.parametrize("name,inputs,values,expected", BAD_INPUTS, ids=[b[0] for b in BAD_INPUTS])
def test_bad_input(bad_dir, name, inputs, values, expected):
    ms = mesh_set(*inputs)
    layers = ms.mesh_number()
    log = []
    with pytest.raises(pymeshlab.PyMeshLabException) as failure:
        map_meshes.apply_logged(ms, log, **values)
    message = str(failure.value)
    print(f"\n    {name}: {message.splitlines()[-1]}")
    assert f"Failed to apply filter: {FILTER}" in message and expected in message, message
    assert ms.mesh_number() == layers, "a failed run left layers behind"


def test_runs_after_failures():
    """Failed runs whose MeshSets are then freed, each followed by a run in a new MeshSet:
    the interpreter lives on. (pymeshlab 2025.7.post1 keeps pointers to a failed filter's
    log; map_meshes.apply_logged and the plugin drop theirs.) In a child process, so that a
    crash fails this test alone."""
    code = f"""
import sys
sys.path.insert(0, {os.path.join(ROOT, "samples")!r})
import map_meshes, pymeshlab
map_meshes.load_plugin()
for _ in range(3):
    for grid in (2, 12):
        ms = pymeshlab.MeshSet()
        for f in ({_SPHERE!r}, {_TORUS!r}):
            ms.load_new_mesh(f)
        try:
            map_meshes.apply_logged(ms, [], source_mesh=0, target_mesh=1, grid_resolution=grid, steps=2)
        except pymeshlab.PyMeshLabException:
            assert grid == 2
        del ms
print("alive")
"""
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0 and "alive" in p.stdout, f"exit {p.returncode}: {p.stderr[-800:]}"
