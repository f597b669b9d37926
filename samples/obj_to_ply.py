#!/usr/bin/env python3
"""Converts a Wavefront .obj to an ASCII .ply that MeshLab 2020.09 reads.

Debian 12's meshlab 2020.09 aborts on every .obj file (an assertion in vcglib's
import_obj.h, line 640, fails while loading), so the samples and map_meshes.sh hand
MeshLab PLY files. Keeps the vertex order (vertex i of the .obj is vertex i of the .ply),
splits polygons into triangle fans, and carries texture coordinates per wedge ("vt"
indices of the faces), and the first map_Kd texture of the .mtl when there is one
(mesh_io.py reads and writes).

Usage: obj_to_ply.py IN.obj OUT.ply
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesh_io  # noqa: E402


def convert(src, dst):
    mesh_io.write_ply(dst, mesh_io.read_mesh(src))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    convert(sys.argv[1], sys.argv[2])
