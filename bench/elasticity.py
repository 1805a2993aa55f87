#!/usr/bin/env python3
"""Benchmark: axisymmetric linear elasticity at ~10k, 100k and 1M DOFs.

Runs `bipot run` on a generated input (soil cylinder r in [0, 20] m, z in [-20, 0] m,
quad4, gravity + surface pressure, CG + MueLu to 1e-8), repeats each case, and prints a
Markdown table of medians: assembly, preconditioner set-up, solve, iterations, total time,
peak memory per DOF, and the np=2 speed-up. Timings come from the summary bipot prints.

Usage: bench/elasticity.py [--bipot build/apps/bipot/bipot] [--repeat 3] [--sizes 70,223,706]
                           [--ranks 1,2] [--linear-solver "{method: direct, factorization: klu2}"]
--linear-solver replaces the `linear_solver:` value (a YAML flow map), e.g. to time the sparse
LU packages: with `method: direct` the set-up column is the factorisation.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

INPUT = """kinematics: axisymmetric
mesh:
  blocks:
    cell: quad4
    x: {{breaks: [0.0, 20.0], cells: [{n}]}}
    y: {{breaks: [-20.0, 0.0], cells: [{n}]}}
    regions: [soil]
materials:
  soil: {{type: linear_elastic, youngs_modulus: 3.0e4, poissons_ratio: 0.33, unit_weight: 18.0}}
linear_solver: {{method: cg, preconditioner: muelu, tolerance: 1.0e-8, max_iterations: 1000}}
stages:
  - name: load
    boundary_conditions:
      - {{set: left, component: r, value: 0}}
      - {{set: right, component: r, value: 0}}
      - {{set: bottom, component: z, value: 0}}
    loads:
      - {{type: gravity}}
      - {{type: pressure, set: top, value: 50.0}}
output: {{directory: {out}, vtk: false}}
"""

SUMMARY = re.compile(
    r"(\d+) linear solves \((\d+) iterations\).*?time ([\d.]+) s = assembly ([\d.]+) \+ set-up "
    r"([\d.]+) \+ solve ([\d.]+) \+ output ([\d.]+).*?peak memory ([\d.]+) MiB", re.S)
DOFS = re.compile(r"(\d+) DOFs on")


def run_case(bipot, n, ranks, workdir, linear_solver=None):
    path = os.path.join(workdir, f"bench_{n}.yaml")
    text = INPUT.format(n=n, out=os.path.join(workdir, f"out_{n}_{ranks}"))
    if linear_solver:
        text = re.sub(r"^linear_solver:.*$", lambda m: f"linear_solver: {linear_solver}", text,
                      flags=re.M)
    with open(path, "w") as f:
        f.write(text)
    cmd = [bipot, "run", path]
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks), "--allow-run-as-root", "--oversubscribe"] + cmd
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    m = SUMMARY.search(out)
    if not m:
        sys.exit("could not parse bipot's summary:\n" + out)
    solves, iters, total, asm, setup, solve, output, mem = m.groups()
    return {"dofs": int(DOFS.search(out).group(1)), "iterations": int(iters) / int(solves),
            "total": float(total), "assembly": float(asm), "setup": float(setup),
            "solve": float(solve), "memory_mb": float(mem)}


def median_of(runs, key):
    return statistics.median(r[key] for r in runs)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bipot", default="build/apps/bipot/bipot")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", default="70,223,706", help="cells per side (DOFs = 2 (n+1)^2)")
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--linear-solver", default=None,
                    help="YAML flow map replacing the input's linear_solver value")
    args = ap.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    ranks = [int(r) for r in args.ranks.split(",")]
    results = {}
    with tempfile.TemporaryDirectory() as work:
        for n in sizes:
            for np_ in ranks:
                runs = [run_case(args.bipot, n, np_, work, args.linear_solver)
                        for _ in range(args.repeat)]
                results[(n, np_)] = {k: median_of(runs, k) for k in runs[0]}
                r = results[(n, np_)]
                print(f"# n={n} np={np_}: {r}", file=sys.stderr, flush=True)
    print("| DOFs | ranks | assembly s | set-up s | solve s | CG iterations | total s | "
          "peak MiB/rank | bytes/DOF (all ranks) |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for (n, np_), r in sorted(results.items()):
        print(f"| {r['dofs']} | {np_} | {r['assembly']:.2f} | {r['setup']:.2f} | "
              f"{r['solve']:.2f} | {r['iterations']:.0f} | {r['total']:.2f} | "
              f"{r['memory_mb']:.0f} | {r['memory_mb'] * np_ * 1048576 / r['dofs']:.0f} |")
    if len(sizes) > 1 and 1 in ranks:
        import math
        a, b = results[(sizes[0], 1)], results[(sizes[-1], 1)]
        exponent = math.log(b["total"] / a["total"]) / math.log(b["dofs"] / a["dofs"])
        counts = [results[(n, 1)]["iterations"] for n in sizes]
        # A direct solver reports no iterations: then there is no spread to state.
        spread = (f"; iteration counts vary by a factor {max(counts) / min(counts):.2f}"
                  if min(counts) > 0 else "")
        print(f"\nTotal time grows as N^{exponent:.2f} from {a['dofs']} to {b['dofs']} DOFs "
              f"(np=1){spread}.")
    if 2 in ranks and 1 in ranks:
        for n in sizes:
            s = results[(n, 1)]["total"] / results[(n, 2)]["total"]
            print(f"Speed-up np=2 vs np=1 at {results[(n, 1)]['dofs']} DOFs: {s:.2f}")


if __name__ == "__main__":
    main()
