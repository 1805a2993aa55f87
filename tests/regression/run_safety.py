#!/usr/bin/python3
"""End-to-end checks that a run never loses or spoils results, and that an error ends every
MPI rank. Used by CTest (tests/regression/CMakeLists.txt and pile/CMakeLists.txt).

  keep        a good run, then a failing run into the same output folder: the good results
              stay byte-identical, the failed run's converged increments are in <out>.failed
              with a status.txt naming the stage and step that failed, nothing else is left
  unwritable  an output folder that cannot be created: a clear error before anything is solved
  ends        a run that fails (on one rank only, at 2 ranks) exits non-zero within a time limit;
              without --bad, the app itself is the run (a test driver)
  finite      runs an input and checks that no CSV of its results holds NaN or inf (and, with
              --no-cutbacks, that no increment needed a cut-back; with --energy-tolerance,
              that energy.csv's relative_error is within it at every step)
"""
import argparse
import csv
import hashlib
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


def digests(folder):
    out = {}
    for root, _, files in os.walk(folder):
        for f in files:
            path = os.path.join(root, f)
            with open(path, "rb") as h:
                out[os.path.relpath(path, folder)] = hashlib.sha256(h.read()).hexdigest()
    return out


def read_status(folder):
    path = os.path.join(folder, "status.txt")
    if not os.path.isfile(path):
        fail(f"{path} is missing")
    with open(path) as f:
        text = f.read()
    fields = dict(re.findall(r"^(\w+): (.*)$", text, re.M))
    return text, fields


def check_keep(a):
    out = os.path.join(a.workdir, "results")
    p, _ = run(a, command(a, a.good, "results"))
    if p.returncode != 0:
        fail(f"the good run exited with {p.returncode}:\n{p.stdout}\n{p.stderr}")
    status, fields = read_status(out)
    if fields.get("status") != "finished":
        fail(f"the good run's status is not 'finished':\n{status}")
    good = digests(out)

    p, _ = run(a, command(a, a.bad, "results"))
    if p.returncode != a.expect_code:
        fail(f"the failing run exited with {p.returncode}, expected {a.expect_code}:\n"
             f"{p.stdout}\n{p.stderr}")
    if digests(out) != good:
        fail("the failing run changed the good run's results")
    failed = out + ".failed"
    status, fields = read_status(failed)
    reported = re.search(r"stage '([^']*)' \(\d+\), step (\d+)", p.stderr)
    if not reported:
        fail(f"stderr names no stage and step:\n{p.stderr}")
    if fields.get("status") != "failed" or fields.get("stage") != f'"{reported.group(1)}"' \
            or fields.get("step") != reported.group(2) or reported.group(0) not in status:
        fail(f"status.txt of the failed run does not name the failure "
             f"(stage '{reported.group(1)}', step {reported.group(2)}):\n{status}")
    if int(fields.get("converged_increments", "0")) < 1:
        fail(f"the failed run converged nothing; this test needs a later failure:\n{status}")
    for name in a.expect_files:
        if not os.path.isfile(os.path.join(failed, name)):
            fail(f"{name} of the failed run's converged increments is missing")
    if "results.failed" not in p.stderr:
        fail(f"stderr does not say where the converged increments are:\n{p.stderr}")
    left = [f for f in os.listdir(a.workdir) if ".running-" in f]
    if left:
        fail(f"working folders left behind: {left}")
    print(f"run_safety: good results unchanged ({len(good)} files), failure recorded in "
          f"{failed}")


def check_unwritable(a):
    blocker = os.path.join(a.workdir, "not_a_folder")
    with open(blocker, "w") as f:
        f.write("a file where the output folder's parent should be\n")
    p, _ = run(a, command(a, a.good, "not_a_folder/results", quiet=False))
    if p.returncode != a.expect_code:
        fail(f"exit code {p.returncode}, expected {a.expect_code}:\n{p.stdout}\n{p.stderr}")
    if not re.search(r"cannot write the results: cannot create '[^']*not_a_folder'", p.stderr):
        fail(f"no clear error about the output folder:\n{p.stderr}")
    if re.search(r"\bstep\b", p.stdout):
        fail(f"the run solved before finding out it could not write:\n{p.stdout}")
    print(f"run_safety: {p.stderr.strip()}")


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
    if a.no_cutbacks:
        cut = [b for c in sorted(csvs) for b in cut_back_rows(c)]
        if cut:
            fail("increments that needed a cut-back (a solver change made the shipped input "
                 "harder; see docs/testing.md):\n" + "\n".join(cut[:20]))
        print("run_safety: no increment needed a cut-back")
    if a.energy_tolerance is not None:
        ledgers = [c for c in csvs if os.path.basename(c) == "energy.csv"]
        if not ledgers:
            fail(f"no energy.csv under {results}")
        worst, over = 0.0, []
        for ledger in ledgers:
            with open(ledger, newline="") as f:
                for n, r in enumerate(csv.DictReader(f), start=2):
                    e = abs(float(r["relative_error"]))
                    worst = max(worst, e)
                    if e > a.energy_tolerance:
                        over.append(f"{ledger}:{n}: stage {r['stage']} step {r['step']}: {e:.3g}")
        if over:
            fail(f"energy balance off by more than {a.energy_tolerance:g} of the work put in "
                 f"at {len(over)} steps:\n" + "\n".join(over[:20]))
        print(f"run_safety: energy balance within {worst:.2g} of the work put in at every step")


def cut_back_rows(path):
    """Rows of a results CSV whose `cutbacks` column is not 0."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if not reader.fieldnames or "cutbacks" not in reader.fieldnames:
            return []
        return [f"{path}:{n}: cutbacks {r['cutbacks']}" for n, r in enumerate(reader, start=2)
                if float(r["cutbacks"]) != 0]


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("check", choices=["keep", "unwritable", "ends", "finite"])
    p.add_argument("--app", required=True)
    p.add_argument("--good", help="an input that runs to the end")
    p.add_argument("--bad", help="an input whose run fails")
    p.add_argument("--workdir", required=True)
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--no-plot", action="store_true", help="pass --no-plot (the pile app)")
    p.add_argument("--no-cutbacks", action="store_true",
                   help="finite: also fail if an increment needed a cut-back")
    p.add_argument("--energy-tolerance", type=float,
                   help="finite: also fail if energy.csv's |relative_error| exceeds it at a step")
    p.add_argument("--expect-code", type=int, default=3)
    p.add_argument("--expect", default=".", help="regex the failing run's stderr must match")
    p.add_argument("--expect-files", nargs="*", default=[],
                   help="files the failed run's folder must hold")
    p.add_argument("--timeout", type=float, default=30)
    a = p.parse_args()
    # The runs start in --workdir: paths given relative to here must still find their files.
    a.app, a.workdir = os.path.abspath(a.app), os.path.abspath(a.workdir)
    a.good, a.bad = [os.path.abspath(f) if f else f for f in (a.good, a.bad)]
    if a.check != "finite":
        shutil.rmtree(a.workdir, ignore_errors=True)
    os.makedirs(a.workdir, exist_ok=True)
    {"keep": check_keep, "unwritable": check_unwritable, "ends": check_ends,
     "finite": check_finite}[a.check](a)


if __name__ == "__main__":
    main()
