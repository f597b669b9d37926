#!/usr/bin/env python3
"""Writes the sample meshes (ASCII PLY) beside this script.

Analytic ones:

  sphere.ply  unit icosphere (icosahedron subdivided 4 times, 2562 vertices), centre 0
  torus.ply   torus around z, ring radius 1, tube radius 0.4, 64 x 32 quads split in
              triangles (2048 vertices); per-wedge texture coordinates (ring, tube angle
              / 2 pi, seamless) and the texture torus_checker.png (made with ImageMagick
              when it is there)

Same shapes as tests/support/meshes.cpp (MakeSphere, MakeTorus).

From the project's shared data (../shared/data/meshes):
  spot.ply, rocker-arm.ply  converted from the .obj files (obj_to_ply.py: Debian's
                            MeshLab 2020.09 aborts on .obj), same vertex order, spot
                            with its per-wedge texture coordinates and the texture
                            spot_checker.png (made with ImageMagick when it is there:
                            12 x 12 cells, hue by column, darker towards the bottom,
                            strong and pale alternating, so that orientation shows)
  cow.off                   copied as it is

Usage: python3 samples/make_sample_meshes.py
"""
import colorsys
import math
import os
import shutil
import subprocess

import mesh_io
import obj_to_ply

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.join(HERE, "..", "..", "shared", "data", "meshes")


def icosphere(subdivisions):
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [normalize(v) for v in verts]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(verts)
                verts.append(normalize(tuple((verts[a][k] + verts[b][k]) / 2 for k in range(3))))
            return middle[key]

        new = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new
    return verts, faces


def normalize(v):
    n = math.sqrt(sum(x * x for x in v))
    return tuple(x / n for x in v)


def torus(R, r, ring, tube):
    """Vertices, texture coordinates, faces and each face's three indices into them (as
    mesh_io.Mesh holds them)."""
    verts, uvs, faces, wedges = [], [], [], []
    for i in range(ring):
        for j in range(tube):
            u, v = 2 * math.pi * i / ring, 2 * math.pi * j / tube
            verts.append(((R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u), r * math.sin(v)))
    for i in range(ring + 1):  # the seam's coordinates twice (0 and 1): seamless per-wedge UVs
        for j in range(tube + 1):
            uvs.append((i / ring, j / tube))
    for i in range(ring):
        for j in range(tube):
            a, b = i * tube + j, ((i + 1) % ring) * tube + j
            c, d = ((i + 1) % ring) * tube + (j + 1) % tube, i * tube + (j + 1) % tube
            ta, tb, tc, td = i * (tube + 1) + j, (i + 1) * (tube + 1) + j, (i + 1) * (tube + 1) + j + 1, i * (tube + 1) + j + 1
            faces += [(a, b, c), (a, c, d)]
            wedges += [(ta, tb, tc), (ta, tc, td)]
    return verts, uvs, faces, wedges


def spot_checker(path, cells=12, size=768):
    """cells x cells squares: the hue turns with the column (u), the colour gets darker
    towards the image's bottom (v), and neighbouring cells alternate strong and pale."""
    px = size // cells
    cmd = ["convert", "-size", f"{size}x{size}", "xc:white"]
    for col in range(cells):
        for row in range(cells):  # row 0 at the image's top
            strong = (col + row) % 2 == 0
            t = row / (cells - 1)
            light = (0.64 - 0.26 * t) if strong else (0.88 - 0.14 * t)
            r, g, b = colorsys.hls_to_rgb(col / cells, light, 0.85 if strong else 0.7)
            colour = "#%02x%02x%02x" % (round(255 * r), round(255 * g), round(255 * b))
            cmd += ["-fill", colour, "-draw", f"rectangle {px * col},{px * row} {px * col + px - 1},{px * row + px - 1}"]
    subprocess.run(cmd + ["-strip", path], check=True)


def main():
    sphere = mesh_io.Mesh()
    sphere.verts, sphere.faces = icosphere(4)
    mesh_io.write_ply(os.path.join(HERE, "sphere.ply"), sphere)
    texture = "torus_checker.png"
    if shutil.which("convert") and not os.path.exists(os.path.join(HERE, texture)):
        # 8 x 8 blue and white squares
        subprocess.run(["convert", "-size", "64x64", "xc:white", "-fill", "#3070c0", "-draw", "rectangle 0,0 31,31",
                        "-draw", "rectangle 32,32 63,63", "-write", "mpr:tile", "+delete", "-size", "256x256",
                        "tile:mpr:tile", "-strip", os.path.join(HERE, texture)], check=True)
    ring = mesh_io.Mesh()
    ring.verts, ring.uvs, ring.faces, ring.wedges = torus(1.0, 0.4, 64, 32)
    ring.textures = [texture]
    mesh_io.write_ply(os.path.join(HERE, "torus.ply"), ring)
    if os.path.isdir(SHARED):
        spot_texture = "spot_checker.png"
        if shutil.which("convert") and not os.path.exists(os.path.join(HERE, spot_texture)):
            spot_checker(os.path.join(HERE, spot_texture))
        spot = mesh_io.read_mesh(os.path.join(SHARED, "spot.obj"))
        spot.textures = [spot_texture]
        mesh_io.write_ply(os.path.join(HERE, "spot.ply"), spot)
        obj_to_ply.convert(os.path.join(SHARED, "rocker-arm.obj"), os.path.join(HERE, "rocker-arm.ply"))
        shutil.copyfile(os.path.join(SHARED, "cow.off"), os.path.join(HERE, "cow.off"))
    else:
        print("no %s: spot, rocker-arm and cow left as they are" % SHARED)


if __name__ == "__main__":
    main()
