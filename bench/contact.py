#!/usr/bin/env python3
"""Benchmark: RCCM debonding with friction at ~10k and ~100k DOFs, both contact solvers.

Model (axisymmetric, a pile-like pull-out): a stiff inclusion r in [0, 0.2] m, z in
[-4, 0] m bonded by an RCCM interface (with friction) to a soil cylinder r <= 4 m, depth
6 m. Stage 1 confines the soil by a radial pressure on its outer radius (the interface
closes and carries contact pressure); stage 2 pulls the inclusion's head up by 8 mm in 16
increments, debonding the interface progressively from the top. Quad4 cells, direct
linear solver (the interface makes the matrix nonsymmetric in slip).
The adhesion viscosity (0.1 kN s/m over 1 s stages) regularises the debonding front: with
alpha = 0, each pair's softening is locally unstable against the compliant soil and both
solvers stall (no path-following yet); 50 kPa of confinement already starts debonding at
the head under load control, hence 20 kPa.

Reports per solver and size: increments, linear solves per increment, matrix set-ups, and
the ratio of the total time to (increments x the time of one linear solve, set-up included),
medians over --repeat runs.

Usage: bench/contact.py [--bipot build/apps/bipot/bipot] [--repeat 3] [--sizes 2,6]
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
    x: {{breaks: [0.0, 0.2, 4.0], cells: [{nx0}, {nx1}], grading: [1.0, 1.08]}}
    y: {{breaks: [-6.0, -4.0, 0.0], cells: [{ny0}, {ny1}]}}
    regions: [soil, soil, pile, soil]
  sets:
    head: {{min: [0.0, 0.0], max: [0.2, 0.0]}}
materials:
  pile: {{type: linear_elastic, youngs_modulus: 3.0e6, poissons_ratio: 0.3}}
  soil: {{type: linear_elastic, youngs_modulus: 3.0e4, poissons_ratio: 0.33}}
linear_solver: {{method: direct}}
interfaces:
  - name: shaft
    between: [pile, soil]
    law: rccm
    parameters: {{normal_stiffness: 2.0e5, tangential_stiffness: 2.0e5, decohesion_energy: 0.05,
                 friction_coefficient: 0.5, adhesion_viscosity: 0.1}}
contact_solver: {{type: {solver}, tolerance: 1.0e-8}}
stages:
  - name: confine
    boundary_conditions:
      - {{set: left, component: r, value: 0}}
      - {{set: bottom, component: z, value: 0}}
    loads:
      - {{type: pressure, set: right, value: 20.0}}
  - name: pull
    increments: 16
    boundary_conditions:
      - {{set: left, component: r, value: 0}}
      - {{set: bottom, component: z, value: 0}}
      - {{set: head, component: z, value: 8.0e-3}}
    loads:
      - {{type: pressure, set: right, value: 20.0}}
output: {{directory: {out}, vtk: false}}
"""

SUMMARY = re.compile(
    r"done: (\d+) increments, (\d+) linear solves.*?, (\d+) matrix set-ups.*?time ([\d.]+) s = "
    r"assembly ([\d.]+) \+ set-up ([\d.]+) \+ solve ([\d.]+)", re.S)
DOFS = re.compile(r"(\d+) DOFs on")


def run_case(bipot, scale, solver, workdir):
    path = os.path.join(workdir, f"contact_{scale}_{solver}.yaml")
    with open(path, "w") as f:
        f.write(INPUT.format(nx0=2 * scale, nx1=20 * scale, ny0=12 * scale, ny1=40 * scale,
                             solver=solver, out=os.path.join(workdir, "out")))
    out = subprocess.run([bipot, "run", path], capture_output=True, text=True)
    if out.returncode != 0:
        return {"failed": out.stderr.strip().splitlines()[-1][:200]}
    m = SUMMARY.search(out.stdout)
    if not m:
        sys.exit("could not parse bipot's summary:\n" + out.stdout)
    inc, solves, setups, total, asm, setup, solve = m.groups()
    inc, solves, setups = int(inc), int(solves), int(setups)
    one_solve = (float(setup) + float(solve)) / max(solves, 1)
    return {"dofs": int(DOFS.search(out.stdout).group(1)), "increments": inc,
            "solves_per_increment": solves / inc, "setups": setups, "total": float(total),
            "ratio": float(total) / (inc * one_solve)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bipot", default="build/apps/bipot/bipot")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", default="2,6", help="mesh scale factors (2: ~10k, 6: ~90k DOFs)")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for scale in [int(s) for s in args.sizes.split(",")]:
            for solver in ["semismooth_newton", "bipotential_uzawa"]:
                runs = [run_case(args.bipot, scale, solver, work) for _ in range(args.repeat)]
                if "failed" in runs[0]:
                    rows.append((scale, solver, runs[0]))
                else:
                    rows.append((scale, solver,
                                 {k: statistics.median(r[k] for r in runs) for k in runs[0]}))
                print(f"# {scale} {solver}: {rows[-1][2]}", file=sys.stderr, flush=True)
    print("| DOFs | solver | increments | linear solves / increment | matrix set-ups | "
          "total s | total / (increments x one solve) |")
    print("|---:|---|---:|---:|---:|---:|---:|")
    for scale, solver, r in rows:
        if "failed" in r:
            print(f"| scale {scale} | {solver} | failed: {r['failed']} | | | | |")
        else:
            print(f"| {r['dofs']} | {solver} | {r['increments']:.0f} | "
                  f"{r['solves_per_increment']:.1f} | {r['setups']:.0f} | {r['total']:.1f} | "
                  f"{r['ratio']:.1f} |")


if __name__ == "__main__":
    main()
