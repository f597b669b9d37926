"""Tests of the Python package (issue 16), run by tests/package/run in a fresh venv that
has the wheel from build-wheel/dist/ installed (pip install eulermap-*.whl) and nothing of
the repository's build/ or .venv.

What it checks:
  - import eulermap loads the plugin the wheel carries into PyPI's pymeshlab 2025.7.post1,
    and the wheel's metadata pins exactly that pymeshlab;
  - eulermap.map_meshes() returns the filter's own figures (those of apply_filter on the
    same meshes), makes the filter's layers, reports the filter's stages as they run
    (progress percentages in order, every time step) and its log; a failure raises
    PyMeshLabException with the filter's message and leaves pymeshlab usable;
  - `eulermap map` writes the files (the mapped vertices on the target, figures.json the
    figures of map_meshes()), shows its progress bar over the stages, and fails with the
    filter's message;
  - a pymeshlab other than 2025.7.post1 is refused: by pip (the pin) and by import eulermap
    (a real pymeshlab 2023.12.post3, installed with --no-deps in a second venv).
"""
import glob
import importlib.metadata
import json
import os
import re
import subprocess
import sys

import numpy as np
import pymeshlab
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SAMPLES = os.path.join(ROOT, "samples")
OUT = os.path.join(ROOT, "out", "package")
sys.path.insert(0, os.path.join(ROOT, "tests", "meshlab"))
import meshes  # noqa: E402  the MeshLab tests' mesh reader and measures

import eulermap  # noqa: E402

SPHERE, TORUS = os.path.join(SAMPLES, "sphere.ply"), os.path.join(SAMPLES, "torus.ply")
FAST = dict(grid_resolution=32, steps=20)
BIN = os.path.dirname(sys.executable)


def without_times(figures):
    """The figures that two runs of one map share: not its times, not its process's peak memory."""
    return {k: v for k, v in figures.items() if not k.startswith("time_") and k not in ("wall_s", "peak_memory_mib")}


def point_cloud(path):
    """A PLY with the sphere's vertices and no faces: the filter refuses it."""
    v = meshes.read_mesh(SPHERE).verts
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(v)}\nproperty float x\nproperty float y\n"
                "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n")
        f.write("".join(f"{x} {y} {z}\n" for x, y, z in v))
    return path


def test_import_loads_the_wheels_plugin():
    site = os.path.dirname(os.path.dirname(eulermap.__file__))
    assert os.path.realpath(eulermap.PLUGIN).startswith(os.path.realpath(site) + os.sep)
    assert os.path.isfile(eulermap.PLUGIN) and not eulermap.PLUGIN.startswith(os.path.join(ROOT, "build"))
    assert eulermap.FILTER in pymeshlab.filter_list()
    assert importlib.metadata.version("pymeshlab") == eulermap.PYMESHLAB_REQUIRED == "2025.7.post1"
    assert "pymeshlab==2025.7.post1" in [r.replace(" ", "") for r in importlib.metadata.requires("eulermap")]
    wheel = os.environ.get("EULERMAP_WHEEL")
    if wheel:  # the venv holds this very wheel's plugin
        import zipfile
        with zipfile.ZipFile(os.path.join(ROOT, wheel)) as z:
            assert z.read("eulermap/libfilter_eulermap_2025.so") == open(eulermap.PLUGIN, "rb").read()
    p = eulermap.parameters()
    assert list(p)[:2] == ["grid_resolution", "steps"] and p["grid_resolution"] == (int, 64)
    assert p["align"] == (str, "centre-and-scale") and p["fill_holes"] == (bool, False)


def test_map_meshes_returns_the_filters_figures_and_its_progress():
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(SPHERE)
    ms.load_new_mesh(TORUS)
    reports, log = [], []
    figures = eulermap.map_meshes(ms, 0, 1, progress=lambda p, stage: reports.append((p, stage)), log=log, **FAST)

    plain = pymeshlab.MeshSet()  # the same filter, called the plain way
    plain.load_new_mesh(SPHERE)
    plain.load_new_mesh(TORUS)
    direct = plain.apply_filter(eulermap.FILTER, source_mesh=0, target_mesh=1, **FAST)
    assert without_times(figures) == without_times(direct)
    assert set(figures) == set(direct)

    assert ms.mesh_number() == 4 and ms.mesh(2).vertex_number() == figures["cut_vertices"]
    assert (figures["cut_components"], figures["cut_boundary_loops"], figures["cut_euler_characteristic"]) == (1, 2, 0)
    assert figures["on_surface_rate"] >= 0.99 and figures["coverage"] >= 0.99
    rate = meshes.on_surface_rate(ms.mesh(3).vertex_matrix().tolist(), meshes.read_mesh(TORUS),
                                  0.005 * meshes.diagonal(meshes.read_mesh(TORUS).verts))
    assert rate >= 0.99, f"{100 * rate:.2f}% of the mapped vertices on the torus"

    percents = [p for p, _ in reports]
    stages = [s for _, s in reports]
    print(f"\n    {len(reports)} progress reports: {stages[0]!r} ... {stages[-1]!r}")
    assert percents == sorted(percents) and percents[-1] == 100
    assert "checking the meshes" in stages and stages[-1] == "Eulerian map: done"
    steps = {int(m.group(1)) for s in stages for m in [re.match(r"step (\d+) of 20$", s)] if m}
    assert steps >= set(range(2, 21)), f"time steps reported: {sorted(steps)}"
    assert any(l.startswith("map quality: on-surface") for l in log) and not any("[" in l and "%]" in l for l in log)


def test_map_meshes_failure_carries_the_filters_message(tmp_path):
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(SPHERE)
    ms.load_new_mesh(point_cloud(str(tmp_path / "cloud.ply")))
    log = []
    with pytest.raises(pymeshlab.PyMeshLabException, match="has no faces"):
        eulermap.map_meshes(ms, 0, 1, log=log, **FAST)
    del ms  # pymeshlab's own bug after a failure (a freed log) would crash the next load
    again = pymeshlab.MeshSet()
    again.load_new_mesh(TORUS)
    assert again.current_mesh().vertex_number() == 2048


def test_command_map(tmp_path):
    out = os.path.join(OUT, "map_sphere_to_torus")
    r = subprocess.run([os.path.join(BIN, "eulermap"), "map", SPHERE, TORUS, out, "--grid", "32", "--steps", "20"],
                       capture_output=True, text=True, timeout=300)
    print(r.stderr[-600:])
    assert r.returncode == 0, r.stderr
    for name in ("cut.ply", "mapped.ply", "report.txt", "figures.json"):
        assert os.path.isfile(os.path.join(out, name)), name
    # tqdm's bar over the filter's stages: each redraw on stderr, the last one at 100%
    # (one redraw per progress report of the filter)
    draws = re.findall(r"^(\S[^|]*?) +(\d+)%\|", r.stderr, re.M)  # text=True: each \r a line end
    steps = {stage for stage, _ in draws if re.fullmatch(r"step \d+ of 20", stage.strip())}
    assert steps >= {f"step {k} of 20" for k in range(2, 21)} and draws[-1] == ("Eulerian map: done", "100"), draws
    assert [int(p) for _, p in draws] == sorted(int(p) for _, p in draws)
    assert "map quality: on-surface" in r.stdout and "wrote " in r.stdout

    figures = json.load(open(os.path.join(out, "figures.json")))
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(SPHERE)
    ms.load_new_mesh(TORUS)
    assert without_times(figures) == without_times(eulermap.map_meshes(ms, 0, 1, **FAST))
    cut, mapped = (meshes.read_mesh(os.path.join(out, n)) for n in ("cut.ply", "mapped.ply"))
    torus = meshes.read_mesh(TORUS)
    assert np.allclose(cut.vertex["TargetPosition"], mapped.verts, atol=1e-5)
    assert meshes.topology(cut) == (1, 2, 0) and len(cut.verts) == figures["cut_vertices"]
    assert meshes.on_surface_rate(mapped.verts, torus, 0.005 * meshes.diagonal(torus.verts)) >= 0.99

    bad = subprocess.run([os.path.join(BIN, "eulermap"), "map", SPHERE, point_cloud(str(tmp_path / "cloud.ply")),
                          str(tmp_path / "bad"), "--no-progress", "-q"], capture_output=True, text=True, timeout=120)
    assert bad.returncode == 1 and "the map failed" in bad.stderr and "has no faces" in bad.stderr, bad.stderr
    assert "Applying filter" not in bad.stdout + bad.stderr and "LOG:" not in bad.stdout + bad.stderr


def test_other_pymeshlab_is_refused(tmp_path):
    """pip refuses the wheel with another pymeshlab, and import eulermap refuses a real
    pymeshlab 2023.12.post3 put beside it with --no-deps (which skips pip's check)."""
    wheel = os.path.join(ROOT, os.environ.get("EULERMAP_WHEEL") or sorted(glob.glob(
        os.path.join(ROOT, "build-wheel", "dist", "eulermap-*.whl")))[-1])
    pip = [sys.executable, "-m", "pip", "--disable-pip-version-check"]
    r = subprocess.run(pip + ["install", "--dry-run", wheel, "pymeshlab==2023.12.post3"], capture_output=True,
                       text=True, timeout=300)
    assert r.returncode != 0 and "pymeshlab==2025.7.post1" in r.stdout + r.stderr, r.stdout + r.stderr
    assert "conflict" in (r.stdout + r.stderr).lower()

    venv = tmp_path / "old"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    python = str(venv / "bin" / "python")
    subprocess.run([python, "-m", "pip", "install", "-q", "--disable-pip-version-check", "--no-deps", wheel,
                    "pymeshlab==2023.12.post3"], check=True, timeout=600)
    r = subprocess.run([python, "-c", "import eulermap"], capture_output=True, text=True, timeout=120)
    print("\n    " + r.stderr.strip().splitlines()[-1])
    assert r.returncode != 0
    assert re.search(r"ImportError: eulermap's plugin is built for pymeshlab==2025\.7\.post1 .* this environment "
                     r"has pymeshlab 2023\.12\.post3\. Install the one it needs: pip install pymeshlab==2025\.7\.post1",
                     r.stderr), r.stderr


def test_build_without_the_headers_says_what_is_missing(tmp_path):
    """pip wheel . with no meshlab 2025.07 source tree: the build stops, naming the variable
    and how to fetch the tree (pip runs the wheel's CMake project in its own environment)."""
    r = subprocess.run([sys.executable, "-m", "pip", "wheel", "--disable-pip-version-check", "--no-deps", "-w",
                        str(tmp_path / "dist"), "-C", f"build-dir={tmp_path / 'build'}", ROOT],
                       capture_output=True, text=True, timeout=600,
                       env=dict(os.environ, EULERMAP_MESHLAB_2025_SOURCE=str(tmp_path / "nothing")))
    text = " ".join((r.stdout + r.stderr).split())
    assert r.returncode != 0 and not glob.glob(str(tmp_path / "dist" / "*.whl"))
    assert f"EULERMAP_MESHLAB_2025_SOURCE='{tmp_path / 'nothing'}' is not such a tree" in text, text[-2000:]
    assert "setup/fetch-meshlab-source.sh 2025.07~dfsg .deps" in text
