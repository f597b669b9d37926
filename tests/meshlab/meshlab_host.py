"""What the MeshLab 2020.09 tests (test_meshlab.py), the pymeshlab tests and the bad-input
corpus share: paths, the sample runs and their expectations, complete .mlx scripts from the
core's parameter table, running meshlabserver and reading its log, the bad inputs, and the
GUI sessions of every MeshLab version (gui_session.sh) with what they measure.
"""
import glob
import hashlib
import os
import re
import subprocess

import meshes

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SAMPLES = os.path.join(ROOT, "samples")
OUT = os.path.join(ROOT, "out", "meshlab")
SHOTS = os.path.join(ROOT, "out", "screenshots")
PLUGIN = "/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_eulermap.so"
BUILT = os.path.join(ROOT, "build", "filter_eulermap", "libfilter_eulermap.so")
BENCH = os.path.join(ROOT, "build", "tests", "bench", "eulermap_bench")
FILTER = "Eulerian Surface Map"
FAILED_PREFIX = FILTER + " failed: "
CRASH_CODES = {134, 136, 139, -6, -8, -11}  # abort, FPE, segfault (as exit codes or signals)

# (name, source, target, expected cut topology, extra checks)
SAMPLE_RUNS = [
    ("sphere_to_torus", "sphere.ply", "torus.ply",
     dict(components=1, loops=2, chi=0, texture="torus_checker.png", mapped_texture=None)),
    ("torus_to_sphere", "torus.ply", "sphere.ply", dict(components=1, loops=2, chi=0, filled=True)),
    # the cow has no texture: the cut keeps spot's own, the mapped layer shows it on the cow (forward)
    ("spot_to_cow", "spot.ply", "cow.off",
     dict(components=1, loops=0, chi=2, anchors="spot.pp", texture="spot_checker.png",
          mapped_texture="spot_checker.png", note="note: transfer_texture: the target 'cow.off' has no texture coordinates")),
    ("cow_to_spot", "cow.off", "spot.ply",
     dict(components=1, loops=0, chi=2, anchors="cow.pp", texture="spot_checker.png", mapped_texture=None,
          log="texture: pulled per wedge from the target's per-wedge coordinates")),
    ("rocker-arm_to_sphere", "rocker-arm.ply", "sphere.ply", dict(components=1, loops=2, chi=0)),
]


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def sample_checksums():
    return {p: sha256(p) for p in sorted(glob.glob(os.path.join(SAMPLES, "*"))) if os.path.isfile(p)}


def mlx_text(**values):
    """A complete script for the filter, from the core's parameter table (core/parameters.h,
    through `eulermap_bench mlx`); `values` override the defaults (source_mesh 0, target_mesh 1)."""
    text = lambda x: ("true" if x else "false") if isinstance(x, bool) else str(x)  # noqa: E731
    p = subprocess.run([BENCH, "mlx"] + [f"{k}={text(v)}" for k, v in values.items()],
                       capture_output=True, text=True, check=True)
    return p.stdout


def plugin_parameter_names():
    """The filter's parameter names, in order, from the core's table."""
    return re.findall(r'<Param [^>]*name="(\w+)"', mlx_text())


def meshlabserver(outdir, inputs, script, saves=(), timeout=1800):
    """Runs meshlabserver under xvfb-run; `saves` are (file, layer) pairs, written with
    vertex quality and wedge texture coordinates. Returns (exit status, log text)."""
    os.makedirs(outdir, exist_ok=True)
    log = os.path.join(outdir, "meshlabserver.log")
    if os.path.exists(log):
        os.remove(log)
    cmd = ["xvfb-run", "-a", "meshlabserver", "-l", log, "-i"] + list(inputs) + ["-s", script]
    for path, layer in saves:
        cmd += ["-o", path, "-l", str(layer), "-m", "vq", "wt"]
    with open(os.path.join(outdir, "meshlabserver.out"), "w") as out:
        p = subprocess.run(cmd, stdout=out, stderr=subprocess.STDOUT, timeout=timeout)
    text = open(log, errors="replace").read() if os.path.exists(log) else ""
    return p.returncode, text


# ---------------------------------------------------------------- the tests


def build_id(path):
    """The ELF build ID (cmake --install rewrites the RPATH, so the bytes differ)."""
    out = subprocess.run(["readelf", "-n", path], capture_output=True, text=True).stdout
    m = re.search(r"Build ID: (\w+)", out)
    return m.group(1) if m else sha256(path)


def filter_log(log):
    """The filter's lines in meshlabserver's log."""
    lines, on = [], False
    for line in log.splitlines():
        if line.endswith("filter: " + FILTER):
            on = True
            continue
        if on and re.match(r"(Mesh .* saved as|Output mesh|Problem with filter|Failed to apply|Invalid layer)", line):
            break
        if on:
            lines.append(line)
    return lines


def failure_message(log):
    for line in log.splitlines():
        if line.startswith(FAILED_PREFIX):
            return line[len(FAILED_PREFIX):]
    return "(no message from the filter)" + log[-300:]


def quick_map(source, target, outdir):
    """samples/map_meshes.sh on two samples at grid 24, 8 steps; fails the test if it fails."""
    p = subprocess.run([os.path.join(SAMPLES, "map_meshes.sh"), os.path.join(SAMPLES, source),
                        os.path.join(SAMPLES, target), outdir, "--grid", "24", "--steps", "8"],
                       capture_output=True, text=True, timeout=600)
    check(p.returncode == 0, f"map_meshes.sh failed ({p.returncode}): {p.stderr[-500:]}")


def read_png(path):
    """(width, height, RGB bytes) of a picture, through ImageMagick's convert."""
    data = subprocess.run(["convert", path, "-depth", "8", "ppm:-"], capture_output=True, check=True).stdout
    m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)
    check(m, f"convert did not turn {path} into an 8-bit PPM")
    return int(m.group(1)), int(m.group(2)), data[m.end():]


# Bad inputs: (name, inputs, script values, expected message part). Small grids, so a
# wrongly accepted input still ends quickly.
def write_file(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def _pp(path, points):
    body = "".join(f' <point x="{x}" y="{y}" z="{z}" active="1" name="{n}"/>\n' for n, (x, y, z) in points)
    return write_file(path, "<!DOCTYPE PickedPoints>\n<PickedPoints>\n" + body + "</PickedPoints>\n")


def bad_inputs(tmp):
    sphere, torus = os.path.join(SAMPLES, "sphere.ply"), os.path.join(SAMPLES, "torus.ply")
    points_only = write_file(os.path.join(tmp, "points.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 0\nproperty list uchar int vertex_indices\n"
                         "end_header\n0 0 0\n1 0 0\n0 1 0\n")
    on_sphere = [("north", (0, 0, 1)), ("south", (0, 0, -1)), ("east", (1, 0, 0))]
    on_torus = [("north", (0, 0, 0.4)), ("south", (0, 0, -0.4)), ("east", (1.4, 0, 0))]
    a = _pp(os.path.join(tmp, "a.pp"), on_sphere)
    b_renamed = _pp(os.path.join(tmp, "b_renamed.pp"), on_torus[:2] + [("west", (-1.4, 0, 0))])
    b_far = _pp(os.path.join(tmp, "b_far.pp"), on_torus[:2] + [("east", (5, 5, 5))])
    small = dict(grid_resolution=16, steps=2)
    return [
        ("no_target", [sphere], dict(small, target_mesh=0), "no target mesh"),
        ("target_is_source", [sphere, torus], dict(small, target_mesh=0), "target_mesh is the source mesh itself"),
        ("empty_source", [points_only, torus], small, "has no faces"),
        ("empty_target", [sphere, points_only], small, "has no faces"),
        ("anchor_names_differ", [sphere, torus], dict(small, source_anchors=a, target_anchors=b_renamed),
         "anchor names do not match"),
        ("anchor_far_from_mesh", [sphere, torus], dict(small, source_anchors=a, target_anchors=b_far),
         "anchor 'east' in b_far.pp lies"),
        ("anchor_file_missing", [sphere, torus], dict(small, source_anchors=os.path.join(tmp, "none.pp"),
                                                      target_anchors=b_far), "cannot open"),
        ("anchor_pairs_malformed", [sphere, torus], dict(small, anchor_pairs="12-305"), "is not a pair of vertex indices"),
        ("anchor_pairs_out_of_range", [sphere, torus], dict(small, anchor_pairs="0:99999"), "is out of range"),
        ("anchors_given_twice", [sphere, torus], dict(small, anchor_pairs="0:0", source_anchors=a), "anchors given twice"),
        ("grid_out_of_range", [sphere, torus], dict(small, grid_resolution=2), "grid_resolution 2 is out of range"),
        ("grid_too_large_for_memory", [sphere, torus], dict(small, grid_resolution=2000), "lower grid_resolution"),
    ]


GUI_SESSION = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gui_session.sh")


def gui_session(samples, shots, outdir, layout="2020.09", meshlab=None, grid=24, steps=8, export=None, drive=True):
    """One MeshLab GUI session (gui_session.sh) under xvfb-run on a 1280x960 screen: MeshLab
    (the command `meshlab`, e.g. one that starts it inside a Debian root) opens the torus and
    the sphere of `samples` (the folder as MeshLab sees it); with `drive`, xdotool applies
    the filter from the Filters menu at `grid` and `steps` as the `layout` of that MeshLab
    version places its menus and dialogs, and with `export` (a path as MeshLab sees it) the
    cut layer is saved from File > Export Mesh As. Screenshots go to `shots`, MeshLab's
    output to outdir/meshlab.out. Returns (the session's CompletedProcess, MeshLab's output)."""
    if drive:
        check_dialog_rows(layout)
    os.makedirs(shots, exist_ok=True)
    for old in glob.glob(os.path.join(shots, "meshlab_*.png")):
        os.remove(old)
    os.makedirs(outdir, exist_ok=True)
    env = dict(os.environ, GRID=str(grid), STEPS=str(steps))
    if meshlab:
        env["MESHLAB"] = meshlab
    if export:
        env["EXPORT"] = export
    p = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x960x24", "bash", GUI_SESSION, samples, shots, outdir,
                        "1" if drive else "0", layout], capture_output=True, text=True, timeout=600, env=env)
    out = os.path.join(outdir, "meshlab.out")
    return p, (open(out, errors="replace").read() if os.path.exists(out) else "")


def check_dialog_rows(layout):
    """The clicks of gui_layout_<layout>.sh below the dialog's rows (APPLY, CLOSE) hold for the
    number of filter parameters they were measured with (DIALOG_ROWS): a parameter added to or
    removed from the filter's dialog (core/parameters.h) moves them by a height that depends on
    the MeshLab version (2020.09 caps the dialog's height and hides its last rows behind the
    buttons), so it is a failure that says what to measure again, not a click in the wrong place."""
    measured, rows = int(layout_value(layout, "DIALOG_ROWS")), len(plugin_parameter_names())
    check(rows == measured,
          f"the filter's dialog has {rows} parameter rows (core/parameters.h) and gui_layout_{layout}.sh's clicks "
          f"were measured with {measured}: measure APPLY and CLOSE again on meshlab_3_parameters.png "
          f"(the dialog's screenshot) and set DIALOG_ROWS={rows}")


def layout_value(layout, name):
    """A value of gui_layout_<layout>.sh (e.g. VIEW_BOX), as the shell reads it."""
    path = os.path.join(os.path.dirname(GUI_SESSION), f"gui_layout_{layout}.sh")
    return subprocess.run(["bash", "-c", f'. "$0"; echo "${{{name}}}"', path], capture_output=True, text=True,
                          check=True).stdout.strip()


def checker_shares(png, box):
    """(blue, white) shares of the pixels of `png` inside box (x0, y0, x1, y1): the torus's
    checker (#3070c0 and white, lit or in shade) as MeshLab draws it on a blue-grey background
    (where G = R, so not counted as the checker's blue)."""
    width, height, rgb = read_png(png)
    x0, y0, x1, y1 = box
    px = [rgb[3 * (y * width + x):3 * (y * width + x) + 3] for x in range(x0, x1, 2) for y in range(y0, y1, 2)]
    blue = sum(c[2] > c[0] + 60 and c[1] > c[0] + 30 for c in px) / len(px)
    white = sum(min(c) > 150 and max(c) - min(c) < 30 for c in px) / len(px)
    return blue, white


def measure_cut(cut_ply, target_ply):
    """A cut layer saved from the GUI with its TargetPosition: (mesh, (components, boundary
    loops, Euler characteristic), share of the images within 0.5% of the target's diagonal
    from the target). MeshLab 2020.09 writes TargetPosition as three properties
    TargetPosition_x/_y/_z, 2022.02 and 2025.07 as one list property."""
    c, target = meshes.read_mesh(cut_ply), meshes.read_mesh(target_ply)
    if "TargetPosition" in c.vertex:
        images = [tuple(x) for x in c.vertex["TargetPosition"]]
    else:
        check(all(f"TargetPosition_{k}" in c.vertex for k in "xyz"), f"{cut_ply} has no TargetPosition")
        images = list(zip(*(c.vertex[f"TargetPosition_{k}"] for k in "xyz")))
    rate = meshes.on_surface_rate(images, target, 0.005 * meshes.diagonal(target.verts))
    return c, meshes.topology(c), rate


def note(text):
    """A line of figures in the test's output."""
    print("    " + text, flush=True)
