#!/usr/bin/env python3
"""Benchmark of the pile pull-out app (issue 4): the default RCCM run, and a refinement study.

1. The default input (inputs/pile_pullout/rccm.yaml) as shipped: DOFs, increments, linear
   solves, wall time, peak memory; medians over --repeat runs.
2. Refinement study: the same model with every cell count multiplied by k (growth factors
   taken to the power 1/k, so the grading is the same), pull-out in --study-increments
   increments (half the default input's 80; with the `lu` preconditioner, 40 cost about as
   much as 8 at k = 2 and 4, since smaller increments change fewer interface rows per
   Newton step, and resolve the curve better; the same for all
   k, so times compare), one run per k; then the exponent of total time vs DOFs between
   successive sizes and overall (least squares on log-log).

Usage: bench/pile.py [--app build/apps/pile_pullout/pile_pullout] [--repeat 3]
                     [--factors 1,2,4,8] [--study-increments 40] [--skip-default]
                     [--input inputs/pile_pullout/rccm_mohr_coulomb.yaml]
                     [--linear-solver "{method: gmres, preconditioner: muelu}"]
--linear-solver replaces the input's `linear_solver:` value (a YAML flow map) in every run.
--input takes another input than rccm.yaml (e.g. the pile in Mohr-Coulomb soil); --factors ""
skips the refinement study.
Prints a Markdown table for docs/performance.md.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = os.path.join(ROOT, "inputs", "pile_pullout", "rccm.yaml")


def run(app, path, workdir):
    out = subprocess.run([app, "run", path, "--no-plot", "--output", "results"],
                         cwd=workdir, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"{path}: exit {out.returncode}\n{out.stdout}\n{out.stderr}")
    text = out.stdout
    m = re.search(r"(\d+) DOFs", text)
    s = re.search(r"(\d+) increments, (\d+) linear solves \((\d+) Krylov iterations\), "
                  r"(\d+) matrix set-ups; time ([\d.]+) s"
                  r" = assembly ([\d.]+) \+ set-up ([\d.]+) \+ solve ([\d.]+).*peak memory "
                  r"([\d.]+) MiB", text)
    peak = re.search(r"peak pull-out force ([\d.]+) kN at ([\d.]+) mm", text)
    return {"dofs": int(m.group(1)) if m else 0, "increments": int(s.group(1)),
            "solves": int(s.group(2)), "krylov": int(s.group(3)), "setups": int(s.group(4)),
            "seconds": float(s.group(5)), "assembly": float(s.group(6)),
            "setup": float(s.group(7)), "solve": float(s.group(8)), "memory": float(s.group(9)),
            "peak": float(peak.group(1))}


def with_linear_solver(text, solver):
    """`text` with its `linear_solver:` line's value replaced by `solver` (None: unchanged)."""
    if solver is None:
        return text
    new, n = re.subn(r"^linear_solver:.*$", lambda m: f"linear_solver: {solver}", text,
                     flags=re.M)
    if n != 1:
        sys.exit(f"expected one `linear_solver:` line in the input, found {n}")
    return new


def scaled(text, k, increments):
    def mul(key, v):
        return f"{key}: {int(v) * k}"
    for key in ("pile_radial_cells", "shaft_cells", "soil_radial_cells", "below_toe_cells"):
        text = re.sub(rf"{key}: (\d+)", lambda m: mul(key, m.group(1)), text)
    for key in ("radial_growth", "below_toe_growth"):
        text = re.sub(rf"{key}: ([\d.]+)",
                      lambda m: f"{key}: {float(m.group(1)) ** (1.0 / k):.6f}", text)
    # The study measures the solver on the plan: the shipped energy_tolerance (thousands of
    # halvings at 1e-6 on the viscous pile) is dropped.
    text = re.sub(r"pullout: \{head_displacement: ([\d.e-]+), increments: \d+"
                  r"(, energy_tolerance: [\d.e+-]+)?\}",
                  lambda m: f"pullout: {{head_displacement: {m.group(1)}, increments: "
                            f"{increments}}}", text)
    return text.replace("every: 5", "every: 1000").replace("vtk: true", "vtk: false")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--app", default=os.path.join(ROOT, "build", "apps", "pile_pullout",
                                                 "pile_pullout"))
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--factors", default="1,2,4,8")
    p.add_argument("--study-increments", type=int, default=40)
    p.add_argument("--skip-default", action="store_true")
    p.add_argument("--input", default=DEFAULT)
    p.add_argument("--linear-solver", default=None,
                   help="YAML flow map replacing the input's linear_solver value")
    a = p.parse_args()
    a.app = os.path.abspath(a.app)  # the runs happen in a scratch folder
    work = tempfile.mkdtemp(prefix="bipot_bench_pile_")
    text = with_linear_solver(open(a.input).read(), a.linear_solver)
    label = os.path.basename(a.input)
    if not a.skip_default:
        default = os.path.join(work, label)
        with open(default, "w") as f:
            f.write(text)
        runs = [run(a.app, default, work) for _ in range(a.repeat)]
        med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
        print("| default RCCM run | DOFs | increments | linear solves | set-ups | wall time "
              "(median) | assembly | set-up | solve | peak memory |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        print(f"| {label} | {med['dofs']} | {med['increments']:.0f} | {med['solves']:.0f} | "
              f"{med['setups']:.0f} | {med['seconds']:.1f} s | {med['assembly']:.1f} s | "
              f"{med['setup']:.1f} s | {med['solve']:.1f} s | {med['memory']:.0f} MiB |")
        times = ", ".join("%.1f" % r["seconds"] for r in runs)
        print(f"(times of the {a.repeat} runs: {times} s)\n", flush=True)
    rows = []
    factors = [int(x) for x in a.factors.split(",") if x]
    if not factors:
        return
    print("| k | DOFs | increments | linear solves | Krylov iterations | wall time | assembly | "
          "set-up | solve | memory | peak force | exponent vs previous |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|", flush=True)
    for k in factors:
        path = os.path.join(work, f"pile_k{k}.yaml")
        with open(path, "w") as f:
            f.write(scaled(text, k, a.study_increments))
        r = run(a.app, path, work)
        expo = ""
        if rows:
            q = rows[-1]
            expo = f"{math.log(r['seconds'] / q['seconds']) / math.log(r['dofs'] / q['dofs']):.2f}"
        rows.append(r)
        print(f"| {k} | {r['dofs']} | {r['increments']} | {r['solves']} | {r['krylov']} | "
              f"{r['seconds']:.1f} s | {r['assembly']:.1f} s | "
              f"{r['setup']:.1f} s | {r['solve']:.1f} s | {r['memory']:.0f} MiB | "
              f"{r['peak']:.1f} kN | {expo} |", flush=True)
    if len(rows) > 1:
        xs = [math.log(r["dofs"]) for r in rows]
        ys = [math.log(r["seconds"]) for r in rows]
        mx, my = statistics.mean(xs), statistics.mean(ys)
        slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        print(f"\ntotal time ~ N^{slope:.2f} (least squares over k = {a.factors})")


if __name__ == "__main__":
    main()
