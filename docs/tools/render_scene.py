#!/usr/bin/env python3
"""The two halves of docs/tools/render.sh that are not driving MeshLab (standard library only).

  render_scene.py prepare WORK [options] MESH [options] MESH ...
      Lays the meshes out side by side and writes WORK/scene.mlp (a MeshLab project: one
      layer per mesh, each with the matrix that places it), WORK/m<i>/ (a link to mesh i
      and links to every texture image it names, so that MeshLab, which reads a mesh's
      texture names relative to the mesh file's folder, finds them), a private MeshLab
      settings file under WORK/home (plain background) and WORK/scene.env (the screen
      size to render at and what the picture must show). Options (see render.sh) apply
      to the meshes that follow them; --size, --textures and --supersample anywhere.
  render_scene.py check WORK
      Finds MeshLab's 3D view in WORK/shot.ppm (the screenshot) and checks that it shows
      the meshes as laid out: an orthographic view without the layer dialog, the info
      panel or the trackball, so that the drawing's size matches the layout's. Exit
      status 2 and the reason otherwise.
  render_scene.py finish WORK OUT.png
      Crops the screenshot to the drawing, shrinks it into the requested size with a
      border and writes OUT.png (ImageMagick's convert).

Layout: each mesh is turned (--rotate-y, then --rotate-x, in degrees, about its own
centre), scaled to height 1 (its extent along the screen's vertical axis), and placed
left to right, in the given order, with the same gap (GAP of the height) between
neighbours' bounding boxes, centred on the origin.

MeshLab 2020.09's view (src/meshlab/glarea.cpp): the trackball scales the scene so that
the diagonal of the union of the layers' transformed bounding boxes is 3 units, and the
orthographic camera shows 2 x 1.75 units vertically. So a mesh of height 1 is
3 / diagonal / 3.5 of the view's height tall; render.sh sizes the screen from that.
"""
import math
import os
import re
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "samples"))
import mesh_io  # noqa: E402  the samples' mesh reader

GAP = 0.25             # space between neighbouring meshes, in mesh heights
MARGIN = 0.05          # border around the meshes in the picture, share of its height
VIEW_HALF_HEIGHT = 1.75  # GLArea::viewRatio()
SCENE_DIAGONAL = 3.0     # GLArea::resetTrackBall(): scale 3 / diagonal
TOOLBAR_ROOM = 140     # menu bar, tool bars and status bar around the 3D view (px)
MIN_SCREEN_WIDTH = 2400  # tool bars in one row
MAX_SCREEN = 8000
BACKGROUND = (255, 255, 255)
SIZE_TOLERANCE = 0.04  # drawn size against the layout's (share)


class RenderError(Exception):
    pass


# ------------------------------------------------------------------ layout


def rotation(rx, ry):
    """Rotation matrix (rows): about the vertical axis y by ry degrees (the front, +z,
    towards +x for ry > 0), then about the horizontal axis x by rx degrees (the top, +y,
    towards the viewer at +z for rx > 0)."""
    a, b = math.radians(rx), math.radians(ry)
    ca, sa, cb, sb = math.cos(a), math.sin(a), math.cos(b), math.sin(b)
    rot_x = [[1, 0, 0], [0, ca, -sa], [0, sa, ca]]
    rot_y = [[cb, 0, sb], [0, 1, 0], [-sb, 0, cb]]
    return [[sum(rot_x[i][k] * rot_y[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def apply(m, p):
    return tuple(m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + (m[i][3] if len(m[i]) > 3 else 0) for i in range(3))


def bbox(points):
    return [min(p[k] for p in points) for k in range(3)], [max(p[k] for p in points) for k in range(3)]


def layout(meshes):
    """meshes: dicts with verts, rx, ry. Sets each one's 4x4 matrix (rows) and returns the
    strip's width and the diagonal of MeshLab's scene box (in mesh heights)."""
    x = 0.0
    for m in meshes:
        r = rotation(m["rx"], m["ry"])
        lo, hi = bbox([apply(r, p) for p in m["verts"]])
        ext = [hi[k] - lo[k] for k in range(3)]
        if max(ext) <= 0:
            raise RenderError(f"{m['path']}: all vertices coincide")
        height = ext[1] if ext[1] > 1e-3 * max(ext) else max(ext)
        s = 1.0 / height
        centre = [(lo[k] + hi[k]) / 2 for k in range(3)]
        m["width"] = ext[0] * s
        m["x"] = x + m["width"] / 2
        x += m["width"] + GAP
        m["_rs"] = [[s * r[i][j] for j in range(3)] for i in range(3)]
        m["_t"] = [-s * c for c in centre]
    strip = x - GAP
    for m in meshes:
        t = [m["_t"][0] + m["x"] - strip / 2, m["_t"][1], m["_t"][2]]
        m["matrix"] = [m["_rs"][i] + [t[i]] for i in range(3)] + [[0, 0, 0, 1]]
    # MeshDocument::bbox(): each layer's own box, its 8 corners through its matrix
    corners = []
    for m in meshes:
        lo, hi = bbox(m["verts"])
        for c in range(8):
            p = tuple(hi[k] if c >> k & 1 else lo[k] for k in range(3))
            corners.append(apply(m["matrix"], p))
    lo, hi = bbox(corners)
    return strip, math.dist(lo, hi)


# ------------------------------------------------------------------ prepare


USAGE = "render_scene.py prepare WORK [options] MESH ... | check WORK | finish WORK OUT.png"


def parse(args):
    opts = dict(size=(1600, 400), textures=[], supersample=2.0)
    rx = ry = 0.0
    meshes = []
    it = iter(args)
    for a in it:
        if a in ("--rotate-x", "--rotate-y", "--size", "--textures", "--supersample"):
            v = next(it, None)
            if v is None:
                raise RenderError(f"{a} needs a value")
            try:
                if a == "--rotate-x":
                    rx = float(v)
                elif a == "--rotate-y":
                    ry = float(v)
                elif a == "--supersample":
                    opts["supersample"] = float(v)
                    if not 0.5 <= opts["supersample"] <= 4:
                        raise ValueError
                elif a == "--size":
                    m = re.fullmatch(r"(\d+)x(\d+)", v)
                    if not m or min(int(m[1]), int(m[2])) < 32:
                        raise ValueError
                    opts["size"] = (int(m[1]), int(m[2]))
                else:
                    if not os.path.isdir(v):
                        raise RenderError(f"--textures {v}: no such folder")
                    opts["textures"].append(os.path.abspath(v))
            except ValueError:
                raise RenderError(f"bad value for {a}: '{v}'")
        elif a.startswith("--"):
            raise RenderError(f"unknown option '{a}'")
        else:
            meshes.append(dict(path=a, rx=rx, ry=ry))
    if not meshes:
        raise RenderError("no meshes given")
    return opts, meshes


def find_texture(name, mesh_dir, dirs):
    """Where MeshLab would find texture `name` of a mesh in mesh_dir, else in the --textures
    folders (by the name, then by its last part)."""
    if os.path.isabs(name):
        return name if os.path.isfile(name) else None
    for d in [mesh_dir] + dirs:
        for candidate in (os.path.join(d, name), os.path.join(d, os.path.basename(name))):
            if os.path.isfile(candidate):
                return os.path.abspath(candidate)
    return None


def settings_text():
    """MeshLab's QSettings file (VCG/MeshLab_64bit_fp.conf): global parameters are stored
    as XML strings under their names (MainWindow::loadMeshLabSettings)."""
    def colour(name, rgb):
        xml = (f'<!DOCTYPE MeshLabSettings>\n<Param r="{rgb[0]}" g="{rgb[1]}" b="{rgb[2]}" a="255" '
               f'type="RichColor" name="MeshLab::Appearance::{name}" description="" tooltip=""/>\n')
        return "MeshLab%3A%3AAppearance%3A%3A" + name + '="' + xml.replace('"', '\\"').replace("\n", "\\n") + '"\n'
    def integer(name, value):
        xml = (f'<!DOCTYPE MeshLabSettings>\n<Param value="{value}" type="RichInt" name="MeshLab::{name}" '
               'description="" tooltip=""/>\n')
        return "MeshLab%3A%3A" + name.replace("::", "%3A%3A") + '="' + xml.replace('"', '\\"').replace("\n", "\\n") + '"\n'
    # smooth shading (per-vertex normals) for every mesh, not only those of 50000 faces or more
    return ("[General]\n" + colour("backgroundBotColor", BACKGROUND) + colour("backgroundTopColor", BACKGROUND)
            + integer("System::minPolygonNumberPerSmoothRendering", 0)
            + "dontRemindMeToSendEmail=true\ndontRemindMeAboutUpgrade=true\n")


def xml_attr(s):
    return s.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")


def link_mesh(path, folder):
    """Puts mesh `path` into `folder` (a link; a PLY conversion for .obj, which Debian's
    MeshLab 2020.09 aborts on) and returns that file, the vertices and texture names."""
    mesh = mesh_io.read_mesh(path)
    if path.lower().endswith(".obj"):
        link = os.path.join(folder, os.path.splitext(os.path.basename(path))[0] + ".ply")
        mesh_io.write_ply(link, mesh)
    else:
        link = os.path.join(folder, os.path.basename(path))
        os.symlink(os.path.abspath(path), link)
    return link, mesh.verts, mesh.textures


def prepare(work, args):
    opts, meshes = parse(args)
    for i, m in enumerate(meshes):
        path = m["path"]
        if not os.path.isfile(path):
            raise RenderError(f"no such mesh file: {path}")
        folder = os.path.join(work, f"m{i}")
        os.makedirs(folder)
        try:
            m["file"], m["verts"], textures = link_mesh(path, folder)
        except StopIteration:
            raise RenderError(f"cannot read {path}: it ends before the counts in its header are met")
        except (ValueError, IndexError, KeyError, struct.error) as e:
            raise RenderError(f"cannot read {path}: {type(e).__name__} {e}".rstrip())
        if not m["verts"]:
            raise RenderError(f"{path} has no vertices")
        m["textures"] = textures
        for name in textures:
            found = find_texture(name, os.path.dirname(os.path.abspath(path)), opts["textures"])
            if found is None:
                looked = ", ".join([os.path.dirname(os.path.abspath(path))] + opts["textures"])
                raise RenderError(f"texture '{name}' of {path} not found (looked in {looked}; "
                                  "give its folder with --textures DIR)")
            if not os.path.isabs(name):  # MeshLab reads it relative to the mesh's folder
                target = os.path.normpath(os.path.join(folder, name))
                if not target.startswith(work + os.sep):
                    raise RenderError(f"texture name '{name}' of {path} leads too far up")
                os.makedirs(os.path.dirname(target), exist_ok=True)
                if not os.path.lexists(target):
                    os.symlink(found, target)
                elif os.path.realpath(target) != os.path.realpath(found):
                    raise RenderError(f"texture name '{name}' of {path} means two different files")
    strip, diagonal = layout(meshes)

    width, height = opts["size"]
    margin = round(MARGIN * height)
    mesh_px = min(height - 2 * margin, (width - 2 * margin) / strip)  # a mesh's height in the picture
    render_px = mesh_px * opts["supersample"]                         # ... and on the screen
    view_h = math.ceil(render_px * 2 * VIEW_HALF_HEIGHT * diagonal / SCENE_DIAGONAL)
    view_w = math.ceil(render_px * strip * 1.1 + 64)
    screen_w, screen_h = max(view_w, MIN_SCREEN_WIDTH), view_h + TOOLBAR_ROOM
    if max(screen_w, screen_h) > MAX_SCREEN:
        raise RenderError(f"the render would need a {screen_w}x{screen_h} screen: lower --size or --supersample")

    project = ['<!DOCTYPE MeshLabDocument>', '<MeshLabProject>', ' <MeshGroup>']
    for i, m in enumerate(meshes):
        # 16 numbers, row by row, each followed by a space: MeshLab splits the text on
        # spaces only (MeshDocumentFromXML), so a number must not touch a line break
        rows = "".join(f"{v:.9g} " for row in m["matrix"] for v in row)
        project += [f'  <MLMesh label="{xml_attr(os.path.basename(m["path"]))}" filename="{xml_attr(m["file"])}" visible="1">',
                    f"   <MLMatrix44>\n{rows}\n</MLMatrix44>", "  </MLMesh>"]
    project += [" </MeshGroup>", " <RasterGroup/>", "</MeshLabProject>", ""]
    with open(os.path.join(work, "scene.mlp"), "w") as f:
        f.write("\n".join(project))
    conf = os.path.join(work, "home", ".config", "VCG")
    os.makedirs(conf)
    with open(os.path.join(conf, "MeshLab_64bit_fp.conf"), "w") as f:
        f.write(settings_text())
    env = dict(SCREEN_W=screen_w, SCREEN_H=screen_h, MESHES=len(meshes), OUT_W=width, OUT_H=height,
               MARGIN=margin, STRIP=f"{strip:.9g}", DIAGONAL=f"{diagonal:.9g}")
    with open(os.path.join(work, "scene.env"), "w") as f:
        for k, v in env.items():
            f.write(f"{k}='{v}'\n")
    with open(os.path.join(work, "files.txt"), "w") as f:  # as MeshLab's log names them
        f.write("".join(m["file"] + "\n" for m in meshes))


# ------------------------------------------------------------------ finish


def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+(\d+)\s", data)
    if not m or m[3] != b"255":
        raise RenderError(f"{path}: not an 8-bit binary PPM")
    return int(m[1]), int(m[2]), data[m.end():]


def view_rows(width, height, pixels):
    """The rows of MeshLab's 3D view: the longest run of background in the screen's first
    column (menu, tool and status bars are grey, the view's edge is background)."""
    bg = bytes(BACKGROUND)
    best, start = (0, 0), None
    for y in range(height + 1):
        is_bg = y < height and pixels[3 * width * y:3 * width * y + 3] == bg
        if is_bg and start is None:
            start = y
        elif not is_bg and start is not None:
            best = max(best, (start, y), key=lambda r: r[1] - r[0])
            start = None
    return best


def load_env(work):
    env = {}
    for line in open(os.path.join(work, "scene.env")):
        k, v = line.rstrip("\n").split("=", 1)
        env[k] = v.strip("'")
    return env


def check(work):
    """Measures the drawing in WORK/shot.ppm against the layout; writes its box on the
    screen to WORK/drawing.txt, or raises RenderError saying what is wrong."""
    env = load_env(work)
    shot = os.path.join(work, "shot.ppm")
    width, height, pixels = read_ppm(shot)
    top, bottom = view_rows(width, height, pixels)
    if bottom - top < height / 2:
        raise RenderError("could not find MeshLab's 3D view in the screenshot")
    if height - bottom > 60:
        raise RenderError("MeshLab's info panel is shown below the 3D view")
    box = subprocess.run(["convert", shot, "-crop", f"{width}x{bottom - top}+0+{top}", "+repage",
                          "-format", "%@", "info:"], capture_output=True, text=True, check=True).stdout.strip()
    m = re.fullmatch(r"(\d+)x(\d+)\+(\d+)\+(\d+)", box)
    if not m:
        raise RenderError(f"could not measure the drawing ({box!r})")
    bw, bh, bx, by = (int(g) for g in m.groups())
    if bw >= width - 2 or bh >= bottom - top - 2:
        raise RenderError("the 3D view is not blank around the meshes (the layer dialog shown?)")
    # The layout in pixels: a mesh is 3 / diagonal / 3.5 of the view's height tall.
    mesh_px = (bottom - top) * SCENE_DIAGONAL / float(env["DIAGONAL"]) / (2 * VIEW_HALF_HEIGHT)
    want_w, want_h = mesh_px * float(env["STRIP"]), mesh_px
    if abs(bh - want_h) > SIZE_TOLERANCE * want_h + 3 or abs(bw - want_w) > SIZE_TOLERANCE * want_w + 3:
        raise RenderError(f"the drawing is {bw}x{bh} pixels, the layout expects {want_w:.0f}x{want_h:.0f}: not the "
                          "expected orthographic view (the trackball shown? a mesh missing?)")
    with open(os.path.join(work, "drawing.txt"), "w") as f:
        f.write(f"{bw}x{bh}+{bx}+{by + top}\n")


def finish(work, out):
    """Crops WORK/shot.ppm to the drawing that check() measured and writes OUT (PNG)."""
    env = load_env(work)
    drawing = open(os.path.join(work, "drawing.txt")).read().strip()
    ow, oh, margin = int(env["OUT_W"]), int(env["OUT_H"]), int(env["MARGIN"])
    subprocess.run(["convert", os.path.join(work, "shot.ppm"), "-crop", drawing, "+repage",
                    "-resize", f"{ow - 2 * margin}x{oh - 2 * margin}", "-background", "rgb(%d,%d,%d)" % BACKGROUND,
                    "-gravity", "center", "-extent", f"{ow}x{oh}", "-strip", "-depth", "8",
                    "-define", "png:compression-level=9", "PNG24:" + out], check=True)


def main(argv):
    try:
        if len(argv) >= 2 and argv[0] == "prepare":
            prepare(os.path.abspath(argv[1]), argv[2:])
        elif len(argv) == 2 and argv[0] == "check":
            check(os.path.abspath(argv[1]))
        elif len(argv) == 3 and argv[0] == "finish":
            finish(os.path.abspath(argv[1]), argv[2])
        else:
            raise RenderError("usage: " + USAGE)
    except RenderError as e:
        print(f"render.sh: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
