#!/usr/bin/env python3
"""Maps one mesh file onto another with the Eulerian Surface Map filter, through pymeshlab
(PyPI's 2025.7.post1 in the project's .venv) and the plugin's MeshLab 2025.07 flavour.

Usage: samples/map_meshes.py SOURCE TARGET OUTDIR [--grid N] [--steps N] [--plugin SO]
  SOURCE, TARGET  mesh files pymeshlab reads (.ply, .obj, .off, ...); layer 0 is the source,
                  layer 1 the target. A .pp picked-points file beside each, with the same
                  base name (spot.ply + spot.pp), gives named anchors.
  OUTDIR          gets cut.ply (the cut source: original positions, vertex quality =
                  distortion, per-vertex TargetPosition, texture coordinates pulled from the
                  target and its texture images when it has them), mapped.ply (the same
                  vertices in the same order, at their images on the target) and report.txt
                  (the filter's log).
  --grid N        cells on the longest axis of the grid (default 64)
  --steps N       time steps (default 40)
  --plugin SO     the plugin to load (default: $EULERMAP_PLUGIN, else the one setup/build.sh
                  builds, build/filter_eulermap/libfilter_eulermap_2025.so)
Runs itself with .venv/bin/python when the interpreter it was started with has no
pymeshlab. Exits non-zero, with the filter's message, when the map fails.

As a module (the pymeshlab tests use it): load_plugin(), apply_logged(), map_meshes().
"""
import argparse
import contextlib
import ctypes
import os
import re
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
VENV_PYTHON = os.path.join(ROOT, ".venv", "bin", "python")
PLUGIN = os.environ.get("EULERMAP_PLUGIN") or os.path.join(ROOT, "build", "filter_eulermap",
                                                           "libfilter_eulermap_2025.so")
FILTER = "generate_eulerian_surface_map"

try:
    import pymeshlab
except ImportError:
    # Started by another interpreter (python3 samples/map_meshes.py ...): use the venv's.
    if __name__ == "__main__" and os.access(VENV_PYTHON, os.X_OK) and \
            os.path.realpath(sys.prefix) != os.path.realpath(os.path.join(ROOT, ".venv")):
        os.execv(VENV_PYTHON, [VENV_PYTHON] + sys.argv)
    raise ImportError(f"no pymeshlab for {sys.executable}: setup/build.sh creates {VENV_PYTHON} with it")


def load_plugin(path=PLUGIN):
    """Loads the plugin into pymeshlab once per process (a second load_plugin of the same
    file is an error in pymeshlab)."""
    if FILTER not in pymeshlab.filter_list():
        if not os.path.isfile(path):
            raise FileNotFoundError(f"{path} missing: build the plugin (bash setup/build.sh)")
        pymeshlab.load_plugin(path)


@contextlib.contextmanager
def _output_to(path):
    """Sends file descriptors 1 and 2 to `path` while the block runs: with verbosity on,
    pymeshlab prints MeshLab's log ("LOG: <level> <text>") on standard error and a header
    per filter on standard output, from C++, out of reach of sys.stdout / sys.stderr."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    with open(path, "wb") as f:
        os.dup2(f.fileno(), 1)
        os.dup2(f.fileno(), 2)
    try:
        yield
    finally:
        ctypes.CDLL(None).fflush(None)  # C stdio's buffers
        for fd, copy in zip((1, 2), saved):
            os.dup2(copy, fd)
            os.close(copy)


# "LOG: 2 text" is a log line; "LOG: 2 stage    [ 45% ]" is a progress report; the header
# pymeshlab prints before a filter runs is "Applying filter NAME with the following
# parameters:", then a blank line and the parameters as a dict.
_LOG_LINE = re.compile(r"^LOG: \d+ (.*)$")
_PROGRESS = re.compile(r"\s+\[\s*\d+%\s*\]$")
_HEADER = re.compile(r"^Applying filter \S+ with the following parameters:$")


def _forget_failed_filter():
    """Works around pymeshlab 2025.7.post1 after a filter raised: its progress callback
    still points at the log of that filter's MeshSet (src/pymeshlab/pymeshlab/helpers/
    meshset_helper.cpp, applyFilter, sets VerbosityManager::staticLogger and clears it only
    when the filter returns), so once that MeshSet is freed, the next mesh loaded in any
    MeshSet writes into freed memory and the interpreter aborts. Any filter that succeeds
    clears the pointer: one on a throw-away MeshSet leaves the caller's as it is."""
    pymeshlab.MeshSet().create_tetrahedron()


def apply_logged(ms, log, **parameters):
    """Applies the filter to MeshSet `ms` and appends the filter's log lines to the list
    `log`, also when the filter fails; anything else printed meanwhile goes on to standard
    error. Returns the figures the filter returns (a dict: on_surface_rate, coverage,
    cut_boundary_loops, ...); raises pymeshlab's PyMeshLabException, carrying the filter's
    message, when it fails."""
    with tempfile.NamedTemporaryFile(prefix="eulermap-log-") as tmp:
        ms.set_verbosity(True)
        try:
            with _output_to(tmp.name):
                return ms.apply_filter(FILTER, **parameters)
        except pymeshlab.PyMeshLabException:
            _forget_failed_filter()
            raise
        finally:
            ms.set_verbosity(False)
            header = False  # the header line is followed by the parameters' dict
            for line in open(tmp.name, errors="replace").read().splitlines():
                m = _LOG_LINE.match(line)
                if m and not _PROGRESS.search(line):
                    log.append(m.group(1))
                elif not m and line.strip() and not header and not _HEADER.match(line):
                    print(line, file=sys.stderr)
                header = bool(_HEADER.match(line)) or (header and not line.strip())


def map_meshes(source, target, outdir, grid=64, steps=40, plugin=PLUGIN):
    """The script's job. Returns (the MeshSet: layers 0 and 1 the inputs, then the new
    ones; the figures; the log lines); writes OUTDIR/cut.ply, mapped.ply and report.txt
    (report.txt also when the filter fails, which raises PyMeshLabException)."""
    load_plugin(plugin)
    os.makedirs(outdir, exist_ok=True)
    for name in ("cut.ply", "mapped.ply", "report.txt"):
        with contextlib.suppress(FileNotFoundError):
            os.remove(os.path.join(outdir, name))
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(os.path.abspath(source))  # its path finds the .pp beside it
    ms.load_new_mesh(os.path.abspath(target))
    source_id, target_id = 0, 1  # a new MeshSet numbers its layers 0, 1, 2, ... as they come
    log = []
    try:
        figures = apply_logged(ms, log, source_mesh=source_id, target_mesh=target_id, grid_resolution=grid,
                               steps=steps)
    finally:
        with open(os.path.join(outdir, "report.txt"), "w") as f:
            f.write("".join(line + "\n" for line in log))
    cut_id, mapped_id = 2, 3  # the filter's new layers
    for layer, name, extra in ((cut_id, "cut.ply", {"__ca_vp__targetposition": True}), (mapped_id, "mapped.ply", {})):
        ms.set_current_mesh(layer)
        ms.save_current_mesh(os.path.join(outdir, name), save_vertex_quality=True,
                             save_wedge_texcoord=ms.current_mesh().has_wedge_tex_coord(), **extra)
    return ms, figures, log


def main():
    parser = argparse.ArgumentParser(usage="%(prog)s SOURCE TARGET OUTDIR [--grid N] [--steps N] [--plugin SO]",
                                     description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("source")
    parser.add_argument("target")
    parser.add_argument("outdir")
    parser.add_argument("--grid", type=int, default=64, help="cells on the longest axis of the grid")
    parser.add_argument("--steps", type=int, default=40, help="time steps")
    parser.add_argument("--plugin", default=PLUGIN, help="the plugin to load")
    args = parser.parse_args()
    for f in (args.source, args.target):
        if not os.path.isfile(f):
            parser.error(f"no such mesh file: {f}")
    report = os.path.join(args.outdir, "report.txt")
    try:
        _, _, log = map_meshes(args.source, args.target, args.outdir, args.grid, args.steps, args.plugin)
    except (pymeshlab.PyMeshLabException, FileNotFoundError) as e:
        if os.path.isfile(report):
            print(open(report).read(), end="")
        print(f"map_meshes.py: the map failed: {e}", file=sys.stderr)
        return 1
    print("\n".join(log))
    out = os.path.abspath(args.outdir)
    print(f"wrote {out}/cut.ply, {out}/mapped.ply, {out}/report.txt")
    return 0


if __name__ == "__main__":
    sys.exit(main())
