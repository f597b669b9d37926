"""MeshLab 2020.09 integration tests of the Eulerian Surface Map plugin.

Run with tests/meshlab/run [-k SUBSTRING] (pytest), after building and installing the
plugin (as root): cmake --build build && cmake --install build

What it checks, through Debian's meshlab / meshlabserver under Xvfb:
  - the installed plugin is the one in build/ and meshlabserver lists the filter with a
    help text on every parameter (that the sample .mlx scripts give every parameter of the
    table, in order, is the ctest SampleScripts: tests/bench/generated.py);
  - each sample script (samples/*.mlx): the cut layer's components, boundary loops and
    Euler characteristic, >= 99% of the mapped vertices within 0.5% of the target's
    bounding-box diagonal from the target (in the mapped layer, and before the final
    projection as the report gives it), cut and mapped with the same vertices and faces,
    the report in the log, the input layers unchanged after the filter and the input
    files unchanged (checksums);
  - samples/map_meshes.sh writes cut.ply, mapped.ply and report.txt;
  - docs/tools/render.sh draws a real cut layer with the checker texture it pulled (measured
    in the PNG: three drawings, the checker's colours on the textured ones only);
  - every bad input fails the filter with its message, without a crash;
  - the GUI: meshlab loads the plugin, and (with xdotool) the filter is run from
    Filters > Remeshing; screenshots go to out/screenshots/.
Outputs go to out/meshlab/ (kept). tests/meshlab/run ends with 'N passed, N failed' and
exits 1 when any failed.
"""
import atexit
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshes  # noqa: E402
from meshlab_host import (BUILT, CRASH_CODES, FILTER, OUT, PLUGIN, ROOT, SAMPLE_RUNS, SAMPLES, SHOTS,  # noqa: E402
                          bad_inputs, build_id, check, checker_shares, failure_message, filter_log, gui_session,
                          layout_value, measure_cut, meshlabserver, mlx_text, note, plugin_parameter_names, quick_map, read_png,
                          sample_checksums, sha256, write_file)

INITIAL_CHECKSUMS = sample_checksums()  # test_inputs_unchanged, last, compares with them
BAD_DIR = tempfile.mkdtemp(prefix="eulermap-meshlab-")
atexit.register(shutil.rmtree, BAD_DIR, True)
BAD_INPUTS = bad_inputs(BAD_DIR)


def test_plugin_installed():
    check(os.path.isfile(PLUGIN), f"{PLUGIN} missing: build and install the plugin (cmake --install build)")
    if os.path.isfile(BUILT):
        check(build_id(BUILT) == build_id(PLUGIN), f"{PLUGIN} is not the plugin in {BUILT}: run cmake --install build")


def test_meshlabserver_lists_filter():
    dump = os.path.join(OUT, "filters.txt")
    os.makedirs(OUT, exist_ok=True)
    p = subprocess.run(["xvfb-run", "-a", "meshlabserver", "-d", dump], capture_output=True, text=True, timeout=300)
    check(p.returncode == 0 and os.path.isfile(dump), f"meshlabserver -d failed ({p.returncode}): {p.stdout[-500:]}")
    text = open(dump, errors="replace").read()
    m = re.search(r"\\section \w+ " + re.escape(FILTER) + r"\s*\n(.*?)(?=\\section|\Z)", text, re.S)
    check(m, f"'{FILTER}' not in meshlabserver's filter list ({dump})")
    body = m.group(1)
    check("An Eulerian approach for constructing a map between surfaces" in body, "description does not cite the paper")
    rows = re.findall(r"<TR><TD> \\c (\w+)\s*</TD> <TD> (.*?) </TD> <TD><i> (.*?) -- </i></TD> </TR>", body)
    names = plugin_parameter_names()
    check(len(rows) == len(names), f"{len(rows)} parameters listed, {len(names)} in core/parameters.h")
    for kind, label, help_text in rows:
        check(len(help_text) > 40, f"parameter '{label}' has no real help text: '{help_text}'")


@pytest.mark.parametrize("name, source, target, expect", SAMPLE_RUNS, ids=[run[0] for run in SAMPLE_RUNS])
def test_sample(name, source, target, expect):
    outdir = os.path.join(OUT, name)
    shutil.rmtree(outdir, ignore_errors=True)
    before = sample_checksums()
    cut, mapped, filled = (os.path.join(outdir, f) for f in ("cut.ply", "mapped.ply", "filled.ply"))
    layer0, layer1 = os.path.join(outdir, "layer0_after.ply"), os.path.join(outdir, "layer1_after.ply")
    saves = [(cut, 2), (mapped, 3), (layer0, 0), (layer1, 1)] + ([(filled, 4)] if expect.get("filled") else [])
    t0 = time.time()
    rc, log = meshlabserver(outdir, [os.path.join(SAMPLES, source), os.path.join(SAMPLES, target)],
                            os.path.join(SAMPLES, name + ".mlx"), saves)
    seconds = time.time() - t0
    report = filter_log(log)
    with open(os.path.join(outdir, "report.txt"), "w") as f:
        f.write("\n".join(report) + "\n")
    check(sample_checksums() == before, "the run changed files in samples/")
    check(rc not in CRASH_CODES, f"meshlabserver crashed (exit {rc}); see {outdir}/meshlabserver.out")
    check(rc == 0, f"meshlabserver failed (exit {rc}): {failure_message(log)}")
    base = os.path.splitext(source)[0]
    for line in ("Eulerian Surface Map: ", "grid: ", "times (s): ", "map quality: ", f"new layer {base}_cut: ",
                 f"new layer {base}_mapped: "):
        check(any(l.startswith(line) for l in report), f"the log lacks a '{line}...' line")
    if "anchors" in expect:  # every active point of the .pp beside the source, at least 6
        pp = open(os.path.join(SAMPLES, expect["anchors"])).read()
        n = len(re.findall(r'<point [^>]*active="1"', pp))
        check(n >= 6, f"{expect['anchors']} has {n} active anchors, fewer than 6")
        check(any(l.startswith(f"anchors: {n} named pairs") for l in report),
              f"the log does not report the {n} named anchor pairs of {expect['anchors']}")
    for before_file, after_file in ((source, layer0), (target, layer1)):
        a, b = meshes.read_mesh(os.path.join(SAMPLES, before_file)), meshes.read_mesh(after_file)
        check(a.faces == b.faces and max(abs(p - q) for u, v in zip(a.verts, b.verts) for p, q in zip(u, v)) < 1e-6,
              f"the input layer {before_file} was changed by the filter")
    c, m = meshes.read_mesh(cut), meshes.read_mesh(mapped)
    check(len(c.verts) == len(m.verts) and c.faces == m.faces,
          f"cut ({len(c.verts)} v) and mapped ({len(m.verts)} v) differ in vertices or faces")
    check("quality" in c.vertex, "the cut layer has no vertex quality")
    if "texture" in expect:
        check("texcoord" in c.face_props, "the cut layer has no wedge texture coordinates")
        check(f"TextureFile {expect['texture']}" in c.comments, f"the cut layer does not name {expect['texture']}")
    if "mapped_texture" in expect:  # the forward method: the source's own texture, or none
        if expect["mapped_texture"]:
            s = meshes.read_mesh(os.path.join(SAMPLES, source))
            check("texcoord" in m.face_props and m.faces == s.faces and
                  max(abs(p - q) for u, v in zip(m.face_props["texcoord"], s.face_props["texcoord"])
                      for p, q in zip(u, v)) < 1e-6,
                  "the mapped layer does not carry the source's own wedge texture coordinates")
            check(f"TextureFile {expect['mapped_texture']}" in m.comments,
                  f"the mapped layer does not name {expect['mapped_texture']}")
        else:
            check("texcoord" not in m.face_props and not any("TextureFile" in x for x in m.comments),
                  "the mapped layer has texture coordinates though the source has none")
    for line in (expect.get("note"), expect.get("log")):
        check(not line or any(l.startswith(line) for l in report), f"the log lacks a '{line}...' line")
    tgt = meshes.read_mesh(os.path.join(SAMPLES, target))
    tol = 0.005 * meshes.diagonal(tgt.verts)
    rate = meshes.on_surface_rate(m.verts, tgt, tol)
    topo = meshes.topology(c)
    tracked = [float(x) for l in report for x in re.findall(r"^map quality: on-surface ([\d.]+)%", l)]
    note(f"{name}: {seconds:.0f} s; cut {len(c.verts)} v {len(c.faces)} f, components/loops/chi {topo}; "
         f"mapped on target {100 * rate:.2f}%, before projection {tracked}%")
    check(rate >= 0.99, f"only {100 * rate:.2f}% of the mapped vertices lie within 0.5% of the diagonal of the target")
    # The mapped layer is projected onto the target at the end; the report's on-surface
    # rate measures the tracked images before that projection (report.h, MapQuality).
    check(tracked and tracked[0] >= 99, f"the report's on-surface rate (before projection) is {tracked}%, below 99%")
    want = (expect["components"], expect["loops"], expect["chi"])
    check(topo == want, f"cut layer: components, boundary loops, Euler characteristic {topo}, expected {want}")
    if expect.get("filled"):
        check(os.path.isfile(filled), "no filled layer was saved (fill_holes is on)")
        ftopo = meshes.topology(meshes.read_mesh(filled))
        want = (expect["components"], 0, expect["chi"] + expect["loops"])  # each hole closed by a disc
        check(ftopo == want, f"filled layer: components, boundary loops, Euler characteristic {ftopo}, expected {want}")


def test_map_meshes_script():
    outdir = os.path.join(OUT, "map_meshes")
    shutil.rmtree(outdir, ignore_errors=True)
    quick_map("torus.ply", "sphere.ply", outdir)
    for f in ("cut.ply", "mapped.ply", "report.txt"):
        check(os.path.getsize(os.path.join(outdir, f)) > 0, f"map_meshes.sh wrote no {f}")
    report = open(os.path.join(outdir, "report.txt")).read()
    check(re.search(r"grid: \d+ x \d+ x \d+ nodes", report), "report.txt has no grid line")
    check("steps: 8" in report, "report.txt does not show --steps 8")
    c, m = meshes.read_mesh(os.path.join(outdir, "cut.ply")), meshes.read_mesh(os.path.join(outdir, "mapped.ply"))
    check(len(c.verts) == len(m.verts) and c.faces == m.faces, "cut.ply and mapped.ply differ in vertex order or faces")
    # The cut torus: as many vertices and faces, and the same topology, as the report says
    # (surgery removes faces and adds points where rims open), mapped onto the sphere.
    m_cut = re.search(r"cut source: (\d+) components?, (\d+) boundary loops?, Euler characteristic (-?\d+); "
                      r"(\d+) vertices \((\d+) added by surgery\), (\d+) faces", report)
    check(m_cut, "report.txt has no 'cut source: ...' line")
    comps, loops, chi, nv, added, nf = map(int, m_cut.groups())
    check((len(c.verts), len(c.faces)) == (nv, nf),
          f"cut.ply has {len(c.verts)} vertices, {len(c.faces)} faces; the report says {nv}, {nf}")
    check(meshes.topology(c) == (comps, loops, chi),
          f"cut.ply: components, loops, chi {meshes.topology(c)}; the report says {(comps, loops, chi)}")
    m_split = re.search(r"(\d+) added where edges stretched", report)
    check(m_split, "report.txt has no 'added where edges stretched' figure")
    split = int(m_split.group(1))
    check(len(c.verts) <= 2048 + added + split,
          f"cut.ply has {len(c.verts)} vertices: more than the torus's 2048 + {added} added by surgery + {split} "
          "where edges stretched")
    sphere = meshes.read_mesh(os.path.join(SAMPLES, "sphere.ply"))
    rate = meshes.on_surface_rate(m.verts, sphere, 0.005 * meshes.diagonal(sphere.verts))
    check(rate >= 0.99, f"only {100 * rate:.2f}% of mapped.ply lies on the sphere")


def test_render_script():
    """docs/tools/render.sh draws a real output with MeshLab: sphere -> torus (small grid),
    then sphere | cut sphere with the torus's checker pulled | mapped layer, 1200x300.
    Measured in the PNG: its size, three separate drawings left to right, the plain
    sphere and the mapped layer (the forward method: the sphere's own texture, none)
    without the checker's blue, the cut with the checker's blue and white cells
    alternating along its middle row (MeshLab's stand-in for a missing image, dummy.png,
    is a grey checker: no blue). A texture found nowhere is an error."""
    outdir = os.path.join(OUT, "render")
    shutil.rmtree(outdir, ignore_errors=True)
    quick_map("sphere.ply", "torus.ply", outdir)
    cut, mapped, picture = (os.path.join(outdir, f) for f in ("cut.ply", "mapped.ply", "render.png"))
    check("TextureFile torus_checker.png" in meshes.read_mesh(cut).comments, "the cut layer does not name torus_checker.png")
    check(sha256(os.path.join(outdir, "torus_checker.png")) == sha256(os.path.join(SAMPLES, "torus_checker.png")),
          "map_meshes.sh did not copy the texture the cut layer names beside it")
    render = os.path.join(ROOT, "docs", "tools", "render.sh")
    t0 = time.time()
    p = subprocess.run([render, picture, "--size", "1200x300", "--textures", SAMPLES, os.path.join(SAMPLES, "sphere.ply"),
                        cut, mapped], capture_output=True, text=True, timeout=300)
    seconds = time.time() - t0
    check(p.returncode == 0, f"render.sh failed ({p.returncode}): {(p.stdout + p.stderr)[-600:]}")
    width, height, rgb = read_png(picture)
    check((width, height) == (1200, 300), f"the picture is {width}x{height}, not 1200x300")

    def pixel(x, y):
        i = 3 * (y * width + x)
        return rgb[i], rgb[i + 1], rgb[i + 2]

    def drawn(c):  # not the white background
        return min(c) < 235
    cols = [any(drawn(pixel(x, y)) for y in range(0, height, 2)) for x in range(width)]
    runs, start = [], None
    for x, on in enumerate(cols + [False]):
        if on and start is None:
            start = x
        elif not on and start is not None:
            runs.append((start, x))
            start = None
    check(len(runs) == 3, f"expected 3 separate drawings left to right, found column runs {runs}")
    covered = sum(drawn(pixel(x, y)) for x in range(0, width, 2) for y in range(0, height, 2)) / (width * height / 4)
    check(covered > 0.15, f"only {100 * covered:.1f}% of the picture is drawn")

    def blue(c):  # the checker's #3070c0, lit or in shade
        return c[2] > c[0] + 60 and c[2] > c[1] + 25

    def white(c):  # the checker's white cells (grey in shade)
        return min(c) > 130 and max(c) - min(c) < 30

    shares = []
    for x0, x1 in runs:
        px = [pixel(x, y) for x in range(x0, x1, 2) for y in range(0, height, 2)]
        px = [c for c in px if drawn(c)]
        shares.append((sum(map(blue, px)) / len(px), sum(map(white, px)) / len(px)))
    note(f"render.sh: {seconds:.1f} s; drawings at columns {runs}; (blue, white) shares "
         + ", ".join(f"({b:.2f}, {w:.2f})" for b, w in shares))
    for (b, w), name in ((shares[0], "plain sphere"), (shares[2], "mapped layer")):
        check(b < 0.01, f"the {name} shows the checker's blue ({100 * b:.1f}% of its pixels)")
    for (x0, x1), (b, w), name in ((runs[1], shares[1], "cut"),):
        check(b > 0.2 and w > 0.15, f"the {name} layer is not drawn with the checker: {100 * b:.0f}% blue, {100 * w:.0f}% white")
        row, kinds = [pixel(x, height // 2) for x in range(x0, x1)], []
        for c in row:
            k = "b" if blue(c) else "w" if white(c) else None
            if k and (not kinds or kinds[-1] != k):
                kinds.append(k)
        check(len(kinds) >= 5, f"the {name} layer's middle row does not alternate blue and white cells: {''.join(kinds)}")
    # a texture found nowhere: an error naming it, before MeshLab starts
    alone = os.path.join(outdir, "alone")
    os.makedirs(alone)
    shutil.copy(cut, alone)
    p = subprocess.run([render, os.path.join(outdir, "missing.png"), os.path.join(alone, "cut.ply")],
                       capture_output=True, text=True, timeout=60)
    check(p.returncode != 0 and "texture 'torus_checker.png'" in p.stderr,
          f"render.sh without the texture: exit {p.returncode}, {p.stderr[-300:]}")
    check(not os.path.exists(os.path.join(outdir, "missing.png")), "render.sh wrote a picture without the texture")


# Small grids, so a wrongly accepted input still ends quickly.
@pytest.mark.parametrize("name, inputs, values, expected", BAD_INPUTS, ids=[b[0] for b in BAD_INPUTS])
def test_bad_input(name, inputs, values, expected):
    outdir = os.path.join(OUT, "bad_" + name)
    shutil.rmtree(outdir, ignore_errors=True)
    script = write_file(os.path.join(BAD_DIR, name + ".mlx"), mlx_text(**values))
    rc, log = meshlabserver(outdir, inputs, script, timeout=300)
    check(rc not in CRASH_CODES and "Assertion" not in open(os.path.join(outdir, "meshlabserver.out")).read(),
          f"meshlabserver crashed (exit {rc})")
    message = failure_message(log)
    check(rc == 255, f"expected the filter to fail (meshlabserver exit 255), got exit {rc}")
    check(expected in message, f"message '{message}' does not say '{expected}'")
    note(f"bad input {name}: {message}")


def test_gui():
    """meshlab under Xvfb: the plugin is loaded into the process; with xdotool, the filter
    is run from Filters > Remeshing (sphere -> torus, grid 24, 8 steps), the layers it makes
    appear, and the cut layer, saved from File > Export Mesh As with its TargetPosition, is
    one component with 2 boundary loops and Euler characteristic 0 whose images lie on the
    torus; screenshots in out/screenshots/."""
    have_xdotool = shutil.which("xdotool") is not None
    cut = os.path.join(OUT, "gui", "sphere_cut.ply")
    if os.path.exists(cut):
        os.remove(cut)
    p, log = gui_session(SAMPLES, SHOTS, os.path.join(OUT, "gui"), drive=have_xdotool, export=cut)
    check(p.returncode == 0, f"GUI session failed ({p.returncode}): {(p.stdout + p.stderr)[-600:]}")
    check("PLUGIN_LOADED" in p.stdout, "meshlab did not load libfilter_eulermap.so (not in /proc/PID/maps)")
    shots = sorted(glob.glob(os.path.join(SHOTS, "meshlab_*.png")))
    check(shots, "no screenshot written")
    if not have_xdotool:
        note("GUI: plugin loaded; xdotool missing, so the Filters menu was not driven (apt-get install xdotool)")
        return
    check("new layer sphere_cut" in log and "new layer sphere_mapped" in log,
          "the filter run from Filters > Remeshing > Eulerian Surface Map made no layers; see the screenshots")
    check("ALIVE_AFTER_FILTER" in p.stdout, "meshlab did not survive the filter run")
    # The cut sphere alone in the 3D view: drawn with the torus's checker, so the GUI loaded
    # the new layer's texture image.
    box = tuple(int(v) for v in layout_value("2020.09", "VIEW_BOX").split())
    blue, white = checker_shares(os.path.join(SHOTS, "meshlab_6_cut_only.png"), box)
    note(f"GUI: the cut sphere alone: {100 * blue:.1f}% checker blue, {100 * white:.1f}% white/grey of the 3D view")
    check(blue > 0.05 and white > 0.05, "the cut layer is not drawn with the torus's checker in the GUI "
                                        "(meshlab_6_cut_only.png)")
    check(os.path.isfile(cut), f"File > Export Mesh As wrote no {cut}; see meshlab_7_export_options.png")
    c, topo, rate = measure_cut(cut, os.path.join(SAMPLES, "torus.ply"))
    note(f"GUI: cut {len(c.verts)} v {len(c.faces)} f, components/loops/chi {topo}; images on the torus "
         f"{100 * rate:.2f}%")
    check(topo == (1, 2, 0), f"cut layer: components, boundary loops, Euler characteristic {topo}, expected (1, 2, 0)")
    check(rate >= 0.99, f"only {100 * rate:.2f}% of the cut layer's TargetPosition lie on the torus")
    note("GUI: screenshots " + ", ".join(os.path.relpath(s, ROOT) for s in shots))


def test_inputs_unchanged():
    check(sample_checksums() == INITIAL_CHECKSUMS, "files in samples/ changed during the tests")
