"""The plugin in the MeshLab GUIs that Debian 12 does not have, each in the real program:
MeshLab 2022.02 (Debian 13 trixie's meshlab 2022.02+dfsg1-1, also Ubuntu 24.04's) and
MeshLab 2025.07 single precision (Debian sid's meshlab 2025.07~dfsg-4, as on Flathub and in
the plain AppImage).

Run with tests/meshlab-roots/run [-k trixie] (pytest; a stage of tests/run). For each suite:
  - test_root: a minimal Debian root of that suite with its meshlab, built once per machine
    by setup/debian-root.sh (mmdebstrap, /var/cache/eulermap/roots/SUITE);
  - test_plugin_built: Debian's meshlab source package of that version (headers, into .deps/),
    the FilterPlugin flavour configured, built (its target alone, ccache) and installed with
    cmake --install inside the root (build_plugin.sh), its version and scalar those of the
    root's libmeshlab-common;
  - test_gui: the root's meshlab under Xvfb (gui_session.sh with gui_layout_<version>.sh):
    sphere -> torus applied from Filters > Remeshing, Simplification and Reconstruction >
    Eulerian Surface Map at grid 48, the cut layer saved from File > Export Mesh As with
    its TargetPosition and measured: one component, 2 boundary loops, Euler characteristic 0,
    >= 99% of the images within 0.5% of the torus's diagonal from it; the cut layer drawn
    alone with the torus's checker. Screenshots in out/screenshots/SUITE/.
A root or a build that cannot be made fails its test with the tool's own words.
"""
import fcntl
import os
import re
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "meshlab"))
from meshlab_host import (ROOT, SAMPLES, check, checker_shares, gui_session, layout_value, measure_cut,  # noqa: E402
                          note)

# (suite, Debian source version of its meshlab, MeshLab's version string, the module's name)
SUITES = [
    ("trixie", "2022.02+dfsg1", "2022.02", "libfilter_eulermap_2022.02.so"),
    ("sid", "2025.07~dfsg", "2025.07", "libfilter_eulermap_2025.07.so"),
]
IDS = [s[0] for s in SUITES]
PLUGINS = "usr/lib/x86_64-linux-gnu/meshlab/plugins"
IN_ROOT = os.path.join(HERE, "in_root.sh")
STATE = {}  # suite -> {"root": path, "built": True}


@pytest.fixture(scope="module", autouse=True)
def roots_to_ourselves():
    """One run of these tests at a time on a machine: each installs its own build into the
    roots (and test_user_plugin_folder moves it for a while), which other clones' runs share."""
    base = os.environ.get("EULERMAP_ROOTS", "/var/cache/eulermap/roots")
    os.makedirs(base, exist_ok=True)
    with open(os.path.join(base, ".gui-tests.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        yield


def run(cmd, timeout=3600):
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=ROOT)
    return p, time.time() - t0


def tail(p, n=1500):
    return (p.stdout + p.stderr)[-n:]


@pytest.mark.parametrize("suite, source, version, module", SUITES, ids=IDS)
def test_root(suite, source, version, module):
    # tests/run starts this in the background (log in out/roots/); then this waits for it
    p, seconds = run(["bash", "setup/debian-root.sh", suite], timeout=1800)
    check(p.returncode == 0, f"the {suite} root could not be built (setup/debian-root.sh {suite}, "
                             f"exit {p.returncode}):\n{tail(p)}")
    root = p.stdout.strip().splitlines()[-1]
    have = subprocess.run(["chroot", root, "dpkg-query", "-W", "-f", "${Version}", "meshlab"],
                          capture_output=True, text=True).stdout
    check(have.startswith(source), f"the {suite} root has meshlab {have!r}, expected {source}*")
    size = subprocess.run(["du", "-sh", root], capture_output=True, text=True).stdout.split()[0]
    built = re.search(r"root built in (\d+) s", p.stderr)
    logs = os.environ.get("EULERMAP_ROOT_LOGS")  # set by tests/run, which started the build
    background = os.path.join(logs, suite + ".log") if logs else ""
    earlier = re.search(r"root built in (\d+) s", open(background).read()) if os.path.isfile(background) else None
    how = (f"built now in {built.group(1)} s" if built else
           f"built in the background by tests/run in {earlier.group(1)} s, waited {seconds:.0f} s" if earlier else
           f"reused ({seconds:.1f} s)")
    note(f"{suite} root: meshlab {have}, {size} in {root}; {how}")
    STATE[suite] = {"root": root}


@pytest.mark.parametrize("suite, source, version, module", SUITES, ids=IDS)
def test_plugin_built(suite, source, version, module):
    check(suite in STATE, f"no {suite} root (see test_root[{suite}])")
    root = STATE[suite]["root"]
    p, seconds = run(["bash", "setup/fetch-meshlab-source.sh", source, os.path.join(ROOT, ".deps")])
    check(p.returncode == 0, f"Debian's meshlab {source} source package could not be fetched:\n{tail(p)}")
    tree = os.path.basename(p.stdout.strip().splitlines()[-1])
    build = os.path.join(ROOT, "build-roots", suite)
    p, seconds = run([IN_ROOT, root, "--build", build, "bash", "/src/tests/meshlab-roots/build_plugin.sh", tree])
    check(p.returncode == 0, f"building the plugin inside the {suite} root failed (exit {p.returncode}):\n{tail(p)}")
    installed = os.path.join(root, PLUGINS, module)
    check(os.path.isfile(installed), f"cmake --install put no {module} into {PLUGINS} of the {suite} root:\n{tail(p)}")
    # the flavour's scalar is the one of the MeshLab in the root (read off its RichFloat)
    symbols = subprocess.run(["nm", "-D", "-C", os.path.join(root, "usr/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so")],
                             capture_output=True, text=True).stdout
    scalar = "double" if "RichFloat::RichFloat(QString const&, double" in symbols else "float"
    want = f"MeshLab {version}{'d' if scalar == 'double' else ''}, MESHLAB_SCALAR={scalar}"
    check(want in p.stdout, f"the flavour was not configured as {want}:\n{tail(p)}")
    cache = re.findall(r"(Hits|Misses):\s+(\d+)", p.stdout)
    note(f"{suite}: {module} ({want}) built and installed in {seconds:.0f} s; ccache {dict(cache)}")
    STATE[suite]["built"] = True


@pytest.mark.parametrize("suite, source, version, module", SUITES, ids=IDS)
def test_gui(suite, source, version, module):
    check(STATE.get(suite, {}).get("built"), f"no plugin built in the {suite} root (see test_plugin_built[{suite}])")
    root = STATE[suite]["root"]
    outdir = os.path.join(ROOT, "out", "meshlab-roots", suite)
    shots = os.path.join(ROOT, "out", "screenshots", suite)
    cut = os.path.join(outdir, "sphere_cut.ply")
    if os.path.exists(cut):
        os.remove(cut)
    t0 = time.time()
    # the clone is /src inside the root (in_root.sh)
    p, log = gui_session("/src/samples", shots, outdir, layout=version, meshlab=f"{IN_ROOT} {root} meshlab",
                         grid=48, steps=40, export="/src/" + os.path.relpath(cut, ROOT))
    seconds = time.time() - t0
    check(p.returncode == 0, f"GUI session failed ({p.returncode}): {(p.stdout + p.stderr)[-600:]}")
    check("PLUGIN_LOADED" in p.stdout, f"MeshLab {version} did not load {module} (not in /proc/PID/maps)")
    # "Applied filter Eulerian Surface Map in N msec" (2022.02), "Applied filter: ..." (2025.07)
    check(re.search(r"Applied filter:? Eulerian Surface Map", log),
          f"the filter was not applied from Filters > Remeshing > Eulerian Surface Map in MeshLab {version}; "
          f"see the screenshots in {shots} and {outdir}/meshlab.out:\n{log[-800:]}")
    check("new layer sphere_cut" in log and "new layer sphere_mapped" in log, "the filter made no layers")
    check("ALIVE_AFTER_FILTER" in p.stdout, f"MeshLab {version} did not survive the filter run")
    check(os.path.isfile(cut), f"File > Export Mesh As wrote no {cut}; see meshlab_7_export_options.png")
    c, topo, rate = measure_cut(cut, os.path.join(SAMPLES, "torus.ply"))
    box = tuple(int(v) for v in layout_value(version, "VIEW_BOX").split())
    blue, white = checker_shares(os.path.join(shots, "meshlab_6_cut_only.png"), box)
    note(f"{suite} GUI (MeshLab {version}): {seconds:.0f} s; cut {len(c.verts)} v {len(c.faces)} f, "
         f"components/loops/chi {topo}; images on the torus {100 * rate:.2f}%; "
         f"cut drawn alone: {100 * blue:.1f}% checker blue, {100 * white:.1f}% white/grey")
    check(topo == (1, 2, 0), f"cut layer: components, boundary loops, Euler characteristic {topo}, expected (1, 2, 0)")
    check(rate >= 0.99, f"only {100 * rate:.2f}% of the cut layer's TargetPosition lie on the torus")
    check(blue > 0.05 and white > 0.05, f"the cut layer is not drawn with the torus's checker in MeshLab {version} "
                                        f"({shots}/meshlab_6_cut_only.png)")


@pytest.mark.parametrize("suite, source, version, module", SUITES[1:], ids=IDS[1:])
def test_user_plugin_folder(suite, source, version, module):
    """The way Flathub and AppImage users of MeshLab 2025.07 install it (their MeshLab's own
    folder is read-only): the module alone in the per-user folder MeshLab also loads plugins
    from, ~/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/2025.07/
    (MeshLabApplication::extraPluginsLocation()), none in the system folder; the filter is
    applied from the Filters menu (grid 24, 8 steps)."""
    check(STATE.get(suite, {}).get("built"), f"no plugin built in the {suite} root (see test_plugin_built[{suite}])")
    root = STATE[suite]["root"]
    system = os.path.join(root, PLUGINS, module)
    folder = f"~/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/{version}/"
    user_dir = os.path.join(root, "root", folder[2:])
    os.makedirs(user_dir, exist_ok=True)
    user = os.path.join(user_dir, module)
    os.replace(system, user)
    try:
        outdir = os.path.join(ROOT, "out", "meshlab-roots", suite + "-user")
        p, log = gui_session("/src/samples", os.path.join(ROOT, "out", "screenshots", suite + "-user"), outdir,
                             layout=version, meshlab=f"{IN_ROOT} {root} meshlab")
    finally:
        os.replace(user, system)  # back where cmake --install put it
    check(p.returncode == 0, f"GUI session failed ({p.returncode}): {(p.stdout + p.stderr)[-600:]}")
    check("PLUGIN_LOADED" in p.stdout, f"MeshLab {version} did not load {module} from {folder}")
    check(re.search(r"Applied filter:? Eulerian Surface Map", log) and "new layer sphere_cut" in log,
          f"the filter, loaded from {folder}, was not applied from the Filters menu:\n{log[-800:]}")
    note(f"{suite}: MeshLab {version} loaded {module} from {folder} and applied it from the Filters menu")
