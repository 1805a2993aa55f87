"""GetFEM side of bench/footing.py (--getfem): the same strip footing, solved by GetFEM's
small-strain elastoplasticity brick on bipot's own tri6 mesh.

- Mesh: read from the first .vtu of a bipot run of the same input (nodes and VTK quadratic
  triangles), made a GT_PK(2,2) mesh with FEM_PK(2,2) displacements: the same nodes, so the
  same DOFs (2 per node). VTK numbers a quadratic triangle's nodes corners first, then the
  mid-edge nodes 01, 12, 20; GetFEM's PK(2,2) numbers them row by row in the reference
  triangle: 0, 01, 1, 20, 12, 2.
- Model: `add_small_strain_elastoplasticity_brick` with the law "plane strain Prandtl Reuss"
  (von Mises, no hardening, with the out-of-plane components), "displacement only" (the
  return mapping at each integration point; the plastic multiplier is stored data), theta 1
  (backward Euler), integration IM_TRIANGLE(2): the 3-point rule at (1/6, 1/6), (2/3, 1/6),
  (1/6, 2/3), the one bipot uses for tri6. `small_strain_elastoplasticity_next_iter` commits
  each increment.
- Constraints: the homogeneous ones (bottom x and y, left and right x) by removing those
  DOFs (reduction matrices); the footing's settlement u_y = s by a multiplier on the P2
  nodes of the footing (a filtered FEM_PK(2,2) variable) and the term
  E (u_y - s) mu + E lam v_y integrated with IM_TRIANGLE(6) (exact: u_y = s at every footing
  node; the footing's x stays free: smooth footing). The factor E makes the constraint rows
  forces: GetFEM's Dirichlet bricks give them in m^2, and its Newton adds every row into one
  norm (its backtracking then compared a force residual with a 1e-3 m^2 start: tried first,
  it stalled).
- Newton: `Model.solve` with its default line search. In GetFEM 5.4 (Debian's python3-getfem)
  the Python interface's 'default' is the Newton "with step control" (not the older
  default_newton_line_search): it solves F(U) = (1 - alpha) F(U0), alpha = 1 first, halved
  back towards the last reached alpha after more than 10 stagnating iterations, and each
  step is halved (down to 1e-5) only while the residual exceeds a multiple of the last one
  (2, times 0.93 per iteration, down to 1.05): steps that raise the residual are accepted.
  The other line searches ('basic', the older default, ...) go through the classical
  Newton, which also stops on a small step: ||dU||_1 / ||U||_1 <= max_res.
  Converged when ||F||_1 (every row) <= max_res x approx_external_load; no brick here
  declares an external load, so GetFEM takes 1 and max_res = tolerance x reference is a force
  with bipot's reference: the 2-norm of the nodal reactions on every constrained DOF at the
  last converged increment (in the first one, the 2-norm of the free rows' forces with only
  the settlement applied). The 1-norm makes this stricter than bipot's 2-norm test by at most
  sqrt(rows); --getfem-norm2-bound runs the looser bound (x sqrt(rows)) to bracket it.
- Start: each increment from the last converged state, GetFEM's way (its first iteration
  applies the settlement through the tangent), or with --getfem-extrapolate from the last
  increment extrapolated, bipot's predictor. The zero state has an empty tangent in this law
  (the deviator's norm is differentiated at 0) and MUMPS calls it singular, so the first
  increment starts from a 1e-12 m random displacement.

After each increment: the internal forces f = int sigma : grad(phi) on the unreduced space
(sigma from the committed plastic strain), the footing force sum f_y over the footing's
nodes (q = F / (B/2)), the reactions and bipot's residual measure ||f_free||_2 /
reference, to show how tightly GetFEM converged.
"""
import os
import sys
import tempfile
import time

import numpy as np

from frictional_block import read_vtu

HALF_WIDTH = 0.5
VTK_TO_GETFEM_TRI6 = [0, 3, 1, 5, 4, 2]


def tri6_mesh(vtu):
    """(points (n, 2), cells (m, 6) in VTK order) of bipot's output."""
    g = read_vtu(vtu)
    if set(t[0] for t in g["types"]) != {22}:
        sys.exit(f"{vtu}: not a mesh of quadratic triangles only")
    pts = np.array(g["points"], dtype=float)[:, :2]
    cells = np.array([c[0] for c in g["connectivity"]], dtype=int).reshape(-1, 6)
    return pts, cells


class _Capture:
    """Collects what GetFEM's C++ code prints on file descriptor 1 (its 'noisy' history)."""

    def __enter__(self):
        sys.stdout.flush()
        self.file = tempfile.TemporaryFile(mode="w+")
        self.saved = os.dup(1)
        os.dup2(self.file.fileno(), 1)
        return self

    def __exit__(self, *exc):
        sys.stdout.flush()
        os.dup2(self.saved, 1)
        os.close(self.saved)
        self.file.seek(0)
        self.text = self.file.read()
        self.file.close()


def run_getfem(vtu, increments, settlement, c, young, poisson, tolerance, lsearch="default",
               lsolver="mumps", norm2_bound=False, extrapolate=False, max_iter=200, log=None):
    import getfem as gf
    gf.util_trace_level(0)
    t_start = time.perf_counter()
    pts, cells = tri6_mesh(vtu)
    m = gf.Mesh("empty", 2)
    m.add_convex(gf.GeoTrans("GT_PK(2,2)"),
                 np.ascontiguousarray(pts[cells[:, VTK_TO_GETFEM_TRI6]].transpose(2, 1, 0)))
    if m.nbpts() != len(pts):
        sys.exit(f"GetFEM merged the mesh's {len(pts)} nodes into {m.nbpts()}")
    mfu = gf.MeshFem(m, 2)
    mfu.set_fem(gf.Fem("FEM_PK(2,2)"))
    nd = mfu.nb_basic_dof()
    x = mfu.basic_dof_nodes()
    # A vector Lagrange FEM numbers a node's x and y DOFs consecutively.
    assert np.array_equal(x[:, 0::2], x[:, 1::2]) and nd == 2 * len(pts)
    tol = 1e-9
    xmax, ymax = x[0].max(), x[1].max()
    xdof = np.arange(nd) % 2 == 0
    fixed = (np.abs(x[1]) < tol) | (xdof & ((np.abs(x[0]) < tol) | (np.abs(x[0] - xmax) < tol)))
    footing = ~xdof & (np.abs(x[1] - ymax) < tol) & (x[0] <= HALF_WIDTH + tol)
    free = ~fixed & ~footing  # bipot's free rows
    keep = np.flatnonzero(~fixed)
    R = gf.Spmat("empty", len(keep), nd)
    Ext = gf.Spmat("empty", nd, len(keep))
    for i, d in enumerate(keep):
        R[i, int(d)] = 1.0
        Ext[int(d), i] = 1.0
    mfu.reduction_matrices(R, Ext)

    FOOTING = 1
    top = m.outer_faces_with_direction([0.0, 1.0], 0.01)
    mpts = m.pts()
    on = [j for j in range(top.shape[1])
          if np.all(mpts[0, m.pid_in_faces(top[:, j:j + 1])] <= HALF_WIDTH + tol)]
    m.set_region(FOOTING, top[:, on])

    mim = gf.MeshIm(m, gf.Integ("IM_TRIANGLE(2)"))
    mim_bc = gf.MeshIm(m, gf.Integ("IM_TRIANGLE(6)"))
    lame_lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
    lame_mu = young / (2 * (1 + poisson))
    md = gf.Model("real")
    md.add_fem_variable("u", mfu)
    md.add_fem_data("Previous_u", mfu)
    mimd1 = gf.MeshImData(mim)
    mimd4 = gf.MeshImData(mim, -1, [2, 2])
    md.add_im_data("xi", mimd1)
    md.add_im_data("Previous_xi", mimd1)
    md.add_im_data("Previous_Ep", mimd4)
    md.add_initialized_data("lambda", [lame_lambda])
    md.add_initialized_data("mu", [lame_mu])
    md.add_initialized_data("sigma_y", [np.sqrt(3.0) * c])
    law = (mim, "plane strain Prandtl Reuss", "displacement only", "u", "xi", "Previous_Ep",
           "lambda", "mu", "sigma_y", "1", "timestep")
    md.add_small_strain_elastoplasticity_brick(*law)
    md.set_time_step(1.0)
    md.add_initialized_data("settle", [0.0])
    # The footing: u_y = settle, with P2 multipliers on the footing's nodes, the constraint
    # rows scaled by E so that the residual's rows are all forces (GetFEM's Dirichlet bricks
    # give them in m^2, which its Newton adds to the forces' norm).
    mfl = gf.MeshFem(m, 1)
    mfl.set_fem(gf.Fem("FEM_PK(2,2)"))
    md.add_filtered_fem_variable("lam", mfl, FOOTING)
    md.add_initialized_data("S", [young])
    md.add_nonlinear_term(mim_bc, "S*(u(2)-settle)*Test_lam+S*lam*Test_u(2)", FOOTING)

    # Internal forces on the unreduced space, from the committed plastic strain.
    mff = gf.MeshFem(m, 2)
    mff.set_fem(gf.Fem("FEM_PK(2,2)"))
    post = gf.Model("real")
    post.add_fem_variable("v", mff)
    post.add_fem_data("U", mff)
    post.add_im_data("Ep", mimd4)
    post.add_initialized_data("lambda", [lame_lambda])
    post.add_initialized_data("mu", [lame_mu])
    sigma = "(lambda*Trace(Sym(Grad_U))*Id(2)+2*mu*(Sym(Grad_U)-Ep))"

    def internal_forces(u_full, ep):
        post.set_variable("U", u_full)
        post.set_variable("Ep", ep)
        return gf.asm_generic(mim, 1, sigma + ":Grad_Test_v", -1, post)

    def full(u_red):
        u = np.zeros(nd)
        u[keep] = u_red
        return u

    md.set_variable("u", 1e-12 * np.random.default_rng(1).standard_normal(len(keep)))
    # First reference: the free rows' forces with only the settlement applied.
    u1 = np.zeros(nd)
    u1[footing] = -settlement / increments
    ep0 = np.zeros(len(md.variable("Previous_Ep")))
    reference = float(np.linalg.norm(internal_forces(u1, ep0)[free]))
    rows = md.nbdof()
    u_prev = None
    its, conv, times, checks, histories, refs = [], [], [], [], [], []
    q = float("nan")
    for k in range(1, increments + 1):
        g = -settlement * k / increments
        md.set_variable("settle", [g])
        u_now = md.variable("u")
        if extrapolate and u_prev is not None:
            md.set_variable("u", 2 * u_now - u_prev)
        u_prev = u_now
        refs.append(reference)
        scale = reference * (np.sqrt(rows) if norm2_bound else 1.0)
        max_res = tolerance * scale
        t0 = time.perf_counter()
        with _Capture() as cap:
            nit, ok = md.solve("noisy", "max_res", max_res, "max_iter", max_iter,
                               "lsolver", lsolver, "lsearch", lsearch)
        times.append(time.perf_counter() - t0)
        histories.append([float(line.split("residual")[1]) / reference
                          for line in cap.text.splitlines() if "residual" in line])
        its.append(int(nit))
        conv.append(bool(ok))
        md.small_strain_elastoplasticity_next_iter(*law)
        f = internal_forces(full(md.variable("u")), md.variable("Previous_Ep"))
        checks.append(float(np.linalg.norm(f[free])) / reference)
        if log:
            print(f"#   GetFEM increment {k}: {nit} iterations, {times[-1]:.1f} s", file=log,
                  flush=True)
        q = abs(float(f[footing].sum())) / HALF_WIDTH
        reference = float(np.linalg.norm(f[~free]))
        if not ok:
            break
    return {"dofs": nd, "rows": rows, "increments": len(its), "newton": its, "converged": conv,
            "seconds": time.perf_counter() - t_start, "solve": sum(times),
            "q_over_c": q / c, "free_residual": checks, "histories": histories,
            "references": refs}
