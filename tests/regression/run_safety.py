#!/usr/bin/python3
"""End-to-end checks of runs of the real apps. Used by CTest (tests/regression/CMakeLists.txt;
pile/pile_regression.py uses bad_values).

  ends        a run that fails (on one rank only, at 2 ranks) exits non-zero within a time limit;
              without --bad, the app itself is the run (a test driver)
  finite      runs an input and checks that no CSV of its results holds NaN or inf
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import time


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


def run(a, cmd, timeout=None):
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, cwd=a.workdir, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        fail(f"{' '.join(cmd)} still running after {timeout} s (a rank waits forever?)")
    return p, time.monotonic() - start


def check_ends(a):
    p, seconds = run(a, command(a, a.bad), timeout=a.timeout)
    if p.returncode == 0:
        fail(f"exit code 0 for a failing run:\n{p.stdout}\n{p.stderr}")
    if not re.search(a.expect, p.stderr):
        fail(f"stderr does not match '{a.expect}':\n{p.stderr}")
    print(f"run_safety: every rank ended after {seconds:.1f} s with exit code {p.returncode}")


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
    p, _ = run(a, command(a, a.good))
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
    p.add_argument("check", choices=["ends", "finite"])
    p.add_argument("--app", required=True)
    p.add_argument("--good", help="an input that runs to the end")
    p.add_argument("--bad", help="an input whose run fails")
    p.add_argument("--workdir", required=True)
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--no-plot", action="store_true", help="pass --no-plot (the pile app)")
    p.add_argument("--expect", default=".", help="regex the failing run's stderr must match")
    p.add_argument("--timeout", type=float, default=30)
    a = p.parse_args()
    # The runs start in --workdir: paths given relative to here must still find their files.
    a.app, a.workdir = os.path.abspath(a.app), os.path.abspath(a.workdir)
    a.good, a.bad = [os.path.abspath(f) if f else f for f in (a.good, a.bad)]
    if a.check != "finite":
        shutil.rmtree(a.workdir, ignore_errors=True)
    os.makedirs(a.workdir, exist_ok=True)
    {"ends": check_ends, "finite": check_finite}[a.check](a)


if __name__ == "__main__":
    main()
