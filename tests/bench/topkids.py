#!/usr/bin/env python3
"""The TOPKIDS correspondence benchmark (../shared/data/README.md, "topkids/"): real scans
with topological noise mapped kidXX -> kid00, every method given the same anchors.

    tests/bench/topkids.py [--pairs 01,03,...] [--anchors 16,8,0] [--grid 64] [--no-zoomout]
        (run through tests/bench/topkids, which makes the benchmark's venv)

Methods, one row each per anchor count K:
  eulermap     eulermap_bench map ... --images (the core, default parameters but the grid)
  tps+closest  a thin-plate warp of kidXX through the anchors, then kid00's nearest vertex
  zoomout      functional maps refined by ZoomOut (PyPI pyfmaps), anchors as landmarks;
               cached in out/bench-cache/ (minutes a pair)
Anchors: K farthest-point samples on kidXX (Euclidean, from vertex 0) with their true kid00
vertices. Figures per row, the means over the pairs:
  error      the protocol's: geodesic distance on kid00 (heat method, potpourri3d) between the
             predicted and the true vertex over sqrt(area of kid00), mean x 100
  <0.05 <0.10  share of kidXX vertices whose error is under 0.05 and 0.10 (not x 100)
  coverage   share of kid00's area within 2% of its diagonal of the mapped kidXX (its faces
             at the images of their vertices): eulermap's own definition (core/quality.h)
  flipped    eulermap's report: flipped area as tracked / after untangling, and the share
             of kidXX's vertices that surgery removed (they take their nearest kept
             neighbour's image), the vertices surgery added
  time       seconds a pair (wall)
"""
import argparse
import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np
import potpourri3d as pp3d
from scipy.interpolate import RBFInterpolator
from scipy.spatial import cKDTree

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "samples"))
import mesh_io  # noqa: E402

DATA = os.path.join(os.path.dirname(ROOT), "shared", "data", "topkids")
CACHE = os.path.join(ROOT, "out", "bench-cache")
BENCH = os.path.join(ROOT, "build", "tests", "bench", "eulermap_bench")


def load(name):
    m = mesh_io.read_mesh(os.path.join(DATA, name + ".off"))
    return np.array(m.verts, float), np.array(m.faces, int)


def truth(kid):
    """kidXX vertex i -> kid00 vertex (0-based)."""
    ref = np.loadtxt(os.path.join(DATA, f"kid{kid}_ref.txt"), dtype=int)
    out = np.empty(ref.shape[0], int)
    out[ref[:, 0] - 1] = ref[:, 1] - 1
    return out


def area(V, F):
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()


def farthest_points(V, k):
    chosen = [0]
    d = np.linalg.norm(V - V[0], axis=1)
    while len(chosen) < k:
        chosen.append(int(np.argmax(d)))
        d = np.minimum(d, np.linalg.norm(V - V[chosen[-1]], axis=1))
    return np.array(chosen[:k], int)


def geodesics(V, F):
    """All-pairs heat-method geodesics on kid00 (float32), computed once and cached."""
    os.makedirs(CACHE, exist_ok=True)
    path = os.path.join(CACHE, "kid00_geodesics.npy")
    if os.path.exists(path):
        return np.load(path, mmap_mode="r")
    solver = pp3d.MeshHeatMethodDistanceSolver(V, F)
    D = np.empty((len(V), len(V)), np.float32)
    for i in range(len(V)):
        D[i] = solver.compute_distance(i)
    D = np.minimum(D, D.T)  # the heat method is not exactly symmetric
    np.save(path, D)
    return D


def write_pp(path, points):
    with open(path, "w") as f:
        f.write("<!DOCTYPE PickedPoints>\n<PickedPoints>\n")
        for n, p in enumerate(points):
            f.write(f' <point x="{p[0]:.9g}" y="{p[1]:.9g}" z="{p[2]:.9g}" active="1" name="a{n}"/>\n')
        f.write("</PickedPoints>\n")


def eulermap(kid, anchors, V0, grid, options=()):
    """Images of kidXX's vertices on kid00 (points), and the report's figures."""
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [BENCH, "map", os.path.join(DATA, f"kid{kid}.off"), os.path.join(DATA, "kid00.off")]
        if len(anchors[0]):
            Vs, _ = load(f"kid{kid}")
            write_pp(os.path.join(tmp, "s.pp"), Vs[anchors[0]])
            write_pp(os.path.join(tmp, "t.pp"), V0[anchors[1]])
            cmd += [os.path.join(tmp, "s.pp"), os.path.join(tmp, "t.pp")]
        images = os.path.join(tmp, "images.txt")
        cmd += ["--grid", str(grid), "--images", images, *options]
        report = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
        table = np.loadtxt(images)
    figures = {}
    for name, pattern in (("tracked", r"flipped area ([\d.]+)% as tracked"),
                          ("flipped", r"map quality:.*? flipped area ([\d.]+)%"), ("added", r"\((\d+) added by surgery\)")):
        m = re.search(pattern, report)
        figures[name] = float(m.group(1)) if m else 0.0
    m = re.search(r"cut source: (\d+) components?, (\d+) boundary loops?", report)
    figures["cut"] = (int(m.group(1)), int(m.group(2))) if m else None
    figures["removed"] = 1 - table[:, 3].mean()
    figures["report"] = report
    return table[:, :3], figures


def parts_and_loops(V, F):
    """Connected components and boundary loops of a manifold mesh."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, count = np.unique(edges, axis=0, return_counts=True)
    rim = unique[count == 1]
    graph = lambda e: coo_matrix((np.ones(len(e)), (e[:, 0], e[:, 1])), shape=(len(V), len(V)))  # noqa: E731
    parts = connected_components(graph(edges), directed=False)[0] - (len(V) - len(np.unique(F)))
    on_rim = np.unique(rim)
    loops = connected_components(graph(rim), directed=False)[0] - (len(V) - len(on_rim))
    return parts, loops


def tps(kid, anchors, V0):
    Vs, _ = load(f"kid{kid}")
    if len(anchors[0]) < 4:
        return None
    warp = RBFInterpolator(Vs[anchors[0]], V0[anchors[1]], kernel="thin_plate_spline")
    return warp(Vs)


def zoomout(kid, anchors):
    """kidXX -> kid00 vertex indices from pyfmaps' ZoomOut with the anchors as landmarks."""
    import pyFM.functional
    import pyFM.mesh
    key = hashlib.sha1(json.dumps([kid, anchors[0].tolist(), anchors[1].tolist()]).encode()).hexdigest()[:12]
    path = os.path.join(CACHE, f"zoomout_kid{kid}_{len(anchors[0])}_{key}.json")
    if os.path.exists(path):
        with open(path) as f:
            cached = json.load(f)
        return np.array(cached["p2p"]), cached["time"]
    started = time.perf_counter()
    V0, F0 = load("kid00")
    Vs, Fs = load(f"kid{kid}")
    mesh1, mesh2 = pyFM.mesh.TriMesh(V0, F0), pyFM.mesh.TriMesh(Vs, Fs)
    model = pyFM.functional.FunctionalMapping(mesh1, mesh2)
    landmarks = np.stack([anchors[1], anchors[0]], axis=1) if len(anchors[0]) else None
    model.preprocess(n_descr=100, descr_type="WKS", landmarks=landmarks, subsample_step=5, k_process=200)
    model.fit(K=(35, 35), w_descr=1e0, w_lap=1e-2, w_dcomm=1e-1, w_orient=0)
    refined = model.zoomout_refine(nit=65, step=1)  # 35 -> 100 eigenfunctions
    p2p = model.get_p2p(FM=refined)  # mesh2 (kidXX) vertex -> mesh1 (kid00) vertex
    elapsed = time.perf_counter() - started
    os.makedirs(CACHE, exist_ok=True)
    with open(path, "w") as f:
        json.dump({"p2p": p2p.tolist(), "time": elapsed}, f)
    return p2p, elapsed


def coverage(V0, F0, Vs, Fs, images):
    """Share of kid00's area within 2% of its diagonal of the mapped kidXX (eulermap's own
    definition, core/quality.h): 20000 area-uniform samples on kid00 against a dense
    sampling of the mapped faces."""
    rng = np.random.default_rng(1)

    def sample(V, F, n):
        a = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)
        f = rng.choice(len(F), n, p=a / a.sum())
        r1, r2 = rng.random(n), rng.random(n)
        s = np.sqrt(r1)
        return (1 - s)[:, None] * V[F[f, 0]] + (s * (1 - r2))[:, None] * V[F[f, 1]] + (s * r2)[:, None] * V[F[f, 2]]

    tolerance = 0.02 * np.linalg.norm(V0.max(0) - V0.min(0))
    mapped = np.vstack([images, sample(images, Fs, 200000)])
    d, _ = cKDTree(mapped).query(sample(V0, F0, 20000))
    return float((d <= tolerance).mean())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", default="01,03,04,05,06")
    parser.add_argument("--anchors", default="16,8,0")
    parser.add_argument("--grid", type=int, default=64)
    parser.add_argument("--methods", default="eulermap,tps+closest,zoomout")
    parser.add_argument("--options", default="", help="eulermap_bench's options, e.g. '--alpha 4'")
    args = parser.parse_args()
    V0, F0 = load("kid00")
    nearest = cKDTree(V0)
    scale = np.sqrt(area(V0, F0))
    D = geodesics(V0, F0)
    print(f"# TOPKIDS kidXX -> kid00, pairs {args.pairs}, grid {args.grid}; error x 100 in sqrt(area of kid00)")
    print("| method | K | error x100 | <0.05 | <0.10 | coverage | flipped as tracked / after | removed / added vertices | time a pair (s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for K in [int(k) for k in args.anchors.split(",")]:
        for method in args.methods.split(","):
            rows = []
            for kid in args.pairs.split(","):
                Vs, Fs = load(f"kid{kid}")
                true = truth(kid)
                src = farthest_points(Vs, K) if K else np.array([], int)
                anchors = (src, true[src])
                figures = {}
                started = time.perf_counter()
                if method == "eulermap":
                    images, figures = eulermap(kid, anchors, V0, args.grid, args.options.split())
                    predicted = nearest.query(images)[1]
                elif method == "tps+closest":
                    images = tps(kid, anchors, V0)
                    if images is None:
                        break
                    predicted = nearest.query(images)[1]
                    images = V0[predicted]
                else:
                    try:
                        predicted, elapsed = zoomout(kid, anchors)
                    except ImportError:
                        break
                    started = time.perf_counter() - elapsed
                    images = V0[predicted]
                elapsed = time.perf_counter() - started
                error = np.asarray(D[predicted, true]) / scale
                rows.append(dict(error=100 * error.mean(), u05=(error < 0.05).mean(), u10=(error < 0.10).mean(),
                                 coverage=coverage(V0, F0, Vs, Fs, images), time=elapsed, **figures))
                print(f"#   kid{kid} {method} K={K}: error {rows[-1]['error']:.2f}, coverage {rows[-1]['coverage']:.3f}"
                      + (f", tracked {figures.get('tracked', float('nan')):.2f}% / {figures.get('flipped', float('nan')):.2f}%, "
                         f"removed {figures['removed']:.3f}, added {figures.get('added', 0):.0f}, "
                         f"parts/loops {parts_and_loops(Vs, Fs)} -> {figures['cut']}" if figures else ""),
                      flush=True)
            if not rows:
                continue
            mean = lambda k: np.mean([r[k] for r in rows if k in r]) if any(k in r for r in rows) else float("nan")  # noqa: E731
            flips = f"{mean('tracked'):.2f}% / {mean('flipped'):.2f}%" if method == "eulermap" else "-"
            surgery = f"{mean('removed'):.3f} / {mean('added'):.0f}" if method == "eulermap" else "-"
            print(f"| {method} | {K} | {mean('error'):.2f} | {mean('u05'):.2f} | {mean('u10'):.2f} | {mean('coverage'):.3f} "
                  f"| {flips} | {surgery} | {mean('time'):.1f} |", flush=True)


if __name__ == "__main__":
    main()
