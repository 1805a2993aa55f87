#!/usr/bin/env python3
"""`bipot run --restart`: a run with `output.checkpoint` at `--first` ranks, then the same
input restarted from its checkpoint (at a stage end or within a stage) at `--then` ranks into another
folder. The restarted folder must hold the whole series and every checkpoint: every CSV row of the uninterrupted run (identical at one
rank, each value to 1e-10 of its file's largest magnitude at 2 ranks and across rank counts) and
as many VTK steps, each file present. A
checkpoint offered to another input (one value changed) is refused with exit code 2 and the
reason."""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys


def run(a, ranks, args):
    cmd = [a.app, "run", "-q"] + args + a.app_args.split()
    if ranks > 1:
        cmd = [a.mpiexec, "-n", str(ranks), "--allow-run-as-root", "--oversubscribe"] + cmd
    return subprocess.run(cmd, cwd=a.workdir, capture_output=True, text=True, timeout=120)


def rows(path):
    with open(path) as f:
        return list(csv.reader(f))


def number(text):
    """The value of a CSV cell, or None for a text cell (a stage name, a status)."""
    try:
        return float(text)
    except ValueError:
        return None


def datasets(folder, pvd):
    with open(os.path.join(folder, pvd)) as f:
        return re.findall(r'file="([^"]+)"', f.read())


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--app", required=True)
    p.add_argument("--input", required=True)
    p.add_argument("--checkpoint", required=True,
                   help="stage name of the checkpoint, or its file name (*.bin)")
    p.add_argument("--workdir", required=True)
    p.add_argument("--first", type=int, default=1)
    p.add_argument("--then", type=int, default=1)
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--app-args", default="", help="more options of `run` (e.g. --no-plot)")
    p.add_argument("--change", default="increments: 4=>increments: 5",
                   help="FROM=>TO: the edit that makes another input of --input")
    a = p.parse_args()
    shutil.rmtree(a.workdir, ignore_errors=True)
    os.makedirs(a.workdir)
    whole, restarted = os.path.join(a.workdir, "whole"), os.path.join(a.workdir, "restarted")
    r = run(a, a.first, [a.input, "--output", whole])
    if r.returncode != 0:
        sys.exit("uninterrupted run failed:\n" + r.stdout + r.stderr)
    name = a.checkpoint if a.checkpoint.endswith(".bin") else "checkpoint_%s.bin" % a.checkpoint
    ckp = os.path.join(whole, name)
    r = run(a, a.then, [a.input, "--restart", ckp, "--output", restarted])
    if r.returncode != 0:
        sys.exit("restarted run failed:\n" + r.stdout + r.stderr)
    problems = []
    csvs = sorted(f for f in os.listdir(whole) if f.endswith(".csv"))
    if not csvs:
        problems.append("no CSV in " + whole)
    for name in csvs:
        w, c = rows(os.path.join(whole, name)), rows(os.path.join(restarted, name))
        if w[0] != c[0] or len(w) != len(c):
            problems.append("%s: %d rows, the restarted run has %d" % (name, len(w), len(c)))
            continue
        # At one rank the restart repeats the same operations: identical text. Across rank
        # counts the sums run in another order, and the Newton iterations stop anywhere below
        # the inputs' solver tolerance (1e-10): each value to 1e-10 of the file's largest
        # magnitude (a column that is itself round-off, like energy.csv's balance_error, has
        # no scale of its own). 1e-12 held only while Newton's last step happened to
        # overshoot the tolerance down to round-off. Two runs at 2 ranks are not always
        # bitwise alike either: once in CI (2026-11-25, staged_friction.yaml 2 -> 2) the
        # increments after the checkpoint differed by up to 6.5e-13 of their values, which
        # 18 local repeats, some under load, did not reproduce. The distributed factorisation
        # (MUMPS's parallel scheduling) is the likely source; not pinned down. Same tolerance.
        scale = max([abs(number(x)) for row in w[1:] for x in row if number(x) is not None]
                    or [0.0])
        tol = 0.0 if a.first == a.then == 1 else 1e-10 * scale
        for col in range(len(w[0])):
            for k, (rw, rc) in enumerate(zip(w[1:], c[1:])):
                x, y = number(rw[col]), number(rc[col])
                differ = rw[col] != rc[col] if x is None or y is None else abs(x - y) > tol
                if differ:
                    problems.append("%s row %d column %s: %s, restarted %s"
                                    % (name, k + 1, w[0][col], rw[col], rc[col]))
    for pvd in sorted(f for f in os.listdir(whole) if f.endswith(".pvd")):
        files = datasets(restarted, pvd)
        if len(files) != len(datasets(whole, pvd)):
            problems.append("%s: %d steps, the restarted run's lists %d"
                            % (pvd, len(datasets(whole, pvd)), len(files)))
        problems += ["%s lists %s, not in the folder" % (pvd, f) for f in files
                     if not os.path.exists(os.path.join(restarted, f))]
    # The restarted folder offers the same restarts: the checkpoints up to its own are copied,
    # the later ones written again.
    problems += ["%s: not in the restarted folder" % f for f in sorted(os.listdir(whole))
                 if f.startswith("checkpoint_") and not os.path.exists(os.path.join(restarted, f))]
    # Another input: the same file with one value changed.
    with open(a.input) as f:
        text = f.read()
    other = os.path.join(a.workdir, "other.yaml")
    with open(other, "w") as f:
        old, new = a.change.split("=>")
        if old not in text:
            sys.exit("--change: '%s' is not in %s" % (old, a.input))
        f.write(text.replace(old, new, 1))
    r = run(a, a.then, [other, "--restart", ckp, "--output", os.path.join(a.workdir, "o")])
    if r.returncode != 2 or "written for another input" not in r.stdout + r.stderr:
        problems.append("another input's restart: exit %d, %s" % (r.returncode, r.stderr.strip()))
    if problems:
        sys.exit("\n".join(problems[:20]))
    print("restart %d -> %d ranks: %d CSV files and the VTK series equal the uninterrupted run"
          % (a.first, a.then, len(csvs)))


if __name__ == "__main__":
    main()
