#!/usr/bin/python3
"""Runs the pile_pullout app on a shrunk input, checks that no CSV of the results holds NaN or
inf, and compares its head force curve with a gold file, or (--update) writes the gold file.
Used by CTest (tests/regression/pile/CMakeLists.txt).

The gold curves were produced by this code on one rank. A difference beyond the tolerance
means the physics, the model set-up or the solver's converged answer changed: find out which
before regenerating with --update.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from run_safety import bad_values  # noqa: E402


def read_curve(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    return [(r["stage"], float(r["head_displacement_mm"]), float(r["head_force_kN"]))
            for r in rows]


def check_profile_status(path):
    """The status column names a pair bonded exactly while its adhesion is active (beta > 0),
    and otherwise its contact branch (docs/pile_pullout.md)."""
    errors = []
    with open(path, newline="") as f:
        for line, r in enumerate(csv.DictReader(f), start=2):
            beta, status = float(r["beta"]), r["status"]
            if status not in ("open", "stick", "slip", "bonded"):
                errors.append(f"line {line}: unknown status '{status}'")
            elif (beta > 0) != (status == "bonded"):
                errors.append(f"line {line}: beta {beta} with status '{status}'")
    return errors


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--app", required=True)
    p.add_argument("--input", required=True)
    p.add_argument("--gold", required=True)
    p.add_argument("--workdir", required=True)
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--update", action="store_true")
    a = p.parse_args()

    shutil.rmtree(a.workdir, ignore_errors=True)
    os.makedirs(a.workdir)
    cmd = [a.app, "run", a.input, "--quiet", "--no-plot", "--output", "results"]
    if a.ranks > 1:
        cmd = [a.mpiexec, "-n", str(a.ranks), "--allow-run-as-root", "--oversubscribe"] + cmd
    run = subprocess.run(cmd, cwd=a.workdir)
    if run.returncode != 0:
        sys.exit(f"pile_regression: {' '.join(cmd)} exited with {run.returncode}")
    results = os.path.join(a.workdir, "results")
    bad = [b for f in sorted(os.listdir(results)) if f.endswith(".csv")
           for b in bad_values(os.path.join(results, f))]
    if bad:
        sys.exit("pile_regression: NaN or inf in the results:\n" + "\n".join(bad[:20]))
    status_errors = check_profile_status(os.path.join(results, "profiles.csv"))
    if status_errors:
        sys.exit("pile_regression: profiles.csv status:\n" + "\n".join(status_errors[:20]))
    result = os.path.join(results, "head_force.csv")
    if a.update:
        shutil.copyfile(result, a.gold)
        print(f"wrote {a.gold}")
        return
    got, gold = read_curve(result), read_curve(a.gold)
    if [g[0] for g in got] != [g[0] for g in gold]:
        sys.exit(f"pile_regression: {len(got)} steps {[g[0] for g in got]}, gold has "
                 f"{len(gold)} {[g[0] for g in gold]} (a cut-back pattern changed)")
    # Tolerances: the contact solver stops at a relative residual of 1e-8, and summation order
    # differs between 1 and 2 ranks, so converged values agree to ~1e-8 of the force scale;
    # 1e-6 of the largest force (about 0.5 N here) leaves room for that and nothing else.
    scale = max(abs(g[2]) for g in gold)
    worst = 0.0
    for (stage, u, f), (_, u0, f0) in zip(got, gold):
        worst = max(worst, abs(f - f0) / scale, abs(u - u0) / max(abs(u0), 1.0))
    print(f"pile_regression: {len(got)} steps, worst relative difference {worst:.2e} "
          f"(force scale {scale:.1f} kN)")
    if worst > 1e-6:
        sys.exit("pile_regression: the head force curve differs from the gold beyond 1e-6")


if __name__ == "__main__":
    main()
