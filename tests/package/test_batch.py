"""`eulermap batch` on a Dask LocalCluster of 2 worker processes (issue 16), from the
fresh venv of tests/package/run.

Six pairs onto the sample torus at grid 32: five shapes that map (the sample sphere,
spot, the cow, an ellipsoid, the torus itself) and one that cannot (a
point cloud: the filter refuses a mesh without faces). Checks that
  - every pair is in summary.csv and summary.html, with every figure of the report, and
    the figures of each mapped pair equal those of a single `eulermap map` of that pair
    (same parameters, same OpenMP thread count: 1, as each worker has), times aside;
  - the bad pair is recorded as failed with the filter's message, and the others are mapped;
  - the pairs really ran in the cluster's worker processes (two of them);
  - each mapped pair has its files (mapped vertices on the torus) and a thumbnail that
    shows three shapes;
  - a run interrupted (SIGINT) after its first finished pair exits 130; the same command
    again maps the others only (the finished pairs' result.json untouched, no .partial
    left); a third run maps nothing and starts no cluster; after a pair's folder is removed,
    a run from a CSV of the same pairs maps that pair only, to the same figures;
  - --scheduler ADDRESS: two pairs on a scheduler and a worker started with dask's commands.
"""
import csv
import json
import os
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SAMPLES = os.path.join(ROOT, "samples")
OUT = os.path.join(ROOT, "out", "package", "batch")
sys.path.insert(0, os.path.join(ROOT, "tests", "meshlab"))
sys.path.insert(0, HERE)
import meshes  # noqa: E402
from test_package import point_cloud  # noqa: E402

BIN = os.path.dirname(sys.executable)
PARAMS = ["--grid", "32", "--steps", "16"]
SINGLE_ENV = dict(os.environ, OMP_NUM_THREADS="1")  # as each LocalCluster worker runs its pair
TIMES = ("time_", "wall_s", "peak_memory_mib")  # what differs between two runs of one map


def write_ply(path, verts, faces):
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(verts)}\nproperty float x\nproperty float y\n"
                f"property float z\nelement face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        f.write("".join(f"{x:.7g} {y:.7g} {z:.7g}\n" for x, y, z in verts))
        f.write("".join(f"3 {a} {b} {c}\n" for a, b, c in faces))
    return path


@pytest.fixture(scope="module")
def inputs():
    """The template and the shapes, in out/package/batch/inputs (copies without the .pp
    files beside the samples: the torus has none, so anchors would not match)."""
    d = os.path.join(OUT, "inputs")
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(d)
    for f in ("torus.ply", "torus_checker.png", "sphere.ply", "spot.ply", "spot_checker.png", "cow.off"):
        shutil.copy(os.path.join(SAMPLES, f), d)
    s = meshes.read_mesh(os.path.join(SAMPLES, "sphere.ply"))
    write_ply(os.path.join(d, "ellipsoid.ply"), np.asarray(s.verts) * [1.3, 0.9, 0.7], s.faces)
    point_cloud(os.path.join(d, "cloud.ply"))
    shapes = ["sphere.ply", "spot.ply", "cow.off", "ellipsoid.ply", "cloud.ply", "torus.ply"]
    return os.path.join(d, "torus.ply"), [os.path.join(d, s) for s in shapes]


def batch(*args):
    started = time.perf_counter()
    r = subprocess.run([os.path.join(BIN, "eulermap"), "batch", *args, *PARAMS, "--workers", "2"],
                       capture_output=True, text=True, timeout=900)
    print(f"\n    eulermap batch {' '.join(a for a in args if not a.startswith('/'))}: "
          f"{time.perf_counter() - started:.1f} s")
    print("    " + "\n    ".join(l for l in r.stderr.splitlines() if l.startswith(("eulermap batch", "  ")) or ": " in l
                                 and "it/s" not in l and "pair/s" not in l and "s/pair" not in l))
    return r


def table(out):
    with open(os.path.join(out, "summary.csv"), newline="") as f:
        return {row["name"]: row for row in csv.DictReader(f)}


def result_files(out):
    """Each finished pair's result.json: name -> (modification time, text)."""
    if not os.path.isdir(os.path.join(out, "pairs")):
        return {}
    return {name: (os.stat(p).st_mtime_ns, open(p).read()) for name in os.listdir(os.path.join(out, "pairs"))
            for p in [os.path.join(out, "pairs", name, "result.json")] if os.path.isfile(p)}


def png_panels(path, panels=3):
    """Reads back the thumbnail (8-bit RGB PNG as thumbnail.py writes it): the share of
    non-white pixels in each panel."""
    data = open(path, "rb").read()
    w, h = struct.unpack(">II", data[16:24])
    idat, i = b"", 8
    while i < len(data):
        n, kind = struct.unpack(">I4s", data[i:i + 8])
        if kind == b"IDAT":
            idat += data[i + 8:i + 8 + n]
        i += 12 + n
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(h, 1 + 3 * w)
    assert (raw[:, 0] == 0).all()
    image = raw[:, 1:].reshape(h, w, 3)
    width = (w - 4 * (panels - 1)) // panels
    return [float((image[:, k * (width + 4):k * (width + 4) + width] < 250).any(axis=2).mean()) for k in range(panels)]


def test_batch_on_a_local_cluster(inputs):
    template, shapes = inputs
    out = os.path.join(OUT, "run")
    names = [os.path.splitext(os.path.basename(s))[0] + "_to_torus" for s in shapes]

    # An interrupted run (SIGINT, as Ctrl-C, once the first pair is finished). The child gets
    # SIGINT's default disposition, as in a terminal: a suite started in the background (CI,
    # nohup, `cmd &` in a script) ignores SIGINT, its children inherit that, and Python then
    # installs no KeyboardInterrupt handler, so the run mapped every pair and exited 1 (three
    # clean-clone runs failed so; `(trap '' INT; ...)` reproduces it). Where the run had mapped
    # every pair before the signal came, nothing was interrupted and it is made again.
    def sigint_as_in_a_terminal():
        signal.signal(signal.SIGINT, signal.SIG_DFL)

    for attempt in range(3):
        shutil.rmtree(out, ignore_errors=True)
        started = time.perf_counter()
        run = subprocess.Popen([os.path.join(BIN, "eulermap"), "batch", template, *shapes, "--out", out, *PARAMS,
                                "--workers", "2", "--no-progress"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True, preexec_fn=sigint_as_in_a_terminal)
        while not result_files(out) and run.poll() is None and time.perf_counter() - started < 300:
            time.sleep(0.05)
        running = run.poll() is None
        run.send_signal(signal.SIGINT)
        text = run.communicate(timeout=120)[0]
        if running and "summary in" not in text:
            break
        print(f"\n    attempt {attempt + 1}: the run mapped every pair ({time.perf_counter() - started:.1f} s) before "
              f"the signal; again")
    first = result_files(out)
    print(f"\n    interrupted after {time.perf_counter() - started:.1f} s with {len(first)} pairs finished "
          f"(exit {run.returncode})")
    assert run.returncode == 130 and "interrupted; " in text, text
    assert 1 <= len(first) < len(shapes), f"{sorted(first)} finished before the interruption"

    # the same command again: the finished pairs are not mapped again
    r = batch(template, *shapes, "--out", out)
    assert r.returncode == 1, "a pair failed: the exit status says so"  # the point cloud
    assert f"6 pairs, {len(first)} finished before (skipped), {6 - len(first)} to map" in r.stderr, r.stderr
    assert ", 2 workers" in r.stderr, r.stderr
    assert {n: v for n, v in result_files(out).items() if n in first} == first, "a finished pair was mapped again"
    assert not [d for d in os.listdir(os.path.join(out, "pairs")) if d.endswith(".partial")]
    rows = table(out)
    assert list(rows) == names

    bad = rows.pop("cloud_to_torus")
    assert bad["status"] == "failed" and bad["message"].startswith("the source mesh has no faces (2562 vertices)"), bad
    assert all(bad[k] == "" for k in bad if k.startswith(("coverage", "on_surface")))
    assert "cloud_to_torus: FAILED: the source mesh has no faces" in r.stderr + text
    failed = [n for n, row in rows.items() if row["status"] != "ok"]
    assert not failed, {n: rows[n]["message"] for n in failed}
    workers = {json.load(open(os.path.join(out, "pairs", n, "result.json")))["worker"] for n in names}
    assert all(int(w.split(":")[1]) not in (os.getpid(), run.pid) for w in workers), workers

    # every figure of the report, equal to a single run's
    torus = meshes.read_mesh(template)
    for name, shape in zip(names, shapes):
        if name not in rows:
            continue
        single = os.path.join(OUT, "single", name)
        s = subprocess.run([os.path.join(BIN, "eulermap"), "map", shape, template, single, *PARAMS, "-q",
                            "--no-progress"], capture_output=True, text=True, timeout=300, env=SINGLE_ENV)
        assert s.returncode == 0, s.stderr
        figures = json.load(open(os.path.join(single, "figures.json")))
        row = rows[name]
        assert set(figures) - {"wall_s"} <= set(row), f"{name}: figures missing from the table"
        for k, v in figures.items():
            if not k.startswith(TIMES):
                assert float(row[k]) == v, f"{name}: {k} is {row[k]} in the table, {v} in a single run"
        mapped = meshes.read_mesh(os.path.join(out, "pairs", name, "mapped.ply"))
        rate = meshes.on_surface_rate(mapped.verts, torus, 0.005 * meshes.diagonal(torus.verts))
        print(f"    {name}: coverage {100 * figures['coverage']:.2f}%, on-surface {100 * rate:.2f}%, "
              f"{figures['cut_vertices']} vertices; {len(figures) - 6} figures as in a single run")
        assert rate >= 0.99 and len(mapped.verts) == int(row["cut_vertices"])
        inked = png_panels(os.path.join(out, "pairs", name, "thumbnail.png"))
        assert all(0.05 < share < 0.9 for share in inked), f"{name}: thumbnail panels inked {inked}"

    page = open(os.path.join(out, "summary.html")).read()
    assert page.count('<tr class="ok">') == 5 and page.count('<tr class="failed">') == 1
    assert page.count("thumbnail.png") == 5 and "has no faces" in page

    # nothing left to do: no cluster, nothing written but the summary
    before = result_files(out)
    r = batch(template, *shapes, "--out", out)
    assert "6 pairs, 6 finished before (skipped), 0 to map" in r.stderr and "Dask scheduler" not in r.stderr
    assert result_files(out) == before and r.returncode == 1
    assert table(out) == dict(rows, cloud_to_torus=bad)

    # a pair lost (its folder removed): the CSV form of the same pairs maps that one only
    shutil.rmtree(os.path.join(out, "pairs", "spot_to_torus"))
    pairs = os.path.join(OUT, "pairs.csv")
    with open(pairs, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["source", "target", "name"])
        w.writerows([os.path.relpath(s, OUT), os.path.relpath(template, OUT), n] for s, n in zip(shapes, names))
    r = batch("--pairs", pairs, "--out", out)
    assert "6 pairs, 5 finished before (skipped), 1 to map" in r.stderr, r.stderr
    after = result_files(out)
    assert {n: v for n, v in after.items() if n != "spot_to_torus"} == \
           {n: v for n, v in before.items() if n != "spot_to_torus"}, "a finished pair was mapped again"
    again = table(out)
    assert {k: v for k, v in again["spot_to_torus"].items() if not k.startswith(TIMES)} == \
           {k: v for k, v in rows["spot_to_torus"].items() if not k.startswith(TIMES)}


def test_batch_on_a_running_scheduler(inputs):
    """--scheduler: a scheduler and a worker started apart (dask's own commands, as on a
    cluster), two pairs mapped by that worker, to the figures of single runs."""
    template, shapes = inputs
    out = os.path.join(OUT, "scheduler")
    address_file = os.path.join(OUT, "scheduler.json")
    dask = os.path.join(BIN, "dask")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    scheduler = subprocess.Popen([dask, "scheduler", "--scheduler-file", address_file, "--no-dashboard",
                                  "--host", "127.0.0.1", "--port", "0"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    worker = None
    try:
        started = time.perf_counter()
        while not os.path.isfile(address_file) and time.perf_counter() - started < 60:
            time.sleep(0.1)
        address = json.load(open(address_file))["address"]
        worker = subprocess.Popen([dask, "worker", address, "--nworkers", "1", "--nthreads", "1", "--no-dashboard"],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
        pair_shapes = [s for s in shapes if os.path.basename(s) in ("sphere.ply", "ellipsoid.ply")]
        r = subprocess.run([os.path.join(BIN, "eulermap"), "batch", template, *pair_shapes, "--out", out, *PARAMS,
                            "--scheduler", address], capture_output=True, text=True, timeout=600)
        print("\n    " + "\n    ".join(l for l in r.stderr.splitlines() if l.startswith(("eulermap", "sphere", "ell"))))
        assert r.returncode == 0 and f"Dask scheduler {address}, 1 workers" in r.stderr, r.stderr
    finally:
        for p in (worker, scheduler):
            if p is not None:
                p.terminate()
                p.wait(timeout=60)
    rows = table(out)
    assert list(rows) == ["sphere_to_torus", "ellipsoid_to_torus"]
    for name, shape in zip(rows, pair_shapes):
        single = os.path.join(OUT, "single", name, "figures.json")
        if not os.path.isfile(single):
            subprocess.run([os.path.join(BIN, "eulermap"), "map", shape, template, os.path.dirname(single), *PARAMS,
                            "-q", "--no-progress"], check=True, capture_output=True, timeout=300, env=SINGLE_ENV)
        figures = json.load(open(single))
        result = json.load(open(os.path.join(out, "pairs", name, "result.json")))
        assert result["status"] == "ok" and result["worker"].split(":")[1] != str(os.getpid())
        assert {k: v for k, v in result["figures"].items() if not k.startswith(TIMES)} == \
               {k: v for k, v in figures.items() if not k.startswith(TIMES)}
