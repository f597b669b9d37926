"""Measures of meshes for the MeshLab integration tests (standard library only); the meshes
are read by samples/mesh_io.py (read_mesh, Mesh: .verts, .faces, .vertex, .face_props,
.comments, .textures).

topology(mesh) -> (components, boundary loops, Euler characteristic) of the referenced part.
on_surface_rate(points, mesh, tolerance) -> share of points within `tolerance` of the surface.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "samples"))
from mesh_io import Mesh, read_mesh  # noqa: E402,F401  (the tests read meshes through this module)


def diagonal(points):
    lo = [min(p[k] for p in points) for k in range(3)]
    hi = [max(p[k] for p in points) for k in range(3)]
    return math.sqrt(sum((hi[k] - lo[k]) ** 2 for k in range(3)))


def topology(m):
    """(components, boundary loops, Euler characteristic) over the vertices faces use."""
    parent = {}

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    edges = {}
    for f in m.faces:
        for v in f:
            parent.setdefault(v, v)
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            key = (min(a, b), max(a, b))
            edges[key] = edges.get(key, 0) + 1
        ra, rb, rc = find(f[0]), find(f[1]), find(f[2])
        parent[rb] = ra
        parent[find(rc)] = ra
    components = len({find(v) for v in parent})
    # Boundary loops: connected pieces of the edges used by one face only.
    bparent = {}

    def bfind(x):
        while bparent[x] != x:
            bparent[x] = bparent[bparent[x]]
            x = bparent[x]
        return x

    for (a, b), n in edges.items():
        if n == 1:
            bparent.setdefault(a, a)
            bparent.setdefault(b, b)
            bparent[bfind(a)] = bfind(b)
    loops = len({bfind(v) for v in bparent})
    chi = len(parent) - len(edges) + len(m.faces)
    return components, loops, chi


def _closest_on_triangle(p, a, b, c):
    """Squared distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5)."""
    def sub(u, v):
        return (u[0] - v[0], u[1] - v[1], u[2] - v[2])

    def dot(u, v):
        return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]

    def dist2(q):
        d = sub(p, q)
        return dot(d, d)

    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return dist2(a)
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return dist2(b)
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        v = d1 / (d1 - d3)
        return dist2((a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]))
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return dist2(c)
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        w = d2 / (d2 - d6)
        return dist2((a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return dist2((b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2])))
    denom = 1.0 / (va + vb + vc)
    v, w = vb * denom, vc * denom
    return dist2((a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w))


def on_surface_rate(points, m, tolerance):
    """Share of `points` within `tolerance` of the triangles of m (a uniform grid of cells
    of size ~ tolerance holds each triangle in the cells its padded box meets)."""
    if not points:
        return 0.0
    lo = [min(v[k] for v in m.verts) - 2 * tolerance for k in range(3)]
    size = max(tolerance, diagonal(m.verts) / 200)
    cells = {}
    for f in m.faces:
        a, b, c = m.verts[f[0]], m.verts[f[1]], m.verts[f[2]]
        c0 = [int((min(a[k], b[k], c[k]) - tolerance - lo[k]) // size) for k in range(3)]
        c1 = [int((max(a[k], b[k], c[k]) + tolerance - lo[k]) // size) for k in range(3)]
        for i in range(c0[0], c1[0] + 1):
            for j in range(c0[1], c1[1] + 1):
                for k in range(c0[2], c1[2] + 1):
                    cells.setdefault((i, j, k), []).append((a, b, c))
    t2 = tolerance * tolerance
    near = 0
    for p in points:
        key = tuple(int((p[k] - lo[k]) // size) for k in range(3))
        for a, b, c in cells.get(key, ()):
            if _closest_on_triangle(p, a, b, c) <= t2:
                near += 1
                break
    return near / len(points)
