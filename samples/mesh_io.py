"""Mesh files in and out, standard library only: the one reader of the samples, the
MeshLab tests and the documentation tools.

read_mesh(path) -> Mesh, from PLY (ascii, binary little or big endian), OFF (also COFF,
NOFF, CNOFF) or OBJ, with
  .verts       [(x, y, z)], in file order
  .faces       [(i, j, k)], polygons split into triangle fans
  .vertex      PLY: every per-vertex property by name; .face_props: every per-face one
  .comments    PLY header comments; .textures: texture file names (PLY TextureFile
               comments, OBJ's first map_Kd of its .mtl)
  .uvs, .wedges  OBJ: texture coordinates ("vt") and, per triangle, its three indices into
               them (None for a face without them)
write_ply(path, mesh) writes positions, triangles, per-wedge texture coordinates (OBJ's)
and the first texture name as an ASCII PLY that MeshLab 2020.09 reads.
"""
import os
import struct

_PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


class Mesh:
    def __init__(self):
        self.verts, self.faces = [], []
        self.vertex, self.face_props = {}, {}
        self.comments, self.textures = [], []
        self.uvs, self.wedges = [], []


def read_mesh(path):
    lower = path.lower()
    if lower.endswith(".ply"):
        return _read_ply(path)
    if lower.endswith(".off"):
        return _read_off(path)
    if lower.endswith(".obj"):
        return _read_obj(path)
    raise ValueError(f"{path}: unknown mesh format (.ply, .off and .obj are read)")


def _fan(idx):
    return [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]


def _read_off(path):
    m = Mesh()
    words = []
    for line in open(path, encoding="latin-1"):
        words += line.split("#", 1)[0].split()
    if not words or not words[0].endswith("OFF"):
        raise ValueError(f"{path} is not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    per = 3 + (3 if "N" in words[0] else 0) + (4 if "C" in words[0] else 0)  # positions come first
    m.verts = [tuple(float(x) for x in words[4 + per * i:4 + per * i + 3]) for i in range(nv)]
    i = 4 + per * nv
    for _ in range(nf):
        n = int(words[i])
        m.faces += _fan([int(x) for x in words[i + 1:i + 1 + n]])
        i += 1 + n
    return m


def _read_obj(path):
    m = Mesh()
    mtllibs = []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                m.verts.append(tuple(float(x) for x in t[1:4]))
            elif t[0] == "vt":
                m.uvs.append((float(t[1]), float(t[2]) if len(t) > 2 else 0.0))
            elif t[0] == "mtllib":
                mtllibs.append(line.split(None, 1)[1].strip())
            elif t[0] == "f":
                idx, tex = [], []
                for corner in t[1:]:
                    parts = corner.split("/")
                    v = int(parts[0])
                    idx.append(v - 1 if v > 0 else len(m.verts) + v)
                    if len(parts) > 1 and parts[1]:
                        w = int(parts[1])
                        tex.append(w - 1 if w > 0 else len(m.uvs) + w)
                m.faces += _fan(idx)
                m.wedges += _fan(tex) if len(tex) == len(idx) else [None] * (len(idx) - 2)
    for lib in mtllibs:
        mtl = os.path.join(os.path.dirname(path), lib)
        if os.path.isfile(mtl):
            for line in open(mtl):
                t = line.split(None, 1)
                if t and t[0] == "map_Kd" and len(t) > 1:
                    m.textures.append(t[1].strip())
                    return m
    return m


def _read_ply(path):
    m = Mesh()
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise ValueError(f"{path} is not a PLY file")
        fmt, elements = None, []
        while True:
            line = f.readline()
            if not line:
                raise ValueError(f"{path}: PLY header without end_header")
            text = line.decode("latin-1").strip()
            t = text.split()
            if not t:
                continue
            if t[0] == "format":
                fmt = t[1]
            elif t[0] in ("comment", "obj_info"):
                m.comments.append(" ".join(t[1:]))
                if len(t) > 2 and t[1].lower() == "texturefile":
                    m.textures.append(text.split(None, 2)[2].strip())
            elif t[0] == "element":
                elements.append((t[1], int(t[2]), []))
            elif t[0] == "property":
                if t[1] == "list":
                    elements[-1][2].append((t[4], _PLY_TYPES[t[2]], _PLY_TYPES[t[3]]))
                else:
                    elements[-1][2].append((t[2], None, _PLY_TYPES[t[1]]))
            elif t[0] == "end_header":
                break
        if fmt == "ascii":
            words = f.read().split()
            pos = 0

            def scalar(code):
                nonlocal pos
                pos += 1
                return float(words[pos - 1]) if code in "fd" else int(words[pos - 1])
        elif fmt in ("binary_little_endian", "binary_big_endian"):
            data = f.read()
            order = "<" if fmt == "binary_little_endian" else ">"
            pos = 0

            def scalar(code):
                nonlocal pos
                (value,) = struct.unpack_from(order + code, data, pos)
                pos += struct.calcsize(code)
                return value
        else:
            raise ValueError(f"{path}: unknown PLY format {fmt}")
        for name, count, props in elements:
            columns = {p[0]: [] for p in props}
            for _ in range(count):
                for pname, count_code, value_code in props:
                    if count_code:
                        n = scalar(count_code)
                        columns[pname].append([scalar(value_code) for _ in range(n)])
                    else:
                        columns[pname].append(scalar(value_code))
            if name == "vertex":
                m.vertex = columns
                m.verts = list(zip(columns["x"], columns["y"], columns["z"]))
            elif name == "face":
                m.face_props = columns
                key = "vertex_indices" if "vertex_indices" in columns else "vertex_index"
                for idx in columns[key]:
                    m.faces += _fan(idx)
    return m


def write_ply(path, m):
    with_uv = bool(m.uvs) and len(m.wedges) == len(m.faces) and all(w is not None for w in m.wedges)
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\n")
        if m.textures:
            f.write("comment TextureFile %s\n" % m.textures[0])
        f.write("element vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(m.verts))
        f.write("element face %d\nproperty list uchar int vertex_indices\n" % len(m.faces))
        if with_uv:
            f.write("property list uchar float texcoord\n")
        f.write("end_header\n")
        for v in m.verts:
            f.write("%.9g %.9g %.9g\n" % tuple(v))
        for i, face in enumerate(m.faces):
            line = "3 %d %d %d" % tuple(face)
            if with_uv:
                line += " 6 " + " ".join("%.9g %.9g" % m.uvs[k] for k in m.wedges[i])
            f.write(line + "\n")
