"""The `eulermap` command.

    eulermap map SOURCE TARGET OUTDIR [filter options]
    eulermap batch TEMPLATE SHAPE... --out DIR [filter options] [batch options]
    eulermap batch --pairs PAIRS.csv --out DIR [...]

The filter options are the filter's parameters, as pymeshlab lists them
(--grid-resolution N, --steps N, --alpha X, --align none, --fill-holes, ...); --grid and
--steps are short for the first two. `eulermap map` shows a progress bar over the
filter's stages (from the progress reports the filter sends through pymeshlab's log),
then the filter's report; `eulermap batch` one over the pairs.
"""
import argparse
import contextlib
import os
import sys


def _add_filter_options(parser):
    from . import parameters
    group = parser.add_argument_group("filter parameters (defaults: the filter's)")
    for name, (kind, default) in parameters().items():
        flags = ["--" + name.replace("_", "-")]
        if name == "grid_resolution":
            flags.append("--grid")
        if kind is bool:
            group.add_argument(*flags, dest=name, action=argparse.BooleanOptionalAction, default=None,
                               help=f"(default: {'on' if default else 'off'})")
        else:
            group.add_argument(*flags, dest=name, type=kind, default=None, metavar=name.upper().split("_")[-1],
                               help=f"(default: {default!r})")
    return list(parameters())


def _chosen(args, names):
    """The filter parameters given on the command line (the rest keep the filter's defaults)."""
    return {n: getattr(args, n) for n in names if getattr(args, n) is not None}


def _map(args, names):
    import pymeshlab

    from . import map_files, progress_bar
    from ._mapping import failure_message
    for f in (args.source, args.target):
        if not os.path.isfile(f):
            print(f"eulermap map: no such mesh file: {f}", file=sys.stderr)
            return 2
    bar = contextlib.nullcontext() if args.no_progress else progress_bar()
    try:
        with bar as progress:
            result = map_files(args.source, args.target, args.outdir, progress=progress, **_chosen(args, names))
    except pymeshlab.PyMeshLabException as e:
        report = os.path.join(args.outdir, "report.txt")
        if os.path.isfile(report) and not args.quiet:
            print(open(report).read(), end="")
        print(f"eulermap map: the map failed: {failure_message(e)}", file=sys.stderr)
        return 1
    if not args.quiet:
        print("\n".join(result.log))
    out = os.path.abspath(args.outdir)
    names_out = [n for n in ("cut.ply", "mapped.ply", "filled.ply", "report.txt", "figures.json")
                 if os.path.isfile(os.path.join(out, n))]
    print(f"wrote {', '.join(os.path.join(out, n) for n in names_out)}")
    return 0


def _batch(args, names):
    from . import batch
    try:
        jobs = batch.jobs_from_arguments(args.meshes, args.pairs, args.out, _chosen(args, names))
    except (ValueError, OSError) as e:
        print(f"eulermap batch: {e}", file=sys.stderr)
        return 2
    try:
        summary = batch.run(jobs, args.out, scheduler=args.scheduler, workers=args.workers,
                            threads_per_pair=args.threads_per_pair, retry_failed=args.retry_failed,
                            progress=not args.no_progress, thumbnails=not args.no_thumbnails)
    except KeyboardInterrupt:
        return 130
    except (RuntimeError, OSError) as e:  # no scheduler at that address, no worker
        print(f"eulermap batch: {e}", file=sys.stderr)
        return 2
    return 0 if all(r["status"] == "ok" for r in summary) else 1


def main(argv=None):
    parser = argparse.ArgumentParser(prog="eulermap", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True, metavar="{map,batch}")

    m = commands.add_parser("map", help="map one mesh onto another",
                            description="Maps SOURCE onto TARGET (a .pp picked-points file beside each gives "
                                        "named anchors) and writes OUTDIR/cut.ply, mapped.ply, report.txt and "
                                        "figures.json. Exits 1, with the filter's message, when the map fails.")
    m.add_argument("source")
    m.add_argument("target")
    m.add_argument("outdir")
    m.add_argument("--no-progress", action="store_true", help="no progress bar")
    m.add_argument("--quiet", "-q", action="store_true", help="do not print the filter's report")
    names = _add_filter_options(m)

    b = commands.add_parser(
        "batch", help="map many pairs on Dask workers",
        description="Maps each SHAPE onto TEMPLATE (or each pair of a CSV file with columns source,target "
                    "and optionally name), each pair in a worker process of a Dask cluster, into "
                    "DIR/pairs/<name>/ (the files of `eulermap map`, plus thumbnail.png and result.json), "
                    "and writes DIR/summary.csv and DIR/summary.html with every figure of each pair's "
                    "report. A pair whose result.json is there, for the same input files and parameters, is "
                    "not mapped again (so a second run resumes an interrupted one); a failing pair is "
                    "recorded with its message and the others go on. Exits 1 when any pair failed.")
    b.add_argument("meshes", nargs="*", metavar="TEMPLATE SHAPE", help="the template, then the shapes")
    b.add_argument("--pairs", metavar="CSV", help="pairs to map instead: columns source,target[,name]")
    b.add_argument("--out", required=True, metavar="DIR", help="output folder")
    b.add_argument("--scheduler", metavar="ADDRESS",
                   help="a running Dask scheduler (tcp://host:8786); its workers need eulermap installed and "
                        "the same paths (default: a LocalCluster on this machine)")
    b.add_argument("--workers", type=int, default=None, metavar="N",
                   help="LocalCluster worker processes (default: cores / threads-per-pair)")
    b.add_argument("--threads-per-pair", type=int, default=1, metavar="K",
                   help="OpenMP threads each LocalCluster worker gives its pair (default 1)")
    b.add_argument("--retry-failed", action="store_true", help="map the pairs recorded as failed again")
    b.add_argument("--no-thumbnails", action="store_true", help="no pictures in the summary page")
    b.add_argument("--no-progress", action="store_true", help="no progress bar")
    _add_filter_options(b)

    args = parser.parse_args(argv)
    if args.command == "map":
        return _map(args, names)
    return _batch(args, names)


if __name__ == "__main__":
    sys.exit(main())
