#!/usr/bin/env python3
"""Benchmark (issue 12): a smooth rigid strip footing pushed to failure on Tresca soil.

Plane strain half model [0, 3.5] x [0, 2.5] m, footing half-width 0.5 m, tri6 cells (3-point
rule), von_mises with yield stress sqrt(3) c, c = 10 kPa (in plane strain at collapse von
Mises is Tresca with c = sigma_y / sqrt(3)), E = 1e4 kPa, nu = 0.3, weightless; settlement
0.05 m in --increments increments, direct solver. The mesh of tests/verification/
plastic_limit_test.cpp (8 cells under the half footing) has every cell count multiplied by
k/8 for each --cells k. Reports DOFs, Newton iterations per increment, the time split that
`bipot run` prints, peak memory and the bearing capacity q/c against Prandtl's 2 + pi.
One run per size (run it with `nice`: the machine is shared).

Usage: bench/footing.py [--bipot build/apps/bipot/bipot] [--cells 12,38] [--increments 20]
Prints a Markdown table for docs/performance_plasticity.md.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def footing_input(k, increments, directory):
    """The footing with k cells under the half footing (the test has k = 8)."""
    n = lambda base: max(1, round(base * k / 8))
    c = 10.0
    return f"""kinematics: plane_strain
mesh:
  blocks:
    cell: tri6
    diagonals: alternating
    x: {{breaks: [0.0, 0.5, 1.0, 2.0, 3.5], cells: [{n(8)}, {n(8)}, {n(8)}, {n(4)}], grading: [1.0, 1.0, {1.15 ** (8 / k):.6f}, {1.2 ** (8 / k):.6f}]}}
    y: {{breaks: [0.0, 1.5, 2.5], cells: [{n(4)}, {n(16)}], grading: [{0.85 ** (8 / k):.6f}, 1.0]}}
    regions: [soil, soil, soil, soil, soil, soil, soil, soil]
  sets:
    footing: {{min: [0.0, 2.5], max: [0.5, 2.5]}}
materials:
  soil: {{type: von_mises, youngs_modulus: 1.0e4, poissons_ratio: 0.3, yield_stress: {math.sqrt(3) * c!r}}}
linear_solver: {{method: direct}}
stages:
  - name: load
    increments: {increments}
    boundary_conditions:
      - {{set: bottom, component: x, value: 0}}
      - {{set: bottom, component: y, value: 0}}
      - {{set: left, component: x, value: 0}}
      - {{set: right, component: x, value: 0}}
      - {{set: footing, component: y, value: -0.05}}
output: {{directory: {directory}, vtk: false}}
""", c


def run(bipot, k, increments, workdir):
    out_dir = os.path.join(workdir, f"footing_{k}")
    text, c = footing_input(k, increments, out_dir)
    path = os.path.join(workdir, f"footing_{k}.yaml")
    with open(path, "w") as f:
        f.write(text)
    out = subprocess.run([bipot, "run", path], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"{path}: exit {out.returncode}\n{out.stdout}\n{out.stderr}")
    text = out.stdout + out.stderr
    newton = [int(m.group(1)) for m in re.finditer(r"newton\s+(\d+)", text)]
    cut = re.search(r"(\d+) cut-backs?\b", text)
    t = re.search(r"time ([\d.]+) s = assembly ([\d.]+) \+ set-up ([\d.]+) \+ solve ([\d.]+)"
                  r".*peak memory ([\d.]+) MiB", text)
    dofs = re.search(r"(\d+) DOFs", text)
    with open(os.path.join(out_dir, "reactions.csv")) as f:
        rows = list(csv.DictReader(f))
    q = abs(float(rows[-1]["footing_fy"])) / 0.5
    return {"k": k, "dofs": int(dofs.group(1)) if dofs else 0, "increments": len(newton),
            "newton": sum(newton), "cutbacks": int(cut.group(1)) if cut else 0,
            "seconds": float(t.group(1)), "assembly": float(t.group(2)),
            "setup": float(t.group(3)), "solve": float(t.group(4)), "memory": float(t.group(5)),
            "q_over_c": q / c}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--bipot", default=os.path.join(ROOT, "build", "apps", "bipot", "bipot"))
    p.add_argument("--cells", default="12,38")
    p.add_argument("--increments", type=int, default=20)
    a = p.parse_args()
    print("| cells under B/2 | DOFs | increments | Newton iterations (per increment) | cut-backs "
          "| wall time | assembly | set-up | solve | peak memory | q/c (2 + pi = 5.1416) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|", flush=True)
    with tempfile.TemporaryDirectory() as work:
        for k in [int(x) for x in a.cells.split(",")]:
            r = run(a.bipot, k, a.increments, work)
            print(f"| {k} | {r['dofs']} | {r['increments']} | {r['newton']} "
                  f"({r['newton'] / r['increments']:.2f}) | {r['cutbacks']} | "
                  f"{r['seconds']:.1f} s | {r['assembly']:.1f} s | {r['setup']:.1f} s | "
                  f"{r['solve']:.1f} s | {r['memory']:.0f} MiB | {r['q_over_c']:.4f} "
                  f"({100 * (r['q_over_c'] / (2 + math.pi) - 1):+.2f} %) |", flush=True)


if __name__ == "__main__":
    main()
