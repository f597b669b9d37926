#!/usr/bin/env python3
"""The files written from the parameter table (core/parameters.h), and their check.

  generated.py BENCH --write [README|SAMPLES]   rewrite those that differ (the build does this)
  generated.py BENCH --check [README|SAMPLES]   print what differs and how to regenerate; exit 1

BENCH is the eulermap_bench program. The files:
  - README.md's parameter list, between the lines
    <!-- parameters: eulermap_bench parameters --> and <!-- /parameters -->
    (`eulermap_bench parameters`);
  - the <filter> element of every samples/*.mlx, as `eulermap_bench mlx` writes it with the
    script's own values (meshlabserver 2020.09 needs every parameter of the filter, in order).
    A value the table no longer has is dropped; a parameter the script lacks gets its default.
    The script's comments and everything outside the element are kept.
"""
import difflib
import glob
import html
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
README = os.path.join(ROOT, "README.md")
SAMPLES = os.path.join(ROOT, "samples")
START, END = "<!-- parameters: eulermap_bench parameters -->", "<!-- /parameters -->"
FILTER = re.compile(r"<filter .*?</filter>", re.S)
PARAM = re.compile(r'<Param [^>]*name="(\w+)" value="([^"]*)"')
REGENERATE = ("cmake --build build --target generated_files   "
              "(or: python3 tests/bench/generated.py build/tests/bench/eulermap_bench --write)")


def bench(program, *args):
    return subprocess.run([program, *args], check=True, capture_output=True, text=True).stdout


def readme_text(program, text):
    """README.md's text with its parameter list as the table writes it."""
    lines = text.split("\n")
    start, end = lines.index(START), lines.index(END)
    listed = bench(program, "parameters").rstrip("\n").split("\n")
    return "\n".join(lines[:start + 1] + listed + lines[end:])


def script_text(program, text, known):
    """A sample script's text with its <filter> element as the table writes it for the
    script's own values."""
    values = [f"{name}={html.unescape(value)}" for name, value in PARAM.findall(FILTER.search(text).group(0))
              if name in known]
    element = FILTER.search(bench(program, "mlx", *values)).group(0)
    return FILTER.sub(lambda _: element, text, count=1)


def main(argv):
    if len(argv) < 3 or argv[2] not in ("--write", "--check") or argv[3:] not in ([], ["README"], ["SAMPLES"]):
        sys.exit(__doc__)
    program, write = argv[1], argv[2] == "--write"
    which = argv[3] if len(argv) > 3 else None
    known = {name for name, _ in PARAM.findall(bench(program, "mlx"))}
    files = ([README] if which in (None, "README") else []) + \
            (sorted(glob.glob(os.path.join(SAMPLES, "*.mlx"))) if which in (None, "SAMPLES") else [])
    differ = 0
    for path in files:
        with open(path) as f:
            text = f.read()
        want = readme_text(program, text) if path == README else script_text(program, text, known)
        if want == text:
            continue
        name = os.path.relpath(path, ROOT)
        if write:
            with open(path, "w") as f:
                f.write(want)
            print(f"{name}: rewritten from the parameter table (core/parameters.h)")
            continue
        differ += 1
        print(f"{name} differs from what the parameter table (core/parameters.h) writes:", file=sys.stderr)
        sys.stderr.writelines(difflib.unified_diff(text.splitlines(True), want.splitlines(True), name, name + " (table)"))
    if differ:
        print(f"Regenerate with: {REGENERATE}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main(sys.argv)
