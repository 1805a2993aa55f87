#!/usr/bin/python3
"""End-to-end checks of runs of the real apps. Used by CTest (tests/regression/CMakeLists.txt;
pile/pile_regression.py uses bad_values).

  finite      runs an input and checks that no CSV of its results holds NaN or inf
"""
import argparse
import math
import os
import shutil
import subprocess
import sys


def fail(message):
    sys.exit(f"run_safety: {message}")


def command(a, input_file, output=None, quiet=True):
    """`app run input_file [flags]` (only `app` without an input), through mpiexec at > 1 rank."""
    cmd = [a.app]
    if input_file:
        cmd += ["run", input_file] + (["--quiet"] if quiet else [])
        cmd += (["--no-plot"] if a.no_plot else []) + (["--output", output] if output else [])
    if a.ranks > 1:
        cmd = [a.mpiexec, "-n", str(a.ranks), "--allow-run-as-root", "--oversubscribe"] + cmd
    return cmd


def run(a, cmd):
    return subprocess.run(cmd, cwd=a.workdir, capture_output=True, text=True)


def bad_values(path):
    bad = []
    with open(path) as f:
        next(f, None)  # header
        for line_number, line in enumerate(f, start=2):
            for cell in line.strip().split(","):
                try:
                    value = float(cell)
                except ValueError:
                    continue  # a name (stage, status)
                if not math.isfinite(value):
                    bad.append(f"{path}:{line_number}: {line.strip()}")
                    break
    return bad


def check_finite(a):
    results = os.path.join(a.workdir, "results")
    shutil.rmtree(results, ignore_errors=True)
    p = run(a, command(a, a.good))
    if p.returncode != 0:
        fail(f"exited with {p.returncode}:\n{p.stdout}\n{p.stderr}")
    csvs = [os.path.join(r, f) for r, _, fs in os.walk(results) for f in fs if f.endswith(".csv")]
    if not csvs:
        fail(f"no CSV under {results}")
    bad = [b for c in sorted(csvs) for b in bad_values(c)]
    if bad:
        fail("NaN or inf in the results:\n" + "\n".join(bad[:20]))
    print(f"run_safety: {len(csvs)} CSV files, every value finite")


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("check", choices=["finite"])
    p.add_argument("--app", required=True)
    p.add_argument("--good", help="an input that runs to the end")
    p.add_argument("--workdir", required=True)
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--no-plot", action="store_true", help="pass --no-plot (the pile app)")
    a = p.parse_args()
    # The runs start in --workdir: paths given relative to here must still find their files.
    a.app, a.workdir = os.path.abspath(a.app), os.path.abspath(a.workdir)
    a.good = os.path.abspath(a.good)
    os.makedirs(a.workdir, exist_ok=True)
    {"finite": check_finite}[a.check](a)


if __name__ == "__main__":
    main()
