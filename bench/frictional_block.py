#!/usr/bin/env python3
"""Benchmark: frictional block on a rigid foundation, bipot side by side with GetFEM.

Model (plane strain): an elastic block [0, L] x [0, H] (L = H = 1 m, E = 2e4 kPa,
nu = 0.25) on a rigid flat foundation, Coulomb friction mu = 0.3, no adhesion. Stage 1
(`compress`, 5 increments) pushes the top down by 1e-3 H; stage 2 (`shear`, 10 increments)
moves the top sideways by 4e-3 H at constant compression, far beyond the ~0.9e-3 H at which
the whole contact slides (the last increments are in gross sliding: |F_t| = mu F_n). The
top is clamped to its prescribed displacement in both directions.

Both codes solve the same discrete problem on the same mesh: n x n quad4 (Q1) cells with the
same nodes, 2 x 2 Gauss points (exact on rectangles, so the same stiffness matrix), node-wise
Signorini-Coulomb conditions at the n + 1 bottom nodes with the slip taken over the load
increment.

- bipot: the rigid foundation is a one-cell-thick `foundation` region under the block whose
  every node is clamped (set `foundation_all`, `region: foundation`: only the foundation's
  copies of the interface nodes), a `coulomb_signorini` interface between the two regions
  (node to node, body 1 = foundation, normal +y): the jump is the block's displacement.
  Each pair carries A_i r_i; the nodal complementarity conditions are the same for any
  positive weights, so this is the nodal-force problem below.
- GetFEM (python3-getfem): linearized elasticity brick (plane strain, Lame constants from E,
  nu), Dirichlet with simplification on the top, and the *basic contact brick with friction*
  (`add_basic_contact_brick`), with hand-built B_N (-u_y of each bottom node: B_N U <= 0 is
  u_y >= 0) and B_T (u_x), nodal-force multipliers lambda_n, lambda_t, augmentation
  r = E, alpha = 1, augmented_version 1 = the non-symmetric Alart-Curnier formulation, and the
  slip over the increment (data `wt` = the previous converged displacement, `gamma` = -1:
  the friction projection acts on B_T (U - U_prev)). Solved by GetFEM's Newton
  (`Model.solve`, MUMPS, default line search), which returns its iteration count.

Reports per mesh (n cells per side) and code: DOFs (GetFEM: the block's 2 (n+1)^2
displacement DOFs; bipot: its own count, which adds the clamped foundation's 4 (n+1)); total
wall time (bipot: the whole `bipot run` process, including its start-up of ~0.5 s, input,
mesh and output; GetFEM: mesh, model and all steps, in-process); time per load step (bipot:
its reported run time without output / increments; GetFEM: the mean time of `Model.solve`);
Newton iterations per step as each code counts them (mean and max; bipot's `newton` column
of its progress lines, where 0 means that the increment predictor already satisfied the
tolerance; GetFEM's returned count, where the first iteration of a step also applies the new
Dirichlet values, so it is never below 1); linear solves per step (bipot's total from its
summary line; GetFEM: one per iteration); for bipot, the number of steps where it used more
Newton iterations than GetFEM; and at the end of each stage the difference of the resultant
contact force (normal F_n and tangential F_t, the force of the foundation on the block)
between bipot and GetFEM, divided by |F| at that stage, and the largest nodal displacement
difference over the block divided by max |u| (target: agreement to 1e-6). Times are medians
over --repeat runs; the iteration counts are those of the first run (GetFEM's can differ by
one between runs at a step or two, round-off against its absolute residual threshold).

Usage: bench/frictional_block.py [--bipot build/apps/bipot/bipot] [--repeat 3]
       [--sizes 31,70,122] [--solver generalized_newton|semismooth_newton|bipotential_uzawa|all]
       [--skip-getfem] [--tolerance 1e-10]
(n = 31, 70, 122, 223: ~2k, 10k, 30k, 100k DOFs). GetFEM needs the Debian python3-getfem
package; when the running interpreter lacks it, the script re-runs itself with
/usr/bin/python3. Reading bipot's displacements (LZ4-compressed .vtu) needs python3-lz4.
"""
import argparse
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
import zlib

L, H = 1.0, 1.0
YOUNG, POISSON, MU = 2.0e4, 0.25, 0.3
PRESS, SHEAR = -1.0e-3 * H, 4.0e-3 * H
SOLVERS = ["generalized_newton", "semismooth_newton", "bipotential_uzawa"]

INPUT = """kinematics: plane_strain
mesh:
  blocks:
    cell: quad4
    x: {{breaks: [0.0, {L!r}], cells: [{n}]}}
    y: {{breaks: [{yb!r}, 0.0, {H!r}], cells: [1, {n}]}}
    regions: [foundation, block]
  sets:
    foundation_all: {{min: [0.0, {yb!r}], max: [{L!r}, 0.0], region: foundation}}
materials:
  foundation: {{type: linear_elastic, youngs_modulus: {E!r}, poissons_ratio: {nu!r}}}
  block: {{type: linear_elastic, youngs_modulus: {E!r}, poissons_ratio: {nu!r}}}
linear_solver: {{method: direct}}
interfaces:
  - name: contact
    between: [foundation, block]
    law: coulomb_signorini
    parameters: {{friction_coefficient: {mu!r}}}
contact_solver: {{type: {solver}, tolerance: {tol!r}}}
stages:
  - name: compress
    increments: {n1}
    boundary_conditions:
      - {{set: foundation_all, component: x, value: 0}}
      - {{set: foundation_all, component: y, value: 0}}
      - {{set: top, component: x, value: 0}}
      - {{set: top, component: y, value: {press!r}}}
  - name: shear
    increments: {n2}
    boundary_conditions:
      - {{set: foundation_all, component: x, value: 0}}
      - {{set: foundation_all, component: y, value: 0}}
      - {{set: top, component: x, value: {shear!r}}}
      - {{set: top, component: y, value: {press!r}}}
output: {{directory: {out}, vtk: {vtk}, every: 1000000}}
"""

PROGRESS = re.compile(r"^\s*stage (\S+)\s+step\s+(\d+)\s+([\d.]+)%\s+t = \S+\s+newton\s+(\d+)\s+"
                      r"linear\s+(\d+)\s+residual (\S+)\s+([\d.]+) s", re.M)
DOFS = re.compile(r"(\d+) DOFs on")
SUMMARY = re.compile(r"bipot: time ([\d.]+) s = assembly ([\d.]+) \+ set-up ([\d.]+) \+ "
                     r"solve ([\d.]+) \+ output ([\d.]+)")
SOLVES = re.compile(r"done: (\d+) increments, (\d+) linear solves")


def load_steps(n1, n2):
    """Prescribed top displacement (ux, uy) at the end of each increment, stage index."""
    steps = [((0.0, PRESS * k / n1), 0) for k in range(1, n1 + 1)]
    steps += [((SHEAR * k / n2, PRESS), 1) for k in range(1, n2 + 1)]
    return steps


def grid_key(x, y, n):
    return (int(round(x / L * n)), int(round(y / H * n)))


# ---------------------------------------------------------------------------- bipot


def read_vtu(path):
    """Points, point arrays and cell arrays of a VTK XML unstructured grid written in
    appended raw mode (optionally zlib- or LZ4-compressed: bipot writes LZ4, which needs
    Debian's python3-lz4), as lists of tuples."""
    with open(path, "rb") as f:
        data = f.read()
    marker = data.index(b"<AppendedData")
    start = data.index(b"_", marker) + 1
    head = data[:marker].decode() + "</VTKFile>"
    root = ET.fromstring(head)
    header = "Q" if root.get("header_type", "UInt32") == "UInt64" else "I"
    hsize = 8 if header == "Q" else 4
    compressor = root.get("compressor")
    compressed = compressor is not None
    if compressed and "LZ4" in compressor:
        try:
            import lz4.block
        except ImportError:
            sys.exit(f"{path} is LZ4-compressed: apt-get install python3-lz4")

        def inflate(chunk, size):
            return lz4.block.decompress(chunk, uncompressed_size=size)
    else:
        def inflate(chunk, size):
            return zlib.decompress(chunk)
    import struct
    types = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt8": "B",
             "Int8": "b", "UInt64": "Q", "UInt32": "I"}

    def array(el):
        off = start + int(el.get("offset"))
        if compressed:
            nb, bs, last = struct.unpack_from("<3" + header, data, off)
            sizes = struct.unpack_from("<%d%s" % (nb, header), data, off + 3 * hsize)
            pos = off + (3 + nb) * hsize
            raw = b""
            for k, s in enumerate(sizes):
                raw += inflate(data[pos:pos + s], last if k == nb - 1 and last else bs)
                pos += s
        else:
            (nbytes,) = struct.unpack_from("<" + header, data, off)
            raw = data[off + hsize:off + hsize + nbytes]
        fmt = types[el.get("type")]
        vals = struct.unpack("<%d%s" % (len(raw) // struct.calcsize(fmt), fmt), raw)
        nc = int(el.get("NumberOfComponents", "1"))
        return [vals[i:i + nc] for i in range(0, len(vals), nc)]

    piece = root.find(".//Piece")
    out = {"points": array(piece.find("Points/DataArray"))}
    for el in piece.find("Cells"):
        out[el.get("Name")] = array(el)
    for sect in ("PointData", "CellData"):
        node = piece.find(sect)
        for el in (node if node is not None else []):
            out[sect + ":" + el.get("Name")] = array(el)
    return out


def bipot_block_displacements(vtu, n):
    """{grid key: (ux, uy)} over the block's nodes (its copies of the interface nodes)."""
    g = read_vtu(vtu)
    pts, conn, offs = g["points"], g["connectivity"], g["offsets"]
    region = g["CellData:region"]
    first = 0
    cells = []
    for c, end in enumerate(offs):
        cells.append([conn[k][0] for k in range(first, end[0])])
        first = end[0]
    # The block is the region of the top-most cell.
    top = max(range(len(cells)), key=lambda c: sum(pts[p][1] for p in cells[c]))
    block = region[top][0]
    nodes = {p for c, ids in enumerate(cells) if region[c][0] == block for p in ids}
    u = g["PointData:displacement"]
    return {grid_key(pts[p][0], pts[p][1], n): (u[p][0], u[p][1]) for p in nodes}


def run_bipot(bipot, n, solver, n1, n2, tol, workdir, vtk):
    out_dir = os.path.join(workdir, f"out_{n}_{solver}")
    path = os.path.join(workdir, f"frictional_block_{n}_{solver}.yaml")
    with open(path, "w") as f:
        f.write(INPUT.format(L=L, H=H, n=n, yb=-H / n, E=YOUNG, nu=POISSON, mu=MU, solver=solver,
                             tol=tol, n1=n1, n2=n2, press=PRESS, shear=SHEAR, out=out_dir,
                             vtk="true" if vtk else "false"))
    t0 = time.perf_counter()
    res = subprocess.run([bipot, "run", path], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if res.returncode != 0:
        lines = (res.stderr.strip() or res.stdout.strip()).splitlines()
        return {"failed": (lines[-1] if lines else f"exit {res.returncode}")[:300], "yaml": path}
    steps = PROGRESS.findall(res.stdout)
    if not steps:
        sys.exit("could not parse bipot's progress lines:\n" + res.stdout)
    newton = [int(s[3]) for s in steps]
    summ = SUMMARY.search(res.stdout)
    # bipot's own time without output (input, mesh, assembly, set-ups, solves), per step
    internal = float(summ.group(1)) - float(summ.group(5))
    r = {"dofs": int(DOFS.search(res.stdout).group(1)), "wall": wall,
         "steps": len(steps), "step_time": internal / len(steps), "newton": newton,
         "solves": int(SOLVES.search(res.stdout).group(2)) / len(steps), "yaml": path}
    # Resultant force of the foundation on the block after each increment; the last row
    # of each stage.
    with open(os.path.join(out_dir, "interface_contact.csv")) as f:
        rows = list(csv.DictReader(f))
    ends = {}
    for row in rows:
        ends[int(float(row["stage"])) - 1] = (float(row["force_y"]), float(row["force_x"]))
    r["forces"] = [ends.get(0), ends.get(1)]
    if vtk:
        files = sorted(f for f in os.listdir(out_dir) if f.endswith(".vtu")
                       and not f.startswith("interface_"))
        r["u"] = [bipot_block_displacements(os.path.join(out_dir, f), n) for f in files[-2:]]
    return r


# ---------------------------------------------------------------------------- GetFEM


def run_getfem(n, n1, n2, tol, lsolver):
    import numpy as np
    import getfem as gf
    gf.util_trace_level(0)
    t_start = time.perf_counter()
    m = gf.Mesh("cartesian", np.linspace(0.0, L, n + 1), np.linspace(0.0, H, n + 1))
    BOTTOM, TOP = 1, 2
    m.set_region(BOTTOM, m.outer_faces_with_direction([0.0, -1.0], 0.01))
    m.set_region(TOP, m.outer_faces_with_direction([0.0, 1.0], 0.01))
    mfu = gf.MeshFem(m, 2)
    mfu.set_fem(gf.Fem("FEM_QK(2,1)"))
    mim = gf.MeshIm(m, gf.Integ("IM_GAUSS_PARALLELEPIPED(2,2)"))
    lame_lambda = YOUNG * POISSON / ((1 + POISSON) * (1 - 2 * POISSON))
    lame_mu = YOUNG / (2 * (1 + POISSON))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_initialized_data("lambda", [lame_lambda])
    md.add_initialized_data("mu", [lame_mu])
    md.add_isotropic_linearized_elasticity_brick(mim, "u", "lambda", "mu")  # plane strain
    md.add_initialized_data("top_u", [0.0, 0.0])
    md.add_Dirichlet_condition_with_simplification("u", TOP, "top_u")
    # Contact nodes: the bottom nodes; a Lagrange vector FEM numbers a node's x, y DOFs
    # consecutively (checked below).
    nd = mfu.nbdof()
    pts = mfu.basic_dof_nodes()
    bottom = set(int(d) for d in mfu.basic_dof_on_region(BOTTOM))
    xdofs = sorted(d for d in bottom if d % 2 == 0)
    assert len(xdofs) == n + 1 and all(d + 1 in bottom for d in xdofs)
    assert all(abs(pts[1, d]) < 1e-12 and pts[0, d] == pts[0, d + 1] for d in xdofs)
    nc = len(xdofs)
    BN = gf.Spmat("empty", nc, nd)
    BT = gf.Spmat("empty", nc, nd)
    for i, d in enumerate(xdofs):
        BN[i, d + 1] = -1.0  # B_N U <= 0: u_y >= 0 (the bottom's outward normal is -y)
        BT[i, d] = 1.0       # tangential displacement u_x
    md.add_variable("lambda_n", nc)  # nodal contact forces (<= 0 in compression)
    md.add_variable("lambda_t", nc)  # nodal friction forces
    md.add_initialized_data("r", [YOUNG])
    md.add_initialized_data("friction", [MU])
    md.add_initialized_data("gap", np.zeros(nc))
    md.add_initialized_data("alpha", np.ones(nc))
    md.add_initialized_data("gamma", [-1.0])   # slip = B_T (U - wt)
    md.add_initialized_data("wt", np.zeros(nd))
    md.add_basic_contact_brick("u", "lambda_n", "lambda_t", "r", BN, BT, "friction", "gap",
                               "alpha", 1, "gamma", "wt")
    # Residual target: tol times the expected normal force (E' * strain * L).
    f_ref = YOUNG / (1 - POISSON ** 2) * abs(PRESS) / H * L
    its, times, forces, disp = [], [], [None, None], [None, None]
    for (ux, uy), stage in load_steps(n1, n2):
        md.set_variable("wt", md.variable("u"))
        md.set_variable("top_u", [ux, uy])
        t0 = time.perf_counter()
        nit, converged = md.solve("max_res", tol * f_ref, "max_iter", 200, "lsolver", lsolver)
        times.append(time.perf_counter() - t0)
        if not converged:
            return {"failed": f"Newton did not converge at step {len(its) + 1} "
                              f"({nit} iterations)"}
        its.append(int(nit))
        ln, lt = md.variable("lambda_n"), md.variable("lambda_t")
        forces[stage] = (-float(ln.sum()), float(lt.sum()))  # foundation on block
        u = md.variable("u")
        disp[stage] = {grid_key(pts[0, d], pts[1, d], n): (float(u[d]), float(u[d + 1]))
                       for d in range(0, nd, 2)}
    return {"dofs": nd, "wall": time.perf_counter() - t_start, "steps": len(its),
            "step_time": sum(times) / len(times), "newton": its, "forces": forces, "u": disp,
            "solves": sum(its) / len(its),  # one tangent solve per Newton iteration
            "slipping": int(np.sum(np.abs(np.abs(lt) - MU * np.abs(ln))
                                   <= 1e-8 * np.abs(ln).max())), "pairs": nc}


# ---------------------------------------------------------------------------- report


def median_runs(runs):
    ok = [r for r in runs if "failed" not in r]
    if not ok:
        return runs[0]
    out = dict(ok[0])
    for k in ("wall", "step_time"):
        if k in out:
            out[k] = statistics.median(r[k] for r in ok)
    return out


def compare(b, g):
    """Per stage: (dFn/|F|, dFt/|F|, max |du| / max |u|)."""
    res = []
    for s in range(2):
        fb, fg = b["forces"][s], g["forces"][s]
        norm = (fg[0] ** 2 + fg[1] ** 2) ** 0.5
        du = float("nan")
        if "u" in b and len(b["u"]) == 2:
            ub, ug = b["u"][s], g["u"][s]
            if set(ub) != set(ug):
                sys.exit(f"the two meshes' nodes differ ({len(ub)} vs {len(ug)} nodes)")
            umax = max(max(abs(c) for c in v) for v in ug.values())
            du = max(max(abs(ub[k][0] - ug[k][0]), abs(ub[k][1] - ug[k][1])) for k in ug) / umax
        res.append((abs(fb[0] - fg[0]) / norm, abs(fb[1] - fg[1]) / norm, du))
    return res


def reexec_with_system_python(alternative=" (or run with --skip-getfem)"):
    """Runs the script again with Debian's python3 when this interpreter lacks GetFEM."""
    try:
        import getfem  # noqa: F401
        import numpy  # noqa: F401
    except ImportError:
        system = "/usr/bin/python3"
        if os.path.exists(system) and os.path.realpath(sys.executable) != os.path.realpath(system):
            os.execv(system, [system] + sys.argv)
        sys.exit("GetFEM's Python module is missing: apt-get install python3-getfem" + alternative)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--bipot", default=os.path.join(root, "build/apps/bipot/bipot"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--sizes", default="31,70,122",
                    help="cells per side (31: ~2k, 70: ~10k, 122: ~30k, 223: ~100k DOFs)")
    ap.add_argument("--solver", default="generalized_newton", choices=SOLVERS + ["all"],
                    help="bipot contact solver type")
    ap.add_argument("--skip-getfem", action="store_true", help="bipot only (large meshes)")
    ap.add_argument("--tolerance", type=float, default=1e-10,
                    help="bipot's contact_solver tolerance; GetFEM's max_res is this times "
                         "the expected normal force")
    ap.add_argument("--increments", default="5,10", help="compression, shear increments")
    ap.add_argument("--getfem-lsolver", default="mumps")
    ap.add_argument("--keep", help="keep the inputs and outputs in this directory")
    args = ap.parse_args()
    if not args.skip_getfem:
        reexec_with_system_python()
    n1, n2 = (int(s) for s in args.increments.split(","))
    solvers = SOLVERS if args.solver == "all" else [args.solver]
    sizes = [int(s) for s in args.sizes.split(",")]
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
    tmp = None if args.keep else tempfile.TemporaryDirectory()
    work = args.keep or tmp.name
    rows = []
    for n in sizes:
        g = None
        if not args.skip_getfem:
            g = median_runs([run_getfem(n, n1, n2, args.tolerance, args.getfem_lsolver)
                             for _ in range(args.repeat)])
            print(f"# n={n} getfem: " + ("failed: " + g["failed"] if "failed" in g else
                  f"{g['dofs']} DOFs, {g['wall']:.2f} s, newton {g['newton']}, forces "
                  f"{g['forces']}, {g['slipping']}/{g['pairs']} nodes on the cone"),
                  file=sys.stderr, flush=True)
        for solver in solvers:
            # The first run writes the stage-end displacements (for the comparison); the
            # timed runs write no VTK.
            first = run_bipot(args.bipot, n, solver, n1, n2, args.tolerance, work,
                              vtk=g is not None)
            runs = [first] if g is None or args.repeat == 1 else []
            runs += [run_bipot(args.bipot, n, solver, n1, n2, args.tolerance, work, vtk=False)
                     for _ in range(args.repeat - len(runs))]
            b = median_runs(runs)
            if "failed" not in first and "u" in first:
                b["u"] = first["u"]
            print(f"# n={n} bipot {solver}: " + ("failed: " + b["failed"] + " (" + b["yaml"] +
                  ")" if "failed" in b else f"{b['dofs']} DOFs, {b['wall']:.2f} s, newton "
                  f"{b['newton']}, forces {b['forces']}"), file=sys.stderr, flush=True)
            rows.append((n, solver, b, g))
        if g is not None:
            rows.append((n, "getfem", g, None))
    if tmp:
        tmp.cleanup()

    print("| n | DOFs | code | total s | s / step | Newton / step (mean, max) | linear solves "
          "/ step | steps with more Newton than GetFEM | compress: dFn, dFt, du | "
          "shear: dFn, dFt, du | agree 1e-6 |")
    print("|---:|---:|---|---:|---:|---:|---:|---:|---|---|---|")
    for n, who, r, g in rows:
        name = "GetFEM basic contact (Alart-Curnier)" if who == "getfem" else f"bipot {who}"
        if "failed" in r:
            print(f"| {n} | | {name} | failed: {r['failed']} | | | | | | | |")
            continue
        its = r["newton"]
        line = (f"| {n} | {r['dofs']} | {name} | {r['wall']:.2f} | {r['step_time']:.3f} | "
                f"{statistics.mean(its):.2f}, {max(its)} | {r['solves']:.2f} |")
        if g is not None and "failed" not in g:
            more = [k + 1 for k, (a, b) in enumerate(zip(its, g["newton"])) if a > b]
            line += f" {len(more)}" + (f" (steps {','.join(map(str, more))})" if more else "")
            line += " |"
            c = compare(r, g)
            agree = all(x <= 1e-6 for s in c for x in s[:2]) and all(
                not (s[2] > 1e-6) for s in c)
            line += "".join(f" {s[0]:.1e}, {s[1]:.1e}, {s[2]:.1e} |" for s in c)
            line += " yes |" if agree else " **no** |"
        else:
            line += " | | | |"
        print(line)
    ratios = [(n, who, g["wall"] / r["wall"], g["step_time"] / r["step_time"])
              for n, who, r, g in rows
              if g is not None and "failed" not in r and "failed" not in g]
    if ratios:
        print("\nSpeed-up of bipot over GetFEM (GetFEM time / bipot time), total and per step:")
        for n, who, total, step in ratios:
            print(f"  n = {n:4d}  {who:20s} total {total:6.2f}x  per step {step:6.2f}x")


if __name__ == "__main__":
    main()
