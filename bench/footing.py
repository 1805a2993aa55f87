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

With --getfem, each size is also solved by GetFEM (Debian python3-getfem; the script re-runs
itself with /usr/bin/python3 when the running interpreter lacks it) on bipot's own mesh, read
from a one-increment bipot run with VTK output: see bench/footing_getfem.py for the model, the
constraints, GetFEM's Newton and how its stopping test is made to match bipot's. A second table
then puts both codes side by side (Newton iterations = linear solves per increment).

Usage: bench/footing.py [--bipot build/apps/bipot/bipot] [--cells 12,38] [--increments 20]
       [--cell tri6|quad8]
       [--getfem [--getfem-lsearch default|basic|...] [--getfem-extrapolate]
        [--getfem-norm2-bound] [--getfem-history] [--tolerance 1e-8]]
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
SETTLEMENT = 0.05
YOUNG, POISSON = 1.0e4, 0.3


def footing_input(k, increments, directory, settlement=SETTLEMENT, vtk=False, cell="tri6"):
    """The footing with k cells under the half footing (the test has k = 8); `cell` tri6 (each
    quadrilateral cut in two, the diagonals alternating) or quad8."""
    n = lambda base: max(1, round(base * k / 8))
    c = 10.0
    cells = "cell: tri6\n    diagonals: alternating" if cell == "tri6" else f"cell: {cell}"
    return f"""kinematics: plane_strain
mesh:
  blocks:
    {cells}
    x: {{breaks: [0.0, 0.5, 1.0, 2.0, 3.5], cells: [{n(8)}, {n(8)}, {n(8)}, {n(4)}], grading: [1.0, 1.0, {1.15 ** (8 / k):.6f}, {1.2 ** (8 / k):.6f}]}}
    y: {{breaks: [0.0, 1.5, 2.5], cells: [{n(4)}, {n(16)}], grading: [{0.85 ** (8 / k):.6f}, 1.0]}}
    regions: [soil, soil, soil, soil, soil, soil, soil, soil]
  sets:
    footing: {{min: [0.0, 2.5], max: [0.5, 2.5]}}
materials:
  soil: {{type: von_mises, youngs_modulus: {YOUNG!r}, poissons_ratio: {POISSON!r}, yield_stress: {math.sqrt(3) * c!r}}}
linear_solver: {{method: direct}}
stages:
  - name: load
    increments: {increments}
    boundary_conditions:
      - {{set: bottom, component: x, value: 0}}
      - {{set: bottom, component: y, value: 0}}
      - {{set: left, component: x, value: 0}}
      - {{set: right, component: x, value: 0}}
      - {{set: footing, component: y, value: {-settlement!r}}}
output: {{directory: {directory}, vtk: {str(vtk).lower()}}}
""", c


def run_bipot(bipot, text, path):
    """Writes the input `text` to `path` and runs bipot on it; stops the bench if it fails."""
    with open(path, "w") as f:
        f.write(text)
    out = subprocess.run([bipot, "run", path], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"{path}: exit {out.returncode}\n{out.stdout}\n{out.stderr}")
    return out.stdout + out.stderr


def run(bipot, k, increments, workdir, cell="tri6"):
    out_dir = os.path.join(workdir, f"footing_{k}")
    text, c = footing_input(k, increments, out_dir, cell=cell)
    text = run_bipot(bipot, text, os.path.join(workdir, f"footing_{k}.yaml"))
    newton = [int(m.group(1)) for m in re.finditer(r"newton\s+(\d+)", text)]
    cut = re.search(r"(\d+) cut-backs?\b", text)
    t = re.search(r"time ([\d.]+) s = assembly ([\d.]+) \+ set-up ([\d.]+) \+ solve ([\d.]+)"
                  r".*peak memory ([\d.]+) MiB", text)
    dofs = re.search(r"(\d+) DOFs", text)
    with open(os.path.join(out_dir, "reactions.csv")) as f:
        rows = list(csv.DictReader(f))
    q = abs(float(rows[-1]["footing_fy"])) / 0.5
    return {"k": k, "dofs": int(dofs.group(1)) if dofs else 0, "increments": len(newton),
            "newton": sum(newton), "per_increment": newton,
            "cutbacks": int(cut.group(1)) if cut else 0,
            "seconds": float(t.group(1)), "assembly": float(t.group(2)),
            "setup": float(t.group(3)), "solve": float(t.group(4)), "memory": float(t.group(5)),
            "q_over_c": q / c}


def bipot_mesh(bipot, k, workdir):
    """The first .vtu of a one-increment, 1 nm settlement run: bipot's mesh, for GetFEM."""
    out_dir = os.path.join(workdir, f"mesh_{k}")
    text, _ = footing_input(k, 1, out_dir, settlement=1e-9, vtk=True)
    run_bipot(bipot, text, os.path.join(workdir, f"mesh_{k}.yaml"))
    return os.path.join(out_dir, sorted(f for f in os.listdir(out_dir) if f.endswith(".vtu"))[0])


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--bipot", default=os.path.join(ROOT, "build", "apps", "bipot", "bipot"))
    p.add_argument("--cells", default="12,38")
    p.add_argument("--increments", type=int, default=20)
    p.add_argument("--cell", default="tri6", choices=["tri6", "quad8"],
                   help="bipot's cells (quad8: 3x3 Gauss points; GetFEM takes tri6 only)")
    p.add_argument("--getfem", action="store_true",
                   help="also solve each size with GetFEM on bipot's mesh (footing_getfem.py)")
    p.add_argument("--getfem-lsearch", default="default",
                   choices=["default", "basic", "simplest", "systematic", "quadratic"],
                   help="Model.solve's line search ('default': Newton with step control)")
    p.add_argument("--getfem-extrapolate", action="store_true",
                   help="start each GetFEM increment from the extrapolated last one (as bipot)")
    p.add_argument("--getfem-norm2-bound", action="store_true",
                   help="GetFEM's norm-1 test at tolerance x sqrt(rows): looser than bipot's")
    p.add_argument("--getfem-history", action="store_true",
                   help="print GetFEM's residual histories (norm 1 / reference) on stderr")
    p.add_argument("--tolerance", type=float, default=1e-8,
                   help="GetFEM's tolerance (bipot uses its default, 1e-8)")
    a = p.parse_args()
    if a.getfem and a.cell != "tri6":
        p.error("--getfem reads bipot's mesh as tri6: leave --cell at tri6")
    if a.getfem:
        from frictional_block import reexec_with_system_python
        reexec_with_system_python(alternative="")
    print("| cells under B/2 | DOFs | increments | Newton iterations (per increment) | cut-backs "
          "| wall time | assembly | set-up | solve | peak memory | q/c (2 + pi = 5.1416) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|", flush=True)
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for k in [int(x) for x in a.cells.split(",")]:
            r = run(a.bipot, k, a.increments, work, a.cell)
            print(f"| {k} | {r['dofs']} | {r['increments']} | {r['newton']} "
                  f"({r['newton'] / r['increments']:.2f}) | {r['cutbacks']} | "
                  f"{r['seconds']:.1f} s | {r['assembly']:.1f} s | {r['setup']:.1f} s | "
                  f"{r['solve']:.1f} s | {r['memory']:.0f} MiB | {r['q_over_c']:.4f} "
                  f"({100 * (r['q_over_c'] / (2 + math.pi) - 1):+.2f} %) |", flush=True)
            if a.getfem:
                from footing_getfem import run_getfem
                g = run_getfem(bipot_mesh(a.bipot, k, work), a.increments, SETTLEMENT,
                               10.0, YOUNG, POISSON, a.tolerance, lsearch=a.getfem_lsearch,
                               norm2_bound=a.getfem_norm2_bound,
                               extrapolate=a.getfem_extrapolate, log=sys.stderr)
                print(f"# cells {k} bipot: newton {r['per_increment']}", file=sys.stderr)
                print(f"# cells {k} GetFEM: newton {g['newton']}, converged {g['converged']}, "
                      f"bipot's relative free residual at the end of each increment "
                      f"{['%.1e' % x for x in g['free_residual']]}", file=sys.stderr, flush=True)
                if a.getfem_history:
                    for i, h in enumerate(g["histories"]):
                        print(f"#   increment {i + 1}: " + " ".join("%.1e" % x for x in h),
                              file=sys.stderr, flush=True)
                rows.append((k, r, g))
    if rows:
        print("\n| cells under B/2 | DOFs | code | increments | Newton iterations (mean, max) "
              "| wall time | q/c |")
        print("|---|---|---|---|---|---|---|")
        for k, r, g in rows:
            print(f"| {k} | {r['dofs']} | bipot | {r['increments']} | {r['newton']} "
                  f"({r['newton'] / r['increments']:.2f}, {max(r['per_increment'])}) | "
                  f"{r['seconds']:.1f} s | {r['q_over_c']:.6f} |")
            name = f"GetFEM {a.getfem_lsearch}" + (", extrapolated" if a.getfem_extrapolate else "")
            failed = "" if all(g["converged"]) else " (not converged)"
            print(f"| {k} | {g['dofs']} | {name} | {g['increments']}{failed} | {sum(g['newton'])} "
                  f"({sum(g['newton']) / g['increments']:.2f}, {max(g['newton'])}) | "
                  f"{g['seconds']:.1f} s (solve {g['solve']:.1f} s) | {g['q_over_c']:.6f} |")


if __name__ == "__main__":
    main()
