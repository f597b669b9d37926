"""The bad-input corpus of issue 13: every case a source and a target mesh, parameters,
anchor files and what the filter must do with them, in both real hosts (meshlabserver
2020.09 and pymeshlab 2025.7.post1; tests/corpus/run_corpus.py runs them).

Standard library only (the runner runs under Debian's python3, which has no numpy). The
meshes are generated here, small (a few hundred to a few thousand faces), so nothing large
is checked in; a mesh is either
  - Mesh(verts, faces): lists of (x, y, z) floats (NaN and Inf allowed) and of index
    triples (repeated and unreferenced indices allowed). meshlabserver reads it from an
    ASCII PLY the runner writes; pymeshlab gets the arrays themselves
    (pymeshlab.Mesh(vertex_matrix, face_matrix)), which bypasses its loader's cleaning;
  - Sample("torus.ply"): a file of samples/, which both hosts load from there.

A case's expectation is one of
  - Error(texts): the filter fails cleanly and its message contains every text (a tuple
    of texts: any one of them);
  - Success(warnings, repairs, sane): the filter succeeds with a cut layer that has faces,
    no NaN or Inf in any output vertex, its figures in range; the log has a line
    'warning: ...' containing each text of `warnings` and a line 'repaired: ...'
    containing each text of `repairs`; `sane` also asks for no warning at all and coverage
    and on-surface rate of at least 90% (a map that worked, not only one that said why
    it did not); `log`: texts some log line must contain;
  - Either(error, warnings, sane): a clean failure containing every text of `error` (an
    empty list: any message), or a success as Success(warnings, sane=sane);
and for every success, whatever the case: a coverage below 90% must come with the warning
'the map reaches only', an on-surface rate below 90% with its own warning (a map whose
figures say it failed must say so).
"""
import math
from dataclasses import dataclass, field

# ---------------------------------------------------------------- expectations


@dataclass
class Error:
    texts: list


@dataclass
class Success:
    warnings: list = field(default_factory=list)
    repairs: list = field(default_factory=list)
    sane: bool = False
    log: list = field(default_factory=list)


@dataclass
class Either:
    error: list
    warnings: list = field(default_factory=list)
    sane: bool = False


# ---------------------------------------------------------------- meshes


@dataclass
class Mesh:
    verts: list
    faces: list


@dataclass
class Sample:
    file: str  # in samples/


@dataclass
class Case:
    name: str
    what: str  # one line: the input and why it is bad
    source: object
    target: object
    expect: object
    params: dict = field(default_factory=dict)  # the filter's parameters (pymeshlab names), over DEFAULTS
    anchors: dict = field(default_factory=dict)  # 'source' / 'target': .pp text, or Sample of a .pp
    hosts: tuple = ("meshlabserver", "pymeshlab")


# Small grids: each case runs in a few seconds, and a wrongly accepted input ends quickly.
DEFAULTS = dict(grid_resolution=24, steps=8, alpha=2, hole_radius=1, align=1, source_anchors="", target_anchors="",
                anchor_pairs="", fill_holes=False, transfer_texture=True, transfer_color_quality=False)

NAN, INF = float("nan"), float("inf")


def icosphere(subdivisions=3, radius=1.0, centre=(0.0, 0.0, 0.0)):
    """A sphere from a subdivided icosahedron: 10 * 4^n + 2 vertices, outward faces."""
    t = (1 + math.sqrt(5)) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
             (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [_unit(v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        cache, new = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                verts.append(_unit(tuple((p + q) / 2 for p, q in zip(verts[a], verts[b]))))
                cache[key] = len(verts) - 1
            return cache[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    verts = [tuple(centre[k] + radius * v[k] for k in range(3)) for v in verts]
    return Mesh(verts, faces)


def _unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return tuple(x / n for x in v)


def transformed(mesh, scale=(1.0, 1.0, 1.0), offset=(0.0, 0.0, 0.0)):
    s = scale if isinstance(scale, tuple) else (scale, scale, scale)
    return Mesh([tuple(v[k] * s[k] + offset[k] for k in range(3)) for v in mesh.verts], list(mesh.faces))


def ellipsoid(subdivisions=3, axes=(1.3, 0.9, 0.7)):
    return transformed(icosphere(subdivisions), axes)


def bumpy_ellipsoid(scale=1.0):
    """An ellipsoid with a bump above its front: symmetric left/right (y), not front/back
    or up/down, so six anchors front, back, left, right, top and bump fix its orientation
    and a left/right swap is a real mirror image."""
    bump = _unit((0.6, 0.0, 0.8))
    verts = []
    for v in icosphere(3).verts:
        d = sum((v[k] - bump[k]) ** 2 for k in range(3))
        r = 1 + 0.45 * math.exp(-d / 0.12)
        verts.append((1.5 * r * v[0] * scale, 1.0 * r * v[1] * scale, 0.8 * r * v[2] * scale))
    return Mesh(verts, icosphere(3).faces)


def joined(*meshes):
    verts, faces = [], []
    for m in meshes:
        faces += [tuple(i + len(verts) for i in f) for f in m.faces]
        verts += list(m.verts)
    return Mesh(verts, faces)


def flipped(mesh, every=1):
    """Faces turned over: all (every=1) or every other one (every=2)."""
    return Mesh(list(mesh.verts), [(f[0], f[2], f[1]) if n % every == 0 else f for n, f in enumerate(mesh.faces)])


def soup(mesh):
    """Every face its own three vertices, as STL stores a mesh."""
    verts, faces = [], []
    for f in mesh.faces:
        faces.append((len(verts), len(verts) + 1, len(verts) + 2))
        verts += [mesh.verts[i] for i in f]
    return Mesh(verts, faces)


def half_unwelded(mesh):
    """Every vertex given twice; every other face uses the copies."""
    n = len(mesh.verts)
    faces = [tuple(i + n for i in f) if k % 2 else f for k, f in enumerate(mesh.faces)]
    return Mesh(list(mesh.verts) * 2, faces)


def with_hole(mesh, z=0.8):
    """The faces whose centroid lies above z removed (the vertices stay: unreferenced)."""
    keep = [f for f in mesh.faces if sum(mesh.verts[i][2] for i in f) / 3 <= z]
    return Mesh(list(mesh.verts), keep)


def touching_spheres():
    """Two spheres sharing one vertex (a non-manifold vertex), as one mesh."""
    a, b = icosphere(3), icosphere(3)
    ia = max(range(len(a.verts)), key=lambda i: a.verts[i][0])  # a's rightmost vertex
    ib = min(range(len(b.verts)), key=lambda i: b.verts[i][0])  # b's leftmost
    shift = tuple(a.verts[ia][k] - b.verts[ib][k] for k in range(3))
    b = transformed(b, 1.0, shift)
    n = len(a.verts)
    remap = {i: (ia if i == ib else n + i - (i > ib)) for i in range(len(b.verts))}
    verts = list(a.verts) + [v for i, v in enumerate(b.verts) if i != ib]
    return Mesh(verts, list(a.faces) + [tuple(remap[i] for i in f) for f in b.faces])


def cube(n=6, origin=(0.0, 0.0, 0.0)):
    """A closed unit cube, each side an n x n grid of squares (two triangles each), outward."""
    index, verts, faces = {}, [], []

    def vertex(p):
        key = tuple(round(x * n) for x in p)  # grid points: exact keys
        if key not in index:
            index[key] = len(verts)
            verts.append(tuple(origin[k] + p[k] for k in range(3)))
        return index[key]
    for axis in range(3):
        for side in (0, 1):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            for i in range(n):
                for j in range(n):
                    corners = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        p = [0.0, 0.0, 0.0]
                        p[axis], p[u], p[v] = float(side), (i + di) / n, (j + dj) / n
                        corners.append(vertex(p))
                    a, b, c, d = corners if side else corners[::-1]  # (u, v, axis) is right-handed
                    faces += [(a, b, c), (a, c, d)]
    return Mesh(verts, faces)


def two_cubes(n=6):
    """Two cubes sharing one edge (x = y = 1, 0 <= z <= 1): a closed mesh with a
    non-manifold edge (four faces on each of its n segments)."""
    a, b = cube(n), cube(n, (1.0, 1.0, 0.0))
    verts, faces = list(a.verts), list(a.faces)
    at = {v: i for i, v in enumerate(a.verts)}
    remap = {}
    for i, v in enumerate(b.verts):
        if v in at:  # the shared edge's points
            remap[i] = at[v]
        else:
            remap[i] = len(verts)
            verts.append(v)
    faces += [tuple(remap[i] for i in f) for f in b.faces]
    return Mesh(verts, faces)


def three_sheets():
    """Three square sheets meeting on one edge (the z axis): a non-manifold edge, no inside."""
    verts = [(0, 0, -1), (0, 0, 1)]
    faces = []
    for k in range(3):
        a = 2 * math.pi * k / 3
        verts += [(math.cos(a), math.sin(a), -1), (math.cos(a), math.sin(a), 1)]
        p, q = len(verts) - 2, len(verts) - 1
        faces += [(0, p, q), (0, q, 1)]
    return Mesh(verts, faces)


def equator(axes):
    """Four points on the equator (z = 0) of an ellipsoid with these semi-axes."""
    return [(n, (axes[0] * x, axes[1] * y, 0.0)) for n, (x, y) in
            [("east", (1, 0)), ("west", (-1, 0)), ("front", (0, 1)), ("back", (0, -1))]]


def nearest_vertex(mesh, direction):
    d = _unit(direction)
    return max(mesh.verts, key=lambda v: sum(v[k] * d[k] for k in range(3)))


def pp_text(points, raw=None):
    """A MeshLab picked-points file; points: (name, (x, y, z)); coordinates written as
    given (a string stays as it is, e.g. 'nan')."""
    if raw is not None:
        return raw
    body = "".join(f' <point x="{_num(p[0])}" y="{_num(p[1])}" z="{_num(p[2])}" active="1" name="{n}"/>\n'
                   for n, p in points)
    return "<!DOCTYPE PickedPoints>\n<PickedPoints>\n" + body + "</PickedPoints>\n"


def _num(x):
    return x if isinstance(x, str) else repr(float(x))


def swapped(points, a, b):
    """The same points with names a and b exchanged."""
    names = {a: b, b: a}
    return [(names.get(n, n), p) for n, p in points]


def read_pp(path):
    """(name, (x, y, z)) of a .pp file's points (samples' own, well-formed)."""
    import re
    out = []
    for attrs in re.findall(r"<point ([^>]*)/>", open(path).read()):
        a = dict(re.findall(r'(\w+)="([^"]*)"', attrs))
        out.append((a["name"], (float(a["x"]), float(a["y"]), float(a["z"]))))
    return out


# ---------------------------------------------------------------- the corpus


def cases(samples_dir):
    """All cases. samples_dir: the repository's samples/ (for the sample .pp files)."""
    import os
    sphere, ell = icosphere(3), ellipsoid(3)
    SPHERE, TORUS, SPOT, COW = Sample("sphere.ply"), Sample("torus.ply"), Sample("spot.ply"), Sample("cow.off")
    c = []

    def add(name, what, source, target, expect, **kw):
        c.append(Case(name, what, source, target, expect, **kw))

    # -- empty and broken meshes
    add("empty_source", "a source with no vertices and no faces", Mesh([], []), ell, Error(["has no faces"]))
    add("point_cloud_target", "a target that is a point cloud (vertices, no faces)", sphere, Mesh(ell.verts, []),
        Error(["has no faces"]))
    nan_v = Mesh([(NAN, v[1], v[2]) if i == 5 else v for i, v in enumerate(sphere.verts)], sphere.faces)
    add("nan_vertex_source", "a source vertex, used by faces, with a NaN coordinate", nan_v, ell,
        Error(["vertices with a NaN or infinite coordinate"]))
    inf_v = Mesh([(v[0], INF, v[2]) if i == 7 else v for i, v in enumerate(ell.verts)], ell.faces)
    add("inf_vertex_target", "a target vertex, used by faces, with an infinite coordinate", sphere, inf_v,
        Error(["vertices with a NaN or infinite coordinate"]))
    add("inf_vertex_source", "a source vertex, used by faces, with coordinate -Inf",
        Mesh([(-INF, v[1], v[2]) if i == 3 else v for i, v in enumerate(sphere.verts)], sphere.faces), ell,
        Error(["vertices with a NaN or infinite coordinate"]))
    add("unreferenced_nan_vertex", "an extra source vertex with NaN coordinates that no face uses",
        Mesh(sphere.verts + [(NAN, NAN, NAN)], sphere.faces), ell,
        Success(repairs=["source: 1 vertices that no face uses removed"], sane=True))
    add("stray_vertex_far", "an extra target vertex 1e6 away that no face uses (it would stretch the grid)",
        sphere, Mesh(ell.verts + [(1e6, 0, 0)], ell.faces),
        Success(repairs=["target: 1 vertices that no face uses removed"], sane=True))
    add("duplicate_vertices", "every source vertex given twice, every other face using the copies",
        half_unwelded(sphere), ell, Success(repairs=["vertices at the same place as another welded"], sane=True))
    add("triangle_soup", "an unwelded source (every face its own three vertices, as STL stores it)",
        soup(sphere), ell, Success(repairs=["vertices at the same place as another welded"], sane=True))
    add("triangle_soup_target", "an unwelded target torus (a triangle soup)", sphere,
        soup(_torus()), Success(repairs=["target: ", "vertices at the same place as another welded"]))
    rep = Mesh(sphere.verts, sphere.faces + [(0, 0, 1), (5, 9, 5), (2, 2, 2)])
    add("repeated_index_faces_source", "source faces that repeat a vertex index ('3 0 0 1')", rep, ell,
        Success(repairs=["source: 3 faces that repeat a vertex removed"], sane=True))
    add("repeated_index_faces_target", "target faces that repeat a vertex index ('3 0 0 1'), torus target", SPHERE,
        Mesh(_torus().verts, _torus().faces + [(0, 0, 1), (3, 4, 4)]),
        Success(repairs=["target: 2 faces that repeat a vertex removed"]))
    add("all_faces_repeat_vertex", "every source face repeats a vertex index",
        Mesh(sphere.verts, [(f[0], f[0], f[1]) for f in sphere.faces]), ell,
        Error(["every face of the source mesh repeats a vertex"]))
    za = Mesh(list(sphere.verts), list(sphere.faces))
    for f in sphere.faces[:6]:  # a vertex at the middle of an edge: a face of zero area on it
        a, b = za.verts[f[0]], za.verts[f[1]]
        za.verts.append(tuple((p + q) / 2 for p, q in zip(a, b)))
        za.faces.append((f[0], f[1], len(za.verts) - 1))
    add("zero_area_faces", "six extra source faces of zero area, each on a new vertex at the middle of an edge "
        "(collinear in double precision; rounded to float by meshlabserver's loader)", za, ell,
        Success(repairs=["faces of zero area removed"], sane=True))
    zx = Mesh(list(sphere.verts), list(sphere.faces))
    for f in sphere.faces[:6]:  # a second vertex at the place of f[0]: a face of exactly zero area
        zx.verts.append(zx.verts[f[0]])
        zx.faces.append((f[0], f[1], len(zx.verts) - 1))
    add("zero_area_faces_exact", "six extra source faces of exactly zero area (two corners at one place: welded, "
        "then each repeats a vertex)", zx, ell,
        Success(repairs=["source: 6 vertices at the same place as another welded",
                         "source: 6 faces made twice by the welding removed"], sane=True))
    line = Mesh([(0.1 * i, 0.05 * i, 0) for i in range(12)], [(i, i + 1, i + 2) for i in range(10)])
    add("all_collinear_target", "a target whose vertices all lie on one line (every face zero area)", sphere, line,
        Error(["every face of the target mesh has zero area"]))
    add("all_collinear_source", "a source whose vertices all lie on one line", line, ell,
        Error(["every face of the source mesh has zero area"]))
    add("no_extent", "a source whose vertices all lie at one point (distinct indices)",
        Mesh([(1, 1, 1)] * 4, [(0, 1, 2), (0, 2, 3), (0, 3, 1), (1, 3, 2)]), ell, Error(["has no extent"]))

    # -- topology and orientation
    add("nonmanifold_edge_three_sheets", "three open sheets meeting on one edge", three_sheets(), ell,
        Error(["encloses no volume at this grid"]))
    add("nonmanifold_edge_two_cubes", "two closed cubes sharing one edge, as one source mesh", two_cubes(), ell,
        Success())
    add("nonmanifold_vertex_bowtie", "a bowtie: two triangles sharing one vertex, nothing else",
        Mesh([(0, 0, 0), (1, 0.5, 0), (1, -0.5, 0), (-1, 0.5, 0.2), (-1, -0.5, 0.2)], [(0, 1, 2), (0, 3, 4)]), ell,
        Error(["encloses no volume at this grid"]))
    add("nonmanifold_vertex_touching_spheres", "two spheres sharing one vertex, as one source mesh",
        touching_spheres(), ell, Success())
    # A closed manifold with half its faces turned over: orientable, so it can be repaired (faces turned to agree
    # with their neighbours), or refused with a message that says it is the orientation.
    add("inconsistent_orientation", "every other source face turned over (a closed, orientable sphere)",
        flipped(sphere, 2), ell, Either(["orient"], sane=True))
    add("inside_out_source", "a source with every face turned inward", flipped(sphere), ell,
        Success(repairs=["source: ", "faces of parts that pointed inward turned outward"], sane=True))
    add("inside_out_target", "a torus target with every face turned inward", SPHERE, flipped(_torus()),
        Success(repairs=["target: ", "faces of parts that pointed inward turned outward"]))
    add("open_sphere_with_hole", "a source sphere with a hole (faces above z = 0.8 removed)", with_hole(sphere),
        ell, Success(sane=True))
    add("flat_square", "a flat source: one square of two triangles",
        Mesh([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], [(0, 1, 2), (0, 2, 3)]), ell,
        Error(["encloses no volume at this grid"]))
    add("single_triangle", "a source of one triangle", Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)]), ell,
        Error(["encloses no volume at this grid"]))
    add("sliver_tetrahedron", "a closed tetrahedron 1e-4 thick (thinner than a cell)",
        Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0.3, 0.3, 1e-4)], [(0, 2, 1), (0, 1, 3), (1, 2, 3), (2, 0, 3)]),
        ell, Error(["encloses no volume at this grid"]))
    add("self_intersecting", "two overlapping spheres as one source mesh (faces cross each other)",
        joined(icosphere(3, 1.0, (-0.5, 0, 0)), icosphere(3, 1.0, (0.5, 0, 0))), ell, Success(sane=True))
    # Centre-and-scale brings the target's diagonal (1002) to the source's: each sphere shrinks below a cell.
    add("far_apart_components", "a target of two unit spheres 1000 apart", sphere,
        joined(icosphere(3, 1.0, (-500, 0, 0)), icosphere(3, 1.0, (500, 0, 0))),
        Either(["encloses no volume at this grid"]))

    # -- scales and places
    add("scale_1e-6", "both meshes 1e-6 across", transformed(sphere, 1e-6), transformed(ell, 1e-6),
        Success(sane=True))
    add("scale_1e6", "both meshes 1e6 across", transformed(sphere, 1e6), transformed(ell, 1e6), Success(sane=True))
    add("offset_1e7", "both meshes (1000 across) 1e7 from the origin", transformed(sphere, 1000, (1e7, 1e7, 1e7)),
        transformed(ell, 1000, (1e7, -1e7, 1e7)), Success(sane=True))
    # meshlabserver 2020.09 loads coordinates as float, whose spacing at 1e7 is 1: the unit sphere falls onto a
    # few lattice points. A clean refusal or a sane map, whichever the loaded mesh allows.
    add("offset_1e7_unit_sphere", "a unit source sphere 1e7 from the origin (float rounding in meshlabserver)",
        transformed(sphere, 1.0, (1e7, 0, 0)), ell, Either([], sane=True))
    add("sizes_1_to_1000_align_none", "a target 1000 times the source's size, align none", sphere,
        transformed(ell, 1000), Either([], warnings=["the map reaches only"]), params=dict(align=0))
    add("sizes_1_to_1000_centre_and_scale", "a target 1000 times the source's size, align centre-and-scale",
        sphere, transformed(ell, 1000), Success(sane=True), params=dict(align=1))

    # -- parameters
    for name, params, texts in [
            ("steps_100000", dict(steps=100000), ["steps 100000 is out of range"]),
            ("steps_0", dict(steps=0), ["steps 0 is out of range"]),
            ("grid_2", dict(grid_resolution=2), ["grid_resolution 2 is out of range"]),
            ("alpha_inf", dict(alpha=INF), ["alpha ", "is out of range"]),
            ("alpha_nan", dict(alpha=NAN), ["alpha ", "is out of range"]),
            ("alpha_negative", dict(alpha=-1), ["alpha -1 is out of range"]),
            ("hole_radius_1e9", dict(hole_radius=1e9), ["hole_radius 1e+09 is out of range"]),
            ("hole_radius_inf", dict(hole_radius=INF), ["hole_radius ", "is out of range"]),
            ("hole_radius_0", dict(hole_radius=0), ["hole_radius 0 is out of range"]),
            ("grid_3000_memory", dict(grid_resolution=3000), ["lower grid_resolution"]),
            # about 10 GB at 180 B a node with RunBytes' margin (memory.h): more than the 6 GiB
            # address space of the run, less than the machine has
            ("grid_400_over_limit", dict(grid_resolution=400), ["lower grid_resolution"]),
            ("anchor_pairs_commas", dict(anchor_pairs=",,,"), ["holds no pair of vertex indices"])]:
        add(name, "parameter " + ", ".join(f"{k}={v}" for k, v in params.items()), SPHERE, TORUS, Error(texts),
            params=params)
    add("anchor_pairs_nan_vertex", "anchor_pairs naming a source vertex with NaN coordinates (no face uses it)",
        Mesh(sphere.verts + [(NAN, 0, 0)], sphere.faces), ell, Error(["has a NaN or infinite coordinate"]),
        params=dict(anchor_pairs=f"{len(sphere.verts)}:0, 0:5"))
    add("surgery_removes_everything", "sphere -> torus with hole_radius 16 cells at grid 12: the ball around "
        "the saddle takes in the whole source", SPHERE, TORUS, Error(["surgery removed every face of the source"]),
        params=dict(grid_resolution=12, hole_radius=16))

    # -- anchor files (.pp)
    on_sphere = [(n, nearest_vertex(sphere, d)) for n, d in
                 [("north", (0, 0, 1)), ("south", (0, 0, -1)), ("east", (1, 0, 0)), ("west", (-1, 0, 0)),
                  ("front", (0, 1, 0))]]
    on_ell = [(n, nearest_vertex(ell, d)) for n, d in
              [("north", (0, 0, 1)), ("south", (0, 0, -1)), ("east", (1, 0, 0)), ("west", (-1, 0, 0)),
               ("front", (0, 1, 0))]]
    good_s, good_t = pp_text(on_sphere), pp_text(on_ell)
    pp_cases = [
        ("pp_bad_xml", "a target .pp that is not well-formed XML",
         good_s, pp_text(None, raw="<!DOCTYPE PickedPoints>\n<PickedPoints>\n <point x=\"1\" y=\"0\" z=\"0\" "
                                   "name=\"east\"\n</PickedPoints>\n"), Error(["is not well-formed XML"])),
        ("pp_empty_file", "an empty source .pp file", pp_text(None, raw=""), good_t,
         Error(["source anchors: ", ("is empty, not a MeshLab picked-points file", "Premature end of document")])),
        ("pp_duplicate_names", "two points named 'east' in the source .pp",
         pp_text(on_sphere + [("east", on_sphere[4][1])]), good_t, Error(["two points are named 'east'"])),
        ("pp_nan_coordinate", "a target .pp point with x=\"nan\"",
         good_s, pp_text([(n, ("nan", p[1], p[2]) if n == "east" else p) for n, p in on_ell]),
         Either(["east", "NaN or infinite coordinate"])),
        ("pp_inf_coordinate", "a source .pp point with z=\"inf\"",
         pp_text([(n, (p[0], p[1], "inf") if n == "north" else p) for n, p in on_sphere]), good_t,
         Either(["north", "NaN or infinite coordinate"])),
        ("pp_coplanar_anchors", "four anchors on one plane (the equator, z = 0) on both meshes",
         pp_text(equator((1, 1, 1))), pp_text(equator((1.3, 0.9, 0.7))), Success(sane=True, log=["coplanar"])),
        ("pp_coincident_anchors", "two source anchors at the same point",
         pp_text(on_sphere[:4] + [("front", on_sphere[0][1])]), good_t, Error(["lie at the same point of the source"])),
        ("pp_name_one_side_only", "a name ('front') only in the source .pp",
         good_s, pp_text(on_ell[:4]), Error(["anchor names do not match", "'front' only in"])),
    ]
    for name, what, s, t, expect in pp_cases:
        add(name, what, sphere, ell, expect, anchors=dict(source=s, target=t))
    # Mirrored anchors, on shapes whose parts tell left from right once front, top and bump are fixed.
    src = bumpy_ellipsoid()
    points = [(n, nearest_vertex(src, d)) for n, d in
              [("front", (1, 0, 0)), ("back", (-1, 0, 0)), ("left", (0, 1, 0)), ("right", (0, -1, 0)),
               ("top", (0, 0, 1)), ("bump", (0.6, 0, 0.8))]]
    scaled = [(n, tuple(1.2 * x for x in p)) for n, p in points]
    add("pp_mirrored_bumpy", "six anchors on an ellipsoid with a bump, left and right swapped on the target",
        src, bumpy_ellipsoid(1.2), Success(warnings=["the anchors mirror each other"]),
        anchors=dict(source=pp_text(points), target=pp_text(swapped(scaled, "left", "right"))))
    add("pp_matching_bumpy", "the same six anchors, not swapped (the mirrored case's control)",
        src, bumpy_ellipsoid(1.2), Success(sane=True), anchors=dict(source=pp_text(points), target=pp_text(scaled)))
    cow = read_pp(os.path.join(samples_dir, "cow.pp"))
    mirrored_cow = swapped(swapped(cow, "hoof_front_left", "hoof_front_right"), "hoof_back_left", "hoof_back_right")
    add("pp_mirrored_spot_cow", "spot -> cow, the cow's left and right hooves swapped", SPOT, COW,
        Success(warnings=["the anchors mirror each other"]),
        anchors=dict(source=Sample("spot.pp"), target=pp_text(mirrored_cow)))
    # Names on the wrong places (neither a rigid motion nor a mirror image): the anchors cannot all reach
    # their partners. On spot -> cow the far ones are hooves, which the report counts as tips the grid cuts
    # short (no far-anchor warning), but coverage and on-surface rate say the map failed.
    add("pp_swapped_nose_tail_spot_cow", "spot -> cow, the cow's nose and tail swapped", SPOT, COW,
        Success(warnings=["the map reaches only"]),
        anchors=dict(source=Sample("spot.pp"), target=pp_text(swapped(cow, "nose", "tail"))))
    add("pp_swapped_front_top_bumpy", "six anchors on the bumpy ellipsoid, 'front' and 'top' swapped on the target",
        src, bumpy_ellipsoid(1.2), Success(warnings=["end more than 3 cells from their partners"]),
        anchors=dict(source=pp_text(points), target=pp_text(swapped(scaled, "front", "top"))))
    # 'right' swapped with 'bump': named right the map ends within 0.1 cells of every partner
    # (pp_matching_bumpy); swapped, 'bump' ends 5.6 cells from its partner.
    add("pp_swapped_bump_right_bumpy", "six anchors on the bumpy ellipsoid, 'bump' and 'right' swapped on the "
        "target", src, bumpy_ellipsoid(1.2), Success(warnings=["end more than 3 cells from their partners"]),
        anchors=dict(source=pp_text(points), target=pp_text(swapped(scaled, "bump", "right"))))
    return c


def _torus(R=1.0, r=0.4, nu=40, nv=20):
    verts, faces = [], []
    for i in range(nu):
        a = 2 * math.pi * i / nu
        for j in range(nv):
            b = 2 * math.pi * j / nv
            verts.append(((R + r * math.cos(b)) * math.cos(a), (R + r * math.cos(b)) * math.sin(a), r * math.sin(b)))
    for i in range(nu):
        for j in range(nv):
            p, q = i * nv + j, ((i + 1) % nu) * nv + j
            p1, q1 = i * nv + (j + 1) % nv, ((i + 1) % nu) * nv + (j + 1) % nv
            faces += [(p, q, q1), (p, q1, p1)]
    return Mesh(verts, faces)
