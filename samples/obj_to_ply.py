#!/usr/bin/env python3
"""Converts a Wavefront .obj to an ASCII .ply that MeshLab 2020.09 reads.

Debian 12's meshlab 2020.09 aborts on every .obj file (an assertion in vcglib's
import_obj.h, line 640, fails while loading), so the samples and map_meshes.sh hand
MeshLab PLY files. Keeps the vertex order (vertex i of the .obj is vertex i of the .ply),
splits polygons into triangle fans, and carries texture coordinates per wedge ("vt"
indices of the faces), and the first map_Kd texture of the .mtl when there is one.

Usage: obj_to_ply.py IN.obj OUT.ply
"""
import os
import sys


def read_obj(path):
    verts, uvs, faces, wedges, mtllibs = [], [], [], [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                verts.append(tuple(float(x) for x in t[1:4]))
            elif t[0] == "vt":
                uvs.append((float(t[1]), float(t[2]) if len(t) > 2 else 0.0))
            elif t[0] == "mtllib":
                mtllibs.append(line.split(None, 1)[1].strip())
            elif t[0] == "f":
                idx, tex = [], []
                for corner in t[1:]:
                    parts = corner.split("/")
                    v = int(parts[0])
                    idx.append(v - 1 if v > 0 else len(verts) + v)
                    if len(parts) > 1 and parts[1]:
                        w = int(parts[1])
                        tex.append(w - 1 if w > 0 else len(uvs) + w)
                for k in range(1, len(idx) - 1):
                    faces.append((idx[0], idx[k], idx[k + 1]))
                    wedges.append((tex[0], tex[k], tex[k + 1]) if len(tex) == len(idx) else None)
    texture = None
    for lib in mtllibs:
        mtl = os.path.join(os.path.dirname(path), lib)
        if os.path.isfile(mtl):
            for line in open(mtl):
                t = line.split(None, 1)
                if t and t[0] == "map_Kd" and len(t) > 1:
                    texture = t[1].strip()
                    break
        if texture:
            break
    return verts, uvs, faces, wedges, texture


def write_ply(path, verts, uvs, faces, wedges, texture):
    with_uv = bool(uvs) and all(w is not None for w in wedges)
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\n")
        if texture:
            f.write("comment TextureFile %s\n" % texture)
        f.write("element vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(verts))
        f.write("element face %d\nproperty list uchar int vertex_indices\n" % len(faces))
        if with_uv:
            f.write("property list uchar float texcoord\n")
        f.write("end_header\n")
        for v in verts:
            f.write("%.9g %.9g %.9g\n" % v)
        for face, w in zip(faces, wedges):
            line = "3 %d %d %d" % face
            if with_uv:
                line += " 6 " + " ".join("%.9g %.9g" % uvs[i] for i in w)
            f.write(line + "\n")


def convert(src, dst):
    write_ply(dst, *read_obj(src))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    convert(sys.argv[1], sys.argv[2])
