"""Running the filter from Python: its log and its progress, which pymeshlab does not hand
to Python, and the whole job on files.

pymeshlab 2025.7.post1 has no progress callback in its Python API: MeshSet.apply_filter()
takes the filter's parameters only. With set_verbosity(True) its C++ side prints MeshLab's
log as "LOG: <level> <text>" on standard error, including each progress report of the
filter ("LOG: 2 step 3 of 40    [ 25% ]") as the filter makes it, and a header per filter
on standard output. So while the filter runs, file descriptors 1 and 2 go to a pipe that a
thread reads line by line: progress reports go to the caller's callback as they come, log
lines to the caller's list, anything else on to the real standard error.
"""
import collections
import contextlib
import json
import os
import re
import sys
import threading
import time

import pymeshlab

from . import FILTER

# "LOG: 2 text" is a log line; "LOG: 2 stage    [ 45% ]" is a progress report; the header
# pymeshlab prints before a filter runs is "Applying filter NAME with the following
# parameters:", then a blank line and the parameters as a dict.
_LOG_LINE = re.compile(r"^LOG: \d+ (.*)$")
_PROGRESS = re.compile(r"^(.*?)\s+\[\s*(\d+)%\s*\]$")
_HEADER = re.compile(r"^Applying filter \S+ with the following parameters:$")

MapResult = collections.namedtuple("MapResult", "figures log meshset")
MapResult.__doc__ = """map_files()'s result: the figures (dict), the log lines (list of str) and
the MeshSet (layers 0 and 1 the inputs, 2 the cut source, 3 the mapped source, 4 the filled one)."""


class _OutputPipe:
    """While active, file descriptors 1 and 2 write into a pipe read by a thread, which
    calls on_line(line) for each line. `stderr` is a file on the real standard error
    meanwhile (for progress bars and lines passed on)."""

    def __init__(self, on_line):
        self.on_line = on_line

    def __enter__(self):
        sys.stdout.flush()
        sys.stderr.flush()
        self.saved = [os.dup(1), os.dup(2)]
        self.stderr = os.fdopen(os.dup(self.saved[1]), "w", buffering=1)
        read, write = os.pipe()
        self.thread = threading.Thread(target=self._read, args=(read,), daemon=True)
        self.thread.start()
        os.dup2(write, 1)
        os.dup2(write, 2)
        os.close(write)
        return self

    def _read(self, fd):
        with os.fdopen(fd, "rb") as pipe:
            for raw in pipe:
                try:
                    self.on_line(raw.decode(errors="replace").rstrip("\r\n"))
                except Exception as e:  # a callback's error must not stall the pipe
                    print(f"eulermap: progress callback failed: {e!r}", file=self.stderr)

    def __exit__(self, *exc):
        import ctypes
        sys.stdout.flush()
        sys.stderr.flush()
        ctypes.CDLL(None).fflush(None)  # C stdio's buffers
        for fd, copy in zip((1, 2), self.saved):
            os.dup2(copy, fd)  # the pipe's last writers close: the thread reads to its end
            os.close(copy)
        self.thread.join()
        self.stderr.close()
        return False


def _forget_failed_filter():
    """pymeshlab 2025.7.post1, after a filter raised, keeps a pointer to that MeshSet's log
    (its progress callback's logger); once that MeshSet is freed, the next mesh loaded in
    any MeshSet writes into freed memory. Any filter that succeeds clears the pointer: one
    on a throw-away MeshSet leaves the caller's as it is."""
    pymeshlab.MeshSet().create_tetrahedron()


def failure_message(error):
    """The filter's own message in a PyMeshLabException ("Failed to apply filter: NAME
    Details: <message>" from pymeshlab), or the exception's text."""
    text = str(error).strip()
    m = re.match(r"Failed to apply filter: \S+\s+Details:\s*(.*)$", text, re.S)
    return (m.group(1).strip() if m else text) or type(error).__name__


def map_meshes(ms, source, target, *, progress=None, log=None, **parameters):
    """Maps layer `source` of MeshSet `ms` onto layer `target` with the Eulerian Surface Map
    filter and returns the report's figures (dict: on_surface_rate, coverage, ...; rates
    as shares, times in seconds). New layers: <source>_cut, <source>_mapped (and
    <source>_filled with fill_holes=True).

    parameters  the filter's other parameters (parameters() lists them), e.g.
                grid_resolution=48, steps=30, align="none"
    progress    optional callable(percent, stage): called, from another thread, with each
                progress report of the filter as it runs (percent 0..100, stage its text)
    log         optional list: the filter's log lines are appended to it, also when it fails
    Raises pymeshlab.PyMeshLabException, with the filter's message, when the filter fails.
    """
    lines = [] if log is None else log
    in_header = [False]  # inside the header pymeshlab prints before the filter (up to its dict)

    def on_line(line):
        start = line.find("LOG: ")
        if start > 0 and _LOG_LINE.match(line[start:]):
            # Something wrote to fd 2 without a newline just before (a progress bar drawn on
            # sys.stderr, say): pass it on as it was.
            pipe.stderr.write(line[:start])
            line = line[start:]
        m = _LOG_LINE.match(line)
        if m:
            p = _PROGRESS.match(m.group(1))
            if p:
                if progress is not None:
                    progress(int(p.group(2)), p.group(1).strip())
            else:
                lines.append(m.group(1))
        elif _HEADER.match(line):
            in_header[0] = True
        elif in_header[0]:
            in_header[0] = not line.startswith("{")
        elif line.strip():
            print(line, file=pipe.stderr)

    ms.set_verbosity(True)
    try:
        with _OutputPipe(on_line) as pipe:
            try:
                return ms.apply_filter(FILTER, source_mesh=source, target_mesh=target, **parameters)
            finally:
                ms.set_verbosity(False)  # before anything else runs a filter (below)
    except pymeshlab.PyMeshLabException:
        _forget_failed_filter()
        raise


@contextlib.contextmanager
def progress_bar(**tqdm_options):
    """A tqdm progress bar over the filter's stages: `with progress_bar() as p:
    map_meshes(ms, 0, 1, progress=p)`. It draws on a duplicate of standard error taken
    when the block starts (while the filter runs, file descriptor 2 goes to the pipe that
    map_meshes reads); the bar's text is the stage the filter reports."""
    from tqdm import tqdm
    stream = os.fdopen(os.dup(2), "w", buffering=1)
    options = dict(total=100, unit="%", desc="starting", file=stream,
                   bar_format="{desc:<28.28} {percentage:3.0f}%|{bar}| {elapsed}")
    options.update(tqdm_options)
    bar = tqdm(**options)

    def update(percent, stage):
        bar.set_description_str(stage, refresh=False)
        bar.n = percent
        bar.refresh()  # a redraw for each report (a few dozen a map), so that each stage shows

    try:
        yield update
    finally:
        bar.close()
        stream.close()


def parameters():
    """The filter's parameters other than the two layers: an ordered dict name -> (type,
    default), as pymeshlab lists them (type one of bool, int, float, str; align's default
    is its name, 'centre-and-scale')."""
    text = []
    with _OutputPipe(text.append):
        pymeshlab.print_filter_parameter_list(FILTER)
    types = {"bool": bool, "int": int, "float": float, "str": str}
    found = collections.OrderedDict()
    for line in text:
        m = re.match(r"^\s+(\w+) : (\w+) = (.*)$", line)
        if m and m.group(1) not in ("source_mesh", "target_mesh") and m.group(2) in types:
            kind, value = types[m.group(2)], m.group(3).strip()
            if kind is bool:
                default = value == "True"
            elif kind is str:
                default = value[1:-1] if value[:1] in "'\"" else value
            else:
                default = kind(value)
            found[m.group(1)] = (kind, default)
    if not found:
        raise RuntimeError(f"pymeshlab lists no parameters for {FILTER}: {text}")
    return found


def map_files(source, target, outdir, *, progress=None, **parameters):
    """Maps mesh file `source` onto mesh file `target` (any format pymeshlab reads; a .pp
    picked-points file beside each, with the same base name, gives named anchors) and
    writes into `outdir`:
      cut.ply      the cut source: original positions, vertex quality = distortion,
                   per-vertex TargetPosition, texture coordinates pulled from the target
                   (and its texture images beside it)
      mapped.ply   the same vertices in the same order, at their images on the target
      filled.ply   with fill_holes=True: the cut source with its holes filled
      report.txt   the filter's log (also when it fails)
      figures.json the figures
    Returns a MapResult(figures, log, meshset); raises pymeshlab.PyMeshLabException when
    the filter fails (or a mesh cannot be read)."""
    os.makedirs(outdir, exist_ok=True)
    for name in ("cut.ply", "mapped.ply", "filled.ply", "report.txt", "figures.json"):
        path = os.path.join(outdir, name)
        if os.path.exists(path):
            os.remove(path)
    ms = pymeshlab.MeshSet()
    log = []
    try:
        ms.load_new_mesh(os.path.abspath(source))  # layer 0; its path finds the .pp beside it
        ms.load_new_mesh(os.path.abspath(target))  # layer 1
        started = time.perf_counter()
        figures = map_meshes(ms, 0, 1, progress=progress, log=log, **parameters)
        wall = time.perf_counter() - started
    except pymeshlab.PyMeshLabException as e:
        if not log:
            log.append(f"error: {e}")
        raise
    finally:
        with open(os.path.join(outdir, "report.txt"), "w") as f:
            f.write("".join(line + "\n" for line in log))
    layers = [(2, "cut.ply", {"__ca_vp__targetposition": True}), (3, "mapped.ply", {})]
    if parameters.get("fill_holes") and ms.mesh_id_exists(4):
        layers.append((4, "filled.ply", {}))
    for layer, name, extra in layers:
        ms.set_current_mesh(layer)
        ms.save_current_mesh(os.path.join(outdir, name), save_vertex_quality=True,
                             save_wedge_texcoord=ms.current_mesh().has_wedge_tex_coord(), **extra)
    with open(os.path.join(outdir, "figures.json"), "w") as f:
        json.dump(dict(figures, wall_s=wall), f, indent=1, sort_keys=True)
    return MapResult(figures, log, ms)
