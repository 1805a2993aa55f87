#!/usr/bin/python3
"""Figures from the CSV files the pile_pullout app writes in its results directory.

  curves   head force vs head displacement of the pull-out stage, one line per run
  profiles skin friction, contact pressure, beta and slip along the shaft, one line per step

The shebang names Debian's interpreter because that is the one python3-matplotlib installs
into; a python3 earlier on PATH (pyenv, venv) may lack it. Needs only matplotlib (Agg).
"""
import argparse
import csv
import os
import re
import sys
import tempfile

HEAD_CSV = "head_force.csv"
PROFILE_CSV = "profiles.csv"
HEAD_COLUMNS = ("step", "stage", "head_displacement_mm", "head_force_kN", "unstable")
PROFILE_COLUMNS = ("step", "head_displacement_mm", "depth_m", "skin_friction_kPa",
                   "contact_pressure_kPa", "beta", "slip_mm")
TEXT_COLUMNS = ("stage", "status")  # everything else is read as a number


class PlotError(Exception):
    """A problem with the user's data: reported as one line naming the file, exit code 1."""


def read_csv(path, columns):
    """Rows of `path` as dicts with the named columns converted; extra columns are kept."""
    try:
        with open(path, newline="") as f:
            reader = csv.reader(f)
            header = [h.strip() for h in next(reader, [])]
            missing = [c for c in columns if c not in header]
            if missing:
                raise PlotError(f"{path}: missing column(s) {', '.join(missing)}"
                                f" (header: {','.join(header) or 'empty'})")
            rows = []
            for fields in reader:
                if not fields:
                    continue  # a trailing blank line is not data
                if len(fields) != len(header):
                    raise PlotError(f"{path}:{reader.line_num}: {len(fields)} fields,"
                                    f" header has {len(header)}")
                row = dict(zip(header, (v.strip() for v in fields)))
                for c in columns:
                    if c not in TEXT_COLUMNS:
                        try:
                            row[c] = float(row[c])
                        except ValueError:
                            raise PlotError(f"{path}:{reader.line_num}: column {c}:"
                                            f" '{row[c]}' is not a number") from None
                rows.append(row)
            return rows
    except OSError as e:
        raise PlotError(f"{path}: {e.strerror}") from None


def save_atomically(fig, out):
    """Write the PNG under a temporary name beside `out`, then rename: a reader (or an
    interrupted run) never sees half an image, and os.replace is atomic within one folder."""
    folder = os.path.dirname(os.path.abspath(out))
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + os.path.basename(out) + ".",
                                   suffix=".tmp")
    except OSError as e:
        raise PlotError(f"{out}: cannot write in {folder}: {e.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as f:
            fig.savefig(f, format="png", dpi=150)
        os.chmod(tmp, 0o644)  # mkstemp makes it private; a figure is for everyone to read
        os.replace(tmp, out)
    except BaseException as e:
        os.unlink(tmp)
        if isinstance(e, OSError):
            raise PlotError(f"{out}: {e.strerror}") from None
        raise
    print(out)


def run_spec(text):
    """LABEL=RESULTS_DIR; split at the first '=' so a directory may contain one."""
    label, sep, folder = text.partition("=")
    if not sep or not label or not folder:
        raise argparse.ArgumentTypeError(f"expected LABEL=RESULTS_DIR, got '{text}'")
    return label, folder


def plot_curves(args, Figure):
    fig = Figure(figsize=(7, 5), layout="constrained")
    ax = fig.add_subplot()
    any_unstable = any_traced = False
    for label, folder in args.runs:
        path = os.path.join(folder, HEAD_CSV)
        rows = read_csv(path, HEAD_COLUMNS)
        if not rows:
            raise PlotError(f"{path}: no data rows")
        rows = [r for r in rows if r["stage"] == "pullout"]
        if not rows:
            raise PlotError(f"{path}: no rows of stage 'pullout'")
        u = [r["head_displacement_mm"] for r in rows]
        force = [r["head_force_kN"] for r in rows]
        # A dot per step while they can be told apart; a run whose energy_tolerance halves it
        # into thousands of steps reads better as a line.
        (line,) = ax.plot(u, force, marker="." if len(rows) <= 300 else None, label=label)
        bad = [r for r in rows if r["unstable"] != 0]
        if bad:
            # Hollow markers in the run's colour: the step converged, but only after cut-backs
            # or across a sudden drop of the interface force, so read the curve there with care.
            any_unstable = True
            ax.plot([r["head_displacement_mm"] for r in bad], [r["head_force_kN"] for r in bad],
                    linestyle="none", marker="o", markersize=8, markerfacecolor="none",
                    markeredgecolor=line.get_color())
        # Path-following (control: dissipation / arc_length): the steps traced with the load
        # factor as an unknown, the snap-back's falling branch among them. Older CSVs have no
        # `traced` column.
        traced = [r for r in rows if float(r.get("traced", 0) or 0) != 0]
        if traced:
            any_traced = True
            ax.plot([r["head_displacement_mm"] for r in traced],
                    [r["head_force_kN"] for r in traced], linestyle="none", marker="x",
                    markersize=5, color=line.get_color())
    if any_unstable:
        ax.plot([], [], linestyle="none", marker="o", markerfacecolor="none",
                markeredgecolor="0.3",
                label="unstable step (cut-backs / force drop / load falling)")
    if any_traced:
        ax.plot([], [], linestyle="none", marker="x", color="0.3",
                label="traced step (path-following)")
    ax.set_xlabel("head displacement (mm, upward)")
    ax.set_ylabel("head force (kN, pull-out)")
    ax.set_title(args.title or "Pile pull-out: head force vs head displacement")
    ax.grid(True, alpha=0.4)
    ax.legend()
    save_atomically(fig, args.out)


def plot_profiles(args, Figure, colormaps):
    if not os.path.isdir(args.results_dir):
        raise PlotError(f"{args.results_dir}: no such results directory")
    path = os.path.join(args.results_dir, PROFILE_CSV)
    rows = read_csv(path, PROFILE_COLUMNS) if os.path.exists(path) else []
    if not rows:
        # A bonded pile has no split interface, hence no profiles: nothing to draw, not an error.
        print(f"{path}: no interface profiles (bonded pile?), no figure written",
              file=sys.stderr)
        return
    steps = {}  # step -> its rows, in file order (the app writes them by increasing depth)
    for r in rows:
        steps.setdefault(r["step"], []).append(r)
    panels = (("skin_friction_kPa", "skin friction (kPa)"),
              ("contact_pressure_kPa", "contact pressure (kPa)"),
              ("beta", "beta (-)"),
              ("slip_mm", "slip (mm, pile upward)"))
    fig = Figure(figsize=(12, 6), layout="constrained")
    axes = fig.subplots(1, len(panels), sharey=True)
    cmap = colormaps["viridis"]
    for i, (step, group) in enumerate(steps.items()):
        # Colour runs with the step number so the load history reads left to right in the map.
        colour = cmap(i / max(len(steps) - 1, 1))
        depth = [r["depth_m"] for r in group]
        label = f"{group[0]['head_displacement_mm']:.3g} mm"
        stage = group[0].get("stage", "pullout")
        if stage and stage != "pullout":
            label += f" ({stage})"  # end-of-stage profiles taken before the pull starts
        for ax, (column, _) in zip(axes, panels):
            ax.plot([r[column] for r in group], depth, color=colour, label=label)
    for ax, (_, title) in zip(axes, panels):
        ax.set_xlabel(title)
        ax.grid(True, alpha=0.4)
    axes[2].set_xlim(-0.05, 1.05)  # beta is a fraction; fix the range so 0 and 1 read at a glance
    axes[0].set_ylabel("depth (m)")
    axes[0].invert_yaxis()  # shared axis: depth grows downward in all four panels
    # Beside the panels, not on them: a legend inside would hide the deep end of some curve.
    axes[-1].legend(title="head displacement", fontsize="small", loc="upper left",
                    bbox_to_anchor=(1.02, 1))
    # The app plots before it renames its folder from <dir>.running-<pid> to <dir>: name that.
    shown = re.sub(r"\.running-\d+$", "", args.results_dir.rstrip("/"))
    fig.suptitle(args.title or f"Shaft profiles: {shown}")
    save_atomically(fig, args.out)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    c = sub.add_parser("curves", help="head force vs head displacement, several runs")
    c.add_argument("out", metavar="OUT.png")
    c.add_argument("runs", metavar="LABEL=RESULTS_DIR", nargs="+", type=run_spec)
    c.add_argument("--title")
    p = sub.add_parser("profiles", help="interface profiles along the shaft, one run")
    p.add_argument("out", metavar="OUT.png")
    p.add_argument("results_dir", metavar="RESULTS_DIR")
    p.add_argument("--title")
    args = parser.parse_args(argv)

    # Imported only now so --help works without matplotlib, and a missing install is one line.
    try:
        import matplotlib
        matplotlib.use("Agg")  # files only, no display needed
        from matplotlib import colormaps
        from matplotlib.figure import Figure
    except ImportError:
        print(f"{sys.argv[0]}: needs matplotlib (Debian: apt-get install python3-matplotlib)"
              f" for {sys.executable}", file=sys.stderr)
        return 1
    try:
        if args.command == "curves":
            plot_curves(args, Figure)
        else:
            plot_profiles(args, Figure, colormaps)
    except PlotError as e:
        print(f"{os.path.basename(sys.argv[0])}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
