#!/usr/bin/env python3
"""The bad-input corpus of issue 13 (tests/corpus/cases.py) in both real hosts.

Run after building and installing the plugin (tests/run does both; tests/corpus/run calls
this):
    python3 tests/corpus/run_corpus.py [-k SUBSTRING] [--host meshlabserver|pymeshlab] [-j 2]

Every case runs in each host in its own process, under a memory limit (prlimit --as, 6 GiB)
and a timeout (60 s), at most two at a time:
  - meshlabserver 2020.09 (Debian's, with the installed plugin) on ASCII PLY files written
    for the case, under one private Xvfb display; the new layers saved as PLY;
  - pymeshlab 2025.7.post1 (.venv) with the built 2025 flavour, through
    tests/corpus/pymeshlab_host.py, on the case's arrays (pymeshlab.Mesh), which reach the
    filter as they are.
Each run passes when the filter either fails cleanly with the expected message or
succeeds sanely (cases.py says which: cut layer with faces, no NaN or Inf in an output
vertex, figures in range, the expected 'warning: ' / 'repaired: ' log lines, a warning
whenever coverage or on-surface rate is below 90%), the input files are unchanged
(checksums; in pymeshlab the input layers too), and the process ended by itself: no
signal, no crash exit code, no timeout.

Prints 'PASS name [host]: message or figures' or 'FAIL name [host]: why' per run and,
last, 'N passed, N failed'; exits 1 when any failed. Inputs, logs and outputs of each
run stay in out/corpus/cases/NAME/; the outcomes table goes to out/corpus/outcomes.md.
"""
import argparse
import concurrent.futures
import hashlib
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path[:0] = [HERE, os.path.join(ROOT, "tests", "meshlab")]
import cases as corpus  # noqa: E402
import meshes  # noqa: E402  the MeshLab tests' mesh reader
import meshlab_host  # noqa: E402  shared with the MeshLab tests: mlx_text, filter_log, failure_message, CRASH_CODES

SAMPLES = os.path.join(ROOT, "samples")
OUT = os.path.join(ROOT, "out", "corpus")
VENV_PYTHON = os.path.join(ROOT, ".venv", "bin", "python")
PLUGIN_2025 = os.environ.get("EULERMAP_PLUGIN") or os.path.join(ROOT, "build", "filter_eulermap",
                                                                "libfilter_eulermap_2025.so")
MEMORY_LIMIT = int(os.environ.get("CORPUS_MEMORY_LIMIT", 6 << 30))  # bytes of address space per run
TIMEOUT = int(os.environ.get("CORPUS_TIMEOUT", 60))  # seconds per run
HOSTS = ("meshlabserver", "pymeshlab")
CRASH_CODES = meshlab_host.CRASH_CODES
LOW = 0.9  # below this coverage or on-surface rate a success must warn (core/pipeline.cpp, WarnOnFailure)


# ---------------------------------------------------------------- writing a case's inputs


def _ply_number(x):
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    return repr(float(x))


def write_ply(path, mesh):
    with open(path, "w") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(mesh.verts)}\nproperty double x\nproperty double y\n"
                f"property double z\nelement face {len(mesh.faces)}\nproperty list uchar int vertex_indices\n"
                "end_header\n")
        for v in mesh.verts:
            f.write(" ".join(_ply_number(x) for x in v) + "\n")
        for t in mesh.faces:
            f.write("3 %d %d %d\n" % tuple(t))


def prepare(case):
    """Writes the case's inputs into out/corpus/cases/NAME/inputs; returns what the hosts
    need: mesh files, arrays, anchor files, the files to checksum."""
    base = os.path.join(OUT, "cases", case.name)
    shutil.rmtree(base, ignore_errors=True)
    inputs = os.path.join(base, "inputs")
    os.makedirs(inputs)
    job = {"dir": base, "meshes": {}, "files": []}
    for role in ("source", "target"):
        m = getattr(case, role)
        if isinstance(m, corpus.Sample):
            path = os.path.join(SAMPLES, m.file)
            job["meshes"][role] = {"file": path}
        else:
            path = os.path.join(inputs, role + ".ply")
            write_ply(path, m)
            arrays = os.path.join(inputs, role + ".json")
            with open(arrays, "w") as f:
                json.dump({"verts": [list(v) for v in m.verts], "faces": [list(t) for t in m.faces]}, f)
            job["meshes"][role] = {"file": path, "arrays": arrays}
            job["files"].append(arrays)
        job["files"].append(path)
    params = dict(corpus.DEFAULTS, **case.params)
    for role, pp in case.anchors.items():
        if isinstance(pp, corpus.Sample):
            path = os.path.join(SAMPLES, pp.file)
        else:
            path = os.path.join(inputs, role + ".pp")
            with open(path, "w") as f:
                f.write(pp)
        params[role + "_anchors"] = path
        job["files"].append(path)
    job["params"] = params
    return job


def checksums(files):
    out = {}
    for p in files:
        with open(p, "rb") as f:
            out[p] = hashlib.sha256(f.read()).hexdigest()
    return out


# ---------------------------------------------------------------- the hosts


def run_limited(cmd, log_path, env=None):
    """Runs cmd in its own session under the memory limit and the timeout; returns (exit
    status, negative for a signal, or None when timed out; seconds; peak resident MiB)."""
    t0 = time.time()
    with open(log_path, "w") as out:
        p = subprocess.Popen(["prlimit", f"--as={MEMORY_LIMIT}", "--"] + cmd, stdout=out, stderr=subprocess.STDOUT,
                             env=env, start_new_session=True)
        timed_out = False
        while True:  # wait4: the exit status and this process's own peak memory (prlimit execs cmd)
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid:
                break
            if time.time() - t0 > TIMEOUT:
                os.killpg(p.pid, signal.SIGKILL)  # the session this run started, and nothing else
                pid, status, usage = os.wait4(p.pid, 0)
                timed_out = True
                break
            time.sleep(0.05)
        p.returncode = os.waitstatus_to_exitcode(status)
    return (None if timed_out else p.returncode), time.time() - t0, usage.ru_maxrss / 1024


def parse_figures(lines):
    """The figures of meshlabserver's log (the same as pymeshlab returns), as shares."""
    fig = {}
    for line in lines:
        m = re.match(r"map quality: on-surface ([-\w.]+)%, coverage ([-\w.]+)%, flipped area ([-\w.]+)%, "
                     r"longest mapped edge ([-\w.]+) cells, anchor error ([-\w.]+) cells, mean distortion ([-\w.]+)",
                     line)
        if m:
            v = [float(x) for x in m.groups()]
            fig.update(on_surface_rate=v[0] / 100, coverage=v[1] / 100, flipped_area_share=v[2] / 100,
                       longest_edge_cells=v[3], anchor_error_cells=v[4], mean_distortion=v[5])
        m = re.match(r"cut source: .*; (\d+) vertices \(.*\), (\d+) faces", line)
        if m:
            fig.update(cut_vertices=int(m.group(1)), cut_faces=int(m.group(2)))
    return fig


def layer_figures(path):
    m = meshes.read_mesh(path)
    bad = sum(1 for v in m.verts if not all(math.isfinite(x) for x in v))
    quality = sum(1 for q in m.vertex.get("quality", []) if not math.isfinite(q))
    return {"vertices": len(m.verts), "faces": len(m.faces), "nonfinite_vertices": bad, "nonfinite_quality": quality}


def run_meshlabserver(case, job, display):
    d = os.path.join(job["dir"], "meshlabserver")
    os.makedirs(d, exist_ok=True)
    script = os.path.join(d, "script.mlx")
    with open(script, "w") as f:
        f.write(meshlab_host.mlx_text(**job["params"]))
    log = os.path.join(d, "meshlabserver.log")
    cut, mapped = os.path.join(d, "cut.ply"), os.path.join(d, "mapped.ply")
    cmd = ["meshlabserver", "-l", log, "-i", job["meshes"]["source"]["file"], job["meshes"]["target"]["file"],
           "-s", script, "-o", cut, "-l", "2", "-m", "vq", "-o", mapped, "-l", "3", "-m", "vq"]
    env = dict(os.environ, DISPLAY=display)
    rc, seconds, peak = run_limited(cmd, os.path.join(d, "meshlabserver.out"), env)
    text = open(log, errors="replace").read() if os.path.exists(log) else ""
    out_text = open(os.path.join(d, "meshlabserver.out"), errors="replace").read()
    lines = meshlab_host.filter_log(text)
    res = {"rc": rc, "seconds": seconds, "peak_mib": peak, "log": lines, "tail": (text or out_text).splitlines()[-8:]}
    if "Assertion" in out_text:
        res["assertion"] = next(l for l in out_text.splitlines() if "Assertion" in l)
    failed = [l for l in text.splitlines() if l.startswith(meshlab_host.FAILED_PREFIX)]
    if rc == 0:
        res["outcome"] = "success"
        res["figures"] = parse_figures(lines)
        for name, path in (("cut", cut), ("mapped", mapped)):
            res[name] = layer_figures(path) if os.path.isfile(path) else None
    elif rc == 255 and failed:
        res.update(outcome="error", message=failed[0][len(meshlab_host.FAILED_PREFIX):])
    else:
        res["outcome"] = "other"
    return res


def run_pymeshlab(case, job):
    d = os.path.join(job["dir"], "pymeshlab")
    os.makedirs(d, exist_ok=True)
    result = os.path.join(d, "result.json")
    spec = os.path.join(d, "spec.json")
    with open(spec, "w") as f:
        json.dump({"plugin": PLUGIN_2025, "source": job["meshes"]["source"], "target": job["meshes"]["target"],
                   "params": job["params"], "result": result}, f)
    # apply_logged's temporary log file lands in d, where it stays when the process is killed
    env = dict(os.environ, TMPDIR=d)
    rc, seconds, peak = run_limited([VENV_PYTHON, os.path.join(HERE, "pymeshlab_host.py"), spec],
                              os.path.join(d, "python.out"), env)
    res = json.load(open(result)) if os.path.isfile(result) else {"stage": "not started"}
    res.update(rc=rc, seconds=seconds, peak_mib=peak)
    out_text = open(os.path.join(d, "python.out"), errors="replace").read()
    res["tail"] = (res.get("log") or out_text.splitlines())[-8:]
    if rc != 0 or res.get("stage") != "done":
        res["outcome"] = "host_error" if res.get("outcome") == "host_error" else "other"
        left = [os.path.join(d, f) for f in os.listdir(d) if f.startswith("eulermap-log-")]
        partial = open(left[0], errors="replace").read().splitlines() if left else []
        res["tail"] = [f"(stage {res.get('stage')})"] + out_text.splitlines()[-4:] + partial[-8:]
    elif res["outcome"] == "error":
        # PyMeshLabException's text: 'Failed to apply filter: NAME\nDetails: MESSAGE' or so
        msg = " ".join(res["message"].split("\n"))
        res["message"] = msg.split("Details: ", 1)[1] if "Details: " in msg else msg
    return res


# ---------------------------------------------------------------- judging a run


def _pct(x):
    return f"{100 * x:.1f}%"


def _has(text, t):
    """t in text; a tuple t: any of its texts."""
    return any(x in text for x in t) if isinstance(t, tuple) else t in text


def judge(case, host, res, files_changed):
    """(passed, one-line message)."""
    e = case.expect
    tail = " | ".join(res.get("tail", []))[-600:]
    if res["rc"] is None:
        return False, f"timeout after {TIMEOUT} s (killed); last log lines: {tail}"
    if res["rc"] in CRASH_CODES or res["rc"] < 0:
        return False, f"crashed (exit {res['rc']}); last log lines: {tail}"
    if res.get("assertion"):
        return False, f"assertion failed: {res['assertion']}"
    if res["outcome"] not in ("success", "error"):
        return False, f"ended neither with a map nor with the filter's message (exit {res['rc']}): " \
                      f"{res.get('message', '')[-400:]} last lines: {tail}"
    if files_changed:
        return False, "input files changed: " + ", ".join(os.path.basename(p) for p in files_changed)
    if host == "pymeshlab" and not res.get("inputs_unchanged", False):
        return False, "the filter changed the input layers"

    if res["outcome"] == "error":
        msg = res["message"]
        if host == "pymeshlab" and res.get("layers") != 2:
            return False, f"a failed run left {res.get('layers')} layers: {msg}"
        if isinstance(e, corpus.Success):
            return False, f"failed, expected a success: {msg}"
        missing = [t for t in (e.texts if isinstance(e, corpus.Error) else e.error) if not _has(msg, t)]
        if missing:
            return False, f"message lacks {missing}: {msg}"
        return True, "error: " + msg

    # a success
    log, fig = res.get("log", []), res.get("figures", {})
    warnings = [l for l in log if l.startswith("warning: ")]
    repairs = [l for l in log if l.startswith("repaired: ")]
    summary = (f"cut {fig.get('cut_faces')} f; coverage {_pct(fig.get('coverage', math.nan))}, on-surface "
               f"{_pct(fig.get('on_surface_rate', math.nan))}, anchor error {fig.get('anchor_error_cells', math.nan):.2f}"
               f" cells" + "".join("; " + l for l in repairs + warnings))
    problems = []
    if isinstance(e, corpus.Error):
        problems.append(f"succeeded, expected the error {e.texts}")
    cut, mapped = res.get("cut"), res.get("mapped")
    if not cut or not mapped:
        problems.append("no cut or mapped layer came out")
    else:
        if cut["faces"] == 0:
            problems.append("the cut layer has no faces")
        if cut["nonfinite_vertices"] or mapped["nonfinite_vertices"]:
            problems.append(f"NaN/Inf in output vertices (cut {cut['nonfinite_vertices']}, "
                            f"mapped {mapped['nonfinite_vertices']})")
        if cut.get("nonfinite_quality") or mapped.get("nonfinite_quality"):
            problems.append(f"NaN/Inf in output vertex quality (cut {cut.get('nonfinite_quality')}, "
                            f"mapped {mapped.get('nonfinite_quality')})")
        if cut["vertices"] != mapped["vertices"]:
            problems.append(f"cut ({cut['vertices']} v) and mapped ({mapped['vertices']} v) differ")
        if fig.get("cut_faces") != cut["faces"]:
            problems.append(f"the report says {fig.get('cut_faces')} cut faces, the layer has {cut['faces']}")
    for key in ("coverage", "on_surface_rate", "flipped_area_share"):
        v = fig.get(key)
        if v is None or not (0 <= v <= 1):
            problems.append(f"{key} {v} not in [0, 1]")
    for key, v in fig.items():
        if isinstance(v, (int, float)) and not math.isfinite(v):
            problems.append(f"figure {key} is {v}")
    for key in ("anchor_error_cells", "mean_distortion", "longest_edge_cells"):
        if key in fig and fig[key] < 0:
            problems.append(f"{key} {fig[key]} < 0")
    wanted = e.warnings if isinstance(e, (corpus.Success, corpus.Either)) else []
    for w in wanted:
        if not any(w in l for l in warnings):
            problems.append(f"no 'warning: ' line with '{w}'")
    for r in (e.repairs if isinstance(e, corpus.Success) else []):
        if not any(r in l for l in repairs):
            problems.append(f"no 'repaired: ' line with '{r}'")
    if fig.get("coverage", 1) < LOW and not any("the map reaches only" in l for l in warnings):
        problems.append(f"coverage {_pct(fig['coverage'])} without a warning")
    if fig.get("on_surface_rate", 1) < LOW and not any("reached the target" in l for l in warnings):
        problems.append(f"on-surface rate {_pct(fig['on_surface_rate'])} without a warning")
    for t in (e.log if isinstance(e, corpus.Success) else []):
        if not any(_has(l, t) for l in log):
            problems.append(f"no log line with '{t}'")
    if isinstance(e, (corpus.Success, corpus.Either)) and e.sane:
        if warnings:
            problems.append("a sane map expected, but the log warns")
        if fig.get("coverage", 0) < LOW or fig.get("on_surface_rate", 0) < LOW:
            problems.append("a sane map expected: coverage and on-surface rate of at least 90%")
    if problems:
        return False, "; ".join(problems) + " -- " + summary
    return True, "success: " + summary


# ---------------------------------------------------------------- the runner


def start_xvfb():
    """One private X display for every meshlabserver run (they need a GL context).
    Returns (process, DISPLAY)."""
    r, w = os.pipe()
    p = subprocess.Popen(["Xvfb", "-displayfd", str(w), "-screen", "0", "640x480x24", "-nolisten", "tcp"],
                         pass_fds=(w,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(w)
    number = b""
    with os.fdopen(r, "rb") as f:
        while not number.endswith(b"\n"):
            c = f.read(1)
            if not c:
                break
            number += c
    if not number.strip():
        p.kill()
        raise RuntimeError("Xvfb did not start")
    return p, ":" + number.decode().strip()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("-k", default="", help="run only the cases whose name contains this")
    parser.add_argument("--host", choices=HOSTS, action="append", help="run in this host only (repeatable)")
    parser.add_argument("-j", type=int, default=2, help="runs at a time (default 2)")
    args = parser.parse_args()
    hosts = args.host or list(HOSTS)
    t0 = time.time()
    os.makedirs(OUT, exist_ok=True)

    problems = []
    if "meshlabserver" in hosts and not os.path.isfile(meshlab_host.PLUGIN):
        problems.append(f"{meshlab_host.PLUGIN} missing: cmake --install build")
    if "pymeshlab" in hosts:
        for need in (VENV_PYTHON, PLUGIN_2025):
            if not os.path.exists(need):
                problems.append(f"{need} missing: bash setup/build.sh")
    if problems:
        for p in problems:
            print("FAIL corpus: " + p)
        print("0 passed, 1 failed")
        return 1

    built = os.path.join(ROOT, "build", "filter_eulermap", "libfilter_eulermap.so")
    plugins = []  # which builds the table reflects
    if "meshlabserver" in hosts:
        installed = meshlab_host.build_id(meshlab_host.PLUGIN)
        plugins.append(f"meshlabserver: {meshlab_host.PLUGIN} (build ID {installed[:12]})")
        if os.path.isfile(built) and meshlab_host.build_id(built) != installed:
            print(f"note: the installed {meshlab_host.PLUGIN} is not build/'s {os.path.basename(built)}: "
                  "meshlabserver runs the installed one (cmake --install build)", flush=True)
    if "pymeshlab" in hosts:
        plugins.append(f"pymeshlab: {PLUGIN_2025} (build ID {meshlab_host.build_id(PLUGIN_2025)[:12]})")
    all_cases = [c for c in corpus.cases(SAMPLES) if args.k in c.name]
    jobs = {c.name: prepare(c) for c in all_cases}
    xvfb, display = start_xvfb() if "meshlabserver" in hosts else (None, None)
    runs = [(c, h) for c in all_cases for h in hosts if h in c.hosts]
    results = {}
    lock = threading.Lock()
    counts = [0, 0]

    def one(case, host):
        job = jobs[case.name]
        before = checksums(job["files"])
        try:
            res = run_meshlabserver(case, job, display) if host == "meshlabserver" else run_pymeshlab(case, job)
            after = checksums(job["files"])
            changed = [p for p in before if before[p] != after.get(p)]
            ok, message = judge(case, host, res, changed)
            for role in ("source", "target"):  # pymeshlab refuses an empty vertex matrix: that mesh came by file
                if res.get(role + "_from") == "file" and isinstance(getattr(case, role), corpus.Mesh):
                    message += f" [{role} loaded from its PLY: pymeshlab takes no empty arrays]"
        except Exception as ex:  # a bug in the runner, or a missing tool
            res, ok, message = {"outcome": "runner_error", "seconds": 0}, False, f"runner error: {ex!r}"
        with lock:
            results[(case.name, host)] = (ok, message, res)
            counts[0 if ok else 1] += 1
            print(f"{'PASS' if ok else 'FAIL'} {case.name} [{host}]: {message} ({res.get('seconds', 0):.1f} s, "
                  f"{res.get('peak_mib', 0):.0f} MiB)", flush=True)

    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.j)) as pool:
            for f in [pool.submit(one, c, h) for c, h in runs]:
                f.result()
    finally:
        if xvfb:
            xvfb.terminate()
            xvfb.wait()
    seconds = time.time() - t0
    write_table(all_cases, hosts, results, seconds, plugins)
    print(f"corpus: {len(all_cases)} cases, {len(runs)} runs in {seconds:.0f} s; table in "
          f"{os.path.relpath(os.path.join(OUT, 'outcomes.md'), ROOT)}")
    print(f"{counts[0]} passed, {counts[1]} failed")
    return 1 if counts[1] else 0


def write_table(all_cases, hosts, results, seconds, plugins):
    def cell(text):
        return text.replace("|", "\\|").replace("\n", " ")

    rows = ["# Bad-input corpus (issue 13): outcomes", "",
            f"{len(all_cases)} cases; {sum(ok for ok, _, _ in results.values())} of {len(results)} runs passed; "
            f"{seconds:.0f} s in all (2 at a time). Grid 24, 8 steps unless the case says otherwise; each run in "
            f"its own process under prlimit --as={MEMORY_LIMIT >> 30} GiB and a {TIMEOUT} s timeout. Plugins: "
            + "; ".join(plugins) + ".", "",
            "| case | input | host | result | outcome | message or figures | s | peak MiB |",
            "|---|---|---|---|---|---|---|---|"]
    for c in all_cases:
        for h in hosts:
            if (c.name, h) not in results:
                continue
            ok, message, res = results[(c.name, h)]
            outcome = res.get("outcome", "?")
            if res.get("rc") is None and "timeout" in message:
                outcome = "timeout"
            elif isinstance(res.get("rc"), int) and (res["rc"] in CRASH_CODES or res["rc"] < 0):
                outcome = f"crash (exit {res['rc']})"
            rows.append(f"| {c.name} | {cell(c.what)} | {h} | {'PASS' if ok else 'FAIL'} | {outcome} | "
                        f"{cell(message)} | {res.get('seconds', 0):.1f} | {res.get('peak_mib', 0):.0f} |")
    with open(os.path.join(OUT, "outcomes.md"), "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    sys.exit(main())
