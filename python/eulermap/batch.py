"""Collections: many pairs mapped on Dask (dask.distributed), one pair a task.

Each pair runs in a worker process of the cluster (a LocalCluster of worker processes by
default, or the cluster of a running scheduler), through map_files(), into
OUT/pairs/<name>.partial/, which becomes OUT/pairs/<name>/ once its result.json (status,
message, figures, the key of its inputs) is written, by the worker itself: a pair is
finished exactly when OUT/pairs/<name>/result.json exists, whatever happens to the client.
A second run skips the finished pairs whose key (the contents of both mesh files and of the
.pp files beside them, the parameters, eulermap's version and plugin) is unchanged, and rebuilds
OUT/summary.csv and OUT/summary.html from all the pairs' result.json.

A pair that fails (the filter's message, a file pymeshlab cannot read, a task that a worker
could not run or died running)
is recorded as failed with its message; the others go on. Failed pairs are finished too
(mapped again with --retry-failed, or when their inputs change).
"""
import csv
import hashlib
import html
import json
import os
import shutil
import socket
import sys
import time
import traceback

SUMMARY_FIRST = ["name", "status", "message", "source", "target", "wall_s"]


def _stem(path):
    return os.path.splitext(os.path.basename(path))[0]


def _plugin_digest():
    from . import PLUGIN
    with open(PLUGIN, "rb") as f:
        return hashlib.sha256(f.read()).digest()


def _key(source, target, parameters, plugin_digest):
    """What a finished pair's result depends on: the input files (and the .pp beside each,
    the anchors the filter reads), the parameters, eulermap's version and its plugin."""
    from . import __version__
    h = hashlib.sha256(plugin_digest)
    for path in (source, target):
        for f in (path, os.path.splitext(path)[0] + ".pp"):
            if os.path.isfile(f):
                with open(f, "rb") as data:
                    h.update(hashlib.sha256(data.read()).digest())
            else:
                h.update(b"-")
    h.update(json.dumps(parameters, sort_keys=True).encode())
    h.update(__version__.encode())
    return h.hexdigest()[:16]


def jobs_from_arguments(meshes, pairs_csv, out, parameters):
    """The pairs to map: each of meshes[1:] onto meshes[0], or the rows of pairs_csv
    (columns source, target, optionally name; relative paths are relative to the CSV).
    Each job is a dict: name, source, target (absolute paths), dir, parameters."""
    pairs = []
    if pairs_csv:
        if meshes:
            raise ValueError("give either TEMPLATE SHAPE... or --pairs CSV, not both")
        base = os.path.dirname(os.path.abspath(pairs_csv))
        with open(pairs_csv, newline="") as f:
            for i, row in enumerate(csv.DictReader(f), start=2):
                if not row.get("source") or not row.get("target"):
                    raise ValueError(f"{pairs_csv}:{i}: a row needs source and target")
                pairs.append((os.path.join(base, row["source"]), os.path.join(base, row["target"]),
                              (row.get("name") or "").strip()))
    else:
        if len(meshes) < 2:
            raise ValueError("give a TEMPLATE and at least one SHAPE (or --pairs CSV)")
        pairs = [(shape, meshes[0], "") for shape in meshes[1:]]
    jobs, names = [], set()
    for source, target, name in pairs:
        name = name or f"{_stem(source)}_to_{_stem(target)}"
        unique, n = name, 2
        while unique in names:
            unique, n = f"{name}_{n}", n + 1
        names.add(unique)
        jobs.append(dict(name=unique, source=os.path.abspath(source), target=os.path.abspath(target),
                         dir=os.path.join(os.path.abspath(out), "pairs", unique), parameters=dict(parameters)))
    return jobs


def run_pair(job, thumbnails=True):
    """One pair, in a worker: maps it into job['dir'] and returns its result (the dict
    written to result.json). Never raises for a failing pair: the failure is the result."""
    import pymeshlab

    from ._mapping import failure_message, map_files

    final, partial = job["dir"], job["dir"] + ".partial"
    shutil.rmtree(partial, ignore_errors=True)
    os.makedirs(partial)
    result = dict(name=job["name"], source=job["source"], target=job["target"], key=job["key"],
                  parameters=job["parameters"], worker=f"{socket.gethostname()}:{os.getpid()}")
    started = time.perf_counter()
    try:
        for path in (job["source"], job["target"]):
            if not os.path.isfile(path):
                raise FileNotFoundError(f"no such mesh file: {path}")
        mapped = map_files(job["source"], job["target"], partial, **job["parameters"])
        result.update(status="ok", message="", figures=mapped.figures,
                      warnings=[line for line in mapped.log if line.startswith("warning:")])
        if thumbnails:
            from .thumbnail import render_pair
            try:
                render_pair(mapped.meshset, os.path.join(partial, "thumbnail.png"))
            except Exception as e:  # a picture is not worth failing a pair
                result["message"] = f"no thumbnail: {e}"
    except (pymeshlab.PyMeshLabException, OSError, ImportError) as e:
        result.update(status="failed", message=failure_message(e), figures={})
    except Exception as e:
        result.update(status="failed", message=f"{type(e).__name__}: {e}", figures={},
                      traceback=traceback.format_exc())
    result["wall_s"] = round(time.perf_counter() - started, 3)
    with open(os.path.join(partial, "result.json"), "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
    shutil.rmtree(final, ignore_errors=True)
    os.replace(partial, final)
    return result


def _record_lost(job, message):
    """A pair whose task ended without a result (its worker died, or could not run
    run_pair): recorded as failed."""
    os.makedirs(job["dir"], exist_ok=True)
    result = dict(name=job["name"], source=job["source"], target=job["target"], key=job["key"],
                  parameters=job["parameters"], status="failed", message=message, figures={}, wall_s=None)
    with open(os.path.join(job["dir"], "result.json"), "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
    return result


def finished(job):
    """The pair's recorded result when it is finished for these inputs, else None."""
    path = os.path.join(job["dir"], "result.json")
    try:
        with open(path) as f:
            result = json.load(f)
    except (OSError, ValueError):
        return None
    return result if result.get("key") == job["key"] else None


def _local_cluster(workers, threads_per_pair):
    from distributed import LocalCluster
    cores = os.cpu_count() or 1
    workers = workers or max(1, cores // max(1, threads_per_pair))
    # One task at a time per worker process, and that many threads for its filter (the
    # core's team follows OMP_NUM_THREADS, read by libgomp when the worker starts, hence
    # the worker's environment).
    env = {"OMP_NUM_THREADS": str(threads_per_pair)}
    return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                        env=env, silence_logs=40)


def run(jobs, out, scheduler=None, workers=None, threads_per_pair=1, retry_failed=False, progress=True,
        thumbnails=True, log=sys.stderr):
    """Maps the jobs that are not finished on Dask, writes OUT/summary.csv and
    OUT/summary.html over all jobs, and returns the results (one dict per job, in the
    jobs' order). `log` gets a line per pair."""
    from distributed import Client, as_completed
    from tqdm import tqdm

    os.makedirs(os.path.join(out, "pairs"), exist_ok=True)
    results, todo = {}, []
    digest = _plugin_digest()
    for job in jobs:
        job["key"] = _key(job["source"], job["target"], job["parameters"], digest)
        done = finished(job)
        if done and not (retry_failed and done["status"] != "ok"):
            results[job["name"]] = done
        else:
            todo.append(job)
    print(f"eulermap batch: {len(jobs)} pairs, {len(results)} finished before (skipped), {len(todo)} to map",
          file=log)
    if todo:
        cluster = None
        try:
            cluster = None if scheduler else _local_cluster(workers, threads_per_pair)
            with Client(scheduler or cluster) as client:
                try:
                    client.wait_for_workers(1, timeout=120)
                except (TimeoutError, OSError) as e:
                    raise RuntimeError(f"the Dask scheduler {client.scheduler.address} has no worker after "
                                       f"2 minutes: start some (dask worker {client.scheduler.address})") from e
                print(f"eulermap batch: Dask scheduler {client.scheduler.address}, "
                      f"{len(client.scheduler_info()['workers'])} workers", file=log)
                futures = {client.submit(run_pair, job, thumbnails, key=f"eulermap-{job['name']}-{job['key']}",
                                         pure=False): job for job in todo}
                with tqdm(total=len(todo), unit="pair", file=sys.stderr, disable=not progress) as bar:
                    for future in as_completed(futures):
                        job = futures[future]
                        try:
                            result = future.result()
                        except Exception as e:  # the task itself was lost (e.g. KilledWorker)
                            result = _record_lost(job, f"its task failed on the worker (not in the filter): "
                                                       f"{type(e).__name__}: {e}")
                        results[job["name"]] = result
                        bar.write(_line(result), file=log)
                        bar.update(1)
        except KeyboardInterrupt:
            print(f"eulermap batch: interrupted; {len(results)} of {len(jobs)} pairs finished: the same command "
                  f"maps the others", file=log)
            raise
        finally:
            if cluster is not None:
                cluster.close()
    ordered = [results[job["name"]] for job in jobs]
    write_summary(ordered, out)
    failed = sum(r["status"] != "ok" for r in ordered)
    print(f"eulermap batch: {len(ordered) - failed} ok, {failed} failed; summary in "
          f"{os.path.join(os.path.abspath(out), 'summary.csv')} and summary.html", file=log)
    return ordered


def _line(result):
    """One line about a finished pair."""
    f = result["figures"]
    if result["status"] != "ok":
        return f"{result['name']}: FAILED: {result['message']}"
    return (f"{result['name']}: ok, coverage {100 * f['coverage']:.2f}%, on-surface {100 * f['on_surface_rate']:.2f}%, "
            f"{result['wall_s']:.1f} s")


def _figure_names(results):
    names = []
    for r in results:
        for k in r.get("figures", {}):
            if k not in names:
                names.append(k)
    return sorted(names)


def write_summary(results, out):
    """OUT/summary.csv (one row per pair: name, status, message, source, target, wall_s,
    then every figure of the report, empty for a failed pair) and OUT/summary.html (the same
    table with each pair's thumbnail and links to its files)."""
    figures = _figure_names(results)
    rows = []
    for r in results:
        row = {k: r.get(k, "") for k in SUMMARY_FIRST}
        row["message"] = (row["message"] or "").replace("\n", " ")
        row.update({k: r.get("figures", {}).get(k, "") for k in figures})
        rows.append(row)
    with open(os.path.join(out, "summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=SUMMARY_FIRST + figures)
        w.writeheader()
        w.writerows(rows)

    def cell(v):
        if isinstance(v, float):
            return f"{v:.4g}"
        return html.escape(str(v))

    head = "".join(f"<th>{html.escape(k)}</th>" for k in ["picture"] + SUMMARY_FIRST + figures)
    body = []
    for r, row in zip(results, rows):
        pair = os.path.join("pairs", r["name"])
        thumb = os.path.join(out, pair, "thumbnail.png")
        picture = f'<img src="{html.escape(pair)}/thumbnail.png" alt="{html.escape(r["name"])}">' \
            if os.path.isfile(thumb) else ""
        links = " ".join(f'<a href="{html.escape(pair)}/{n}">{n}</a>'
                         for n in ("cut.ply", "mapped.ply", "report.txt") if os.path.isfile(os.path.join(out, pair, n)))
        cells = [picture] + [cell(row[k]) for k in SUMMARY_FIRST + figures]
        for i in (4, 5):  # source, target: the file's name, its path on hovering
            path = row[SUMMARY_FIRST[i - 1]]
            cells[i] = f'<span title="{html.escape(path)}">{html.escape(os.path.basename(path))}</span>'

        cells[1] = f"{cells[1]}<br><small>{links}</small>"
        if r.get("warnings"):  # the log's warning lines, beside the figures' count of them
            cells[3] = (cells[3] + "<br>" if cells[3] else "") + "<br>".join(
                f"<small>{html.escape(w)}</small>" for w in r["warnings"])
        cls = "ok" if r["status"] == "ok" else "failed"
        body.append(f'<tr class="{cls}">' + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    ok = sum(r["status"] == "ok" for r in results)
    page = f"""<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>eulermap batch: {ok} of {len(results)} pairs mapped</title>
<style>
body {{ font-family: sans-serif; font-size: 13px; }}
table {{ border-collapse: collapse; }}
td, th {{ border: 1px solid #ccc; padding: 3px 6px; text-align: right; white-space: nowrap; }}
th {{ background: #eee; position: sticky; top: 0; }}
tr.failed td {{ background: #fdd; }}
td:nth-child(2) {{ text-align: left; }}
td:nth-child(4) {{ white-space: normal; min-width: 24em; max-width: 40em; text-align: left; }}
</style></head><body>
<h1>eulermap batch: {ok} of {len(results)} pairs mapped</h1>
<p>Each picture: the source, the target, and the mapped source on the target coloured by distortion
(blue low, red high). Figures as the filter reports them (rates as shares, times in seconds);
all of them also in <a href="summary.csv">summary.csv</a>.</p>
<table><tr>{head}</tr>
{chr(10).join(body)}
</table></body></html>
"""
    with open(os.path.join(out, "summary.html"), "w") as f:
        f.write(page)
