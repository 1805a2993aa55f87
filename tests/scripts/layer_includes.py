#!/usr/bin/env python3
"""Fails when a source file includes a layer it may not (docs/architecture.md, "Architecture").

Each layer may include itself and the layers it depends on, directly or through them (the
"depends on" column of the table in docs/architecture.md, encoded below), and only its own
third-party headers (Trilinos and MUMPS in fem/linalg, VTK in fem/io, yaml-cpp in fem/input;
Gmsh in none). Tests are not checked: they may include any layer.

Usage: layer_includes.py SOURCE_ROOT     (a CTest test: layer_includes)
"""
import os
import re
import sys

# layer directory -> the layers it depends on (the table's "depends on" column).
DEPENDS = {
    "fem/core": [],
    "fem/mesh": ["fem/core"],
    "fem/element": ["fem/core", "fem/mesh"],
    "materials": ["fem/core"],
    "contact/laws": ["fem/core"],
    "fem/linalg": ["fem/core"],
    "fem/assembly": ["fem/element", "fem/linalg"],
    "contact/interface": ["fem/mesh", "fem/element", "contact/laws"],
    "contact/solver": ["contact/laws", "contact/interface", "fem/assembly", "fem/linalg"],
    "fem/io": ["fem/mesh"],
    "fem/gmsh": ["fem/mesh"],
    # TODAY'S EXCEPTION: fem/linalg in fem/input, for the linear solver's parameter schema
    # (LinearSolver::schema) the reader validates `linear_solver:` against.
    "fem/input": ["fem/core", "fem/mesh", "fem/element", "fem/linalg"],
    "fem/analysis": ["fem/core", "fem/mesh", "fem/element", "fem/assembly", "fem/linalg",
                     "fem/io", "fem/gmsh", "fem/input"],
    # The built-in catalogue: where bipot's own materials and laws are wired in.
    "apps/catalogue": ["fem/analysis", "materials", "contact/laws", "contact/interface",
                       "contact/solver"],
    "apps/common": ["fem/analysis", "apps/catalogue"],
    "apps/bipot": ["fem/analysis", "apps/common", "apps/catalogue"],
    "apps/pile_pullout": ["fem/analysis", "fem/input", "apps/common", "apps/catalogue"],
}

# Third-party headers -> the only layers that may include them.
THIRD_PARTY = [
    (re.compile(r"^(Teuchos|Tpetra|Belos|MueLu|Ifpack2|Amesos2|Kokkos|Xpetra|Zoltan2)"),
     "Trilinos", {"fem/linalg"}),
    (re.compile(r"^[dszc]mumps"), "MUMPS", {"fem/linalg"}),
    # TODAY'S EXCEPTION: apps/common calls MPI_Abort itself (an error on one rank alone ends
    # every rank, apps/common/app_support.cpp); the table keeps MPI private to fem/linalg.
    (re.compile(r"^mpi\.h$"), "MPI", {"fem/linalg", "apps/common"}),
    (re.compile(r"^vtk"), "VTK", {"fem/io"}),
    # libgmsh's reader crashes on malformed files: bipot reads .msh itself (fem/gmsh), and
    # only tests use libgmsh, to write meshes.
    (re.compile(r"^gmsh\.h$"), "Gmsh", set()),
    (re.compile(r"^yaml-cpp/"), "yaml-cpp", {"fem/input"}),
]

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SOURCE_DIRS = ["fem", "contact", "materials", "apps"]
EXTENSIONS = (".cpp", ".hpp", ".h")


def closure(layer):
    """The layer itself and everything it depends on, directly or not."""
    seen, todo = set(), [layer]
    while todo:
        current = todo.pop()
        if current in seen:
            continue
        seen.add(current)
        todo.extend(DEPENDS[current])
    return seen


def layer_of(path):
    """The layer a path (file or included header, relative to the root) belongs to."""
    best = None
    for layer in DEPENDS:
        if path.startswith(layer + "/") and (best is None or len(layer) > len(best)):
            best = layer
    return best


def check(root):
    problems, files = [], 0
    for top in SOURCE_DIRS:
        for dirpath, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if not name.endswith(EXTENSIONS):
                    continue
                files += 1
                rel = os.path.relpath(os.path.join(dirpath, name), root)
                layer = layer_of(rel)
                if layer is None:
                    problems.append(f"{rel}: in no layer of the table; add its directory to "
                                    "docs/architecture.md and tests/scripts/layer_includes.py")
                    continue
                allowed = closure(layer)
                with open(os.path.join(root, rel), encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        quote, header = m.groups()
                        where = f"{rel}:{number}: {layer}"
                        if quote == '"' and header.split("/")[0] in SOURCE_DIRS:
                            target = layer_of(header)
                            if target is None:
                                problems.append(f"{where} includes \"{header}\", in no layer")
                            elif target not in allowed:
                                problems.append(f"{where} includes \"{header}\" of layer "
                                                f"{target}, which it may not (it may include: "
                                                f"{', '.join(sorted(allowed))})")
                            continue
                        for pattern, package, owners in THIRD_PARTY:
                            if pattern.search(header) and layer not in owners:
                                problems.append(f"{where} includes {package} header <{header}>, "
                                                f"private to {', '.join(sorted(owners))}")
    return problems, files


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")
    problems, files = check(root)
    if files == 0:
        print(f"layer_includes: no source files under {root}", file=sys.stderr)
        return 1
    if problems:
        print(f"layer_includes: {len(problems)} include(s) break the layering of "
              "docs/architecture.md:", file=sys.stderr)
        for p in problems:
            print("  " + p, file=sys.stderr)
        return 1
    print(f"layer_includes: {files} files, every include allowed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
