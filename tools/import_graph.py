"""The module import graph of the ``mechdesign`` package and its cycles (issue 17, point 4).

    python tools/import_graph.py [--src src] [--edges] [--allow A->B ...]

Every ``import`` and ``from … import`` anywhere in a module counts, also those inside
functions, methods and ``if TYPE_CHECKING:`` blocks (a function-level import is still a
dependency, only a later one). Edges:

* ``import a.b.c`` and ``from a.b import c`` depend on ``a.b.c`` if it is a module of the
  package, else on the nearest enclosing module or package (``a.b``);
* importing ``a.b.c`` also runs ``a/__init__.py`` and ``a/b/__init__.py``, so a module
  depends on the ``__init__`` of every package on the way (except its own packages, which
  are already imported when it runs);
* only modules of the scanned package are nodes; the standard library and third-party
  imports are ignored.

Prints the strongly connected components with more than one module (Tarjan) — the import
cycles — one per line, and exits 1 when there is any (0 when none). ``--allow A->B``
removes one edge before the search (for a cycle that is being removed elsewhere).
"""
from __future__ import annotations

import argparse
import ast
import sys
from pathlib import Path

PACKAGE = "mechdesign"


def modules(src: Path, package: str = PACKAGE) -> dict[str, Path]:
    """Dotted module name → file, for every ``.py`` file of ``package`` under ``src``
    (a package is named by its ``__init__.py``)."""
    out = {}
    root = src / package
    for path in sorted(root.rglob("*.py")):
        parts = list(path.relative_to(src).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _is_package(name: str, mods: dict[str, Path]) -> bool:
    return name in mods and mods[name].name == "__init__.py"


def _resolve(name: str, mods: dict[str, Path]) -> str | None:
    """``name`` or its nearest enclosing module of the package; None if outside it."""
    parts = name.split(".")
    while parts:
        cand = ".".join(parts)
        if cand in mods:
            return cand
        parts.pop()
    return None


def _with_parents(target: str, importer: str, mods: dict[str, Path]) -> set[str]:
    """``target`` and the ``__init__`` of every package above it that ``importer`` is not in."""
    out = {target}
    parts = target.split(".")
    own = importer.split(".")
    if not _is_package(importer, mods):
        own = own[:-1]                               # a plain module's own package
    for i in range(1, len(parts)):
        pkg = ".".join(parts[:i])
        mine = own[:i] == parts[:i] and len(own) >= i
        if pkg in mods and not mine:
            out.add(pkg)
    return out


def imports_of(name: str, path: Path, mods: dict[str, Path]) -> set[str]:
    """Modules of the package that module ``name`` (file ``path``) imports, anywhere in it."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    package = name if _is_package(name, mods) else name.rpartition(".")[0]
    targets: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                t = _resolve(alias.name, mods)
                if t is not None:
                    targets |= _with_parents(t, name, mods)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")
                if node.level > 1:
                    base = base[:len(base) - (node.level - 1)]
                base_name = ".".join(base + ([node.module] if node.module else []))
            else:
                base_name = node.module or ""
            for alias in node.names:
                full = f"{base_name}.{alias.name}" if alias.name != "*" else base_name
                t = full if full in mods else _resolve(base_name, mods)
                if t is not None:
                    targets |= _with_parents(t, name, mods)
    targets.discard(name)
    return targets


def graph(src: Path, package: str = PACKAGE) -> dict[str, set[str]]:
    """Module → the package's modules it imports."""
    mods = modules(src, package)
    return {name: imports_of(name, path, mods) for name, path in mods.items()}


def cycles(g: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components of more than one module (or a module importing
    itself), each sorted, the list sorted (Tarjan's algorithm, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    on_stack: set[str] = set()
    stack: list[str] = []
    out: list[list[str]] = []
    counter = 0
    for root in sorted(g):
        if root in index:
            continue
        work = [(root, iter(sorted(g[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            v, it = work[-1]
            for w in it:
                if w not in g:
                    continue
                if w not in index:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(g[w]))))
                    break
                if w in on_stack:
                    low[v] = min(low[v], index[w])
            else:
                work.pop()
                if work:
                    u = work[-1][0]
                    low[u] = min(low[u], low[v])
                if low[v] == index[v]:
                    comp = []
                    while True:
                        w = stack.pop()
                        on_stack.discard(w)
                        comp.append(w)
                        if w == v:
                            break
                    if len(comp) > 1 or v in g[v]:
                        out.append(sorted(comp))
    return sorted(out)


def without(g: dict[str, set[str]], allowed) -> dict[str, set[str]]:
    """A copy of ``g`` without the edges ``allowed`` ((importer, imported) pairs)."""
    drop = set(allowed)
    return {v: {w for w in ws if (v, w) not in drop} for v, ws in g.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--src", type=Path, default=Path(__file__).resolve().parents[1] / "src")
    ap.add_argument("--edges", action="store_true", help="print every edge of the graph too")
    ap.add_argument("--allow", action="append", default=[], metavar="A->B",
                    help="ignore the edge A → B (dotted module names); repeatable")
    args = ap.parse_args(argv)
    g = graph(args.src)
    allowed = [tuple(a.split("->")) for a in args.allow]
    g = without(g, allowed)
    if args.edges:
        for v in sorted(g):
            for w in sorted(g[v]):
                print(f"{v} -> {w}")
    found = cycles(g)
    n_edges = sum(len(ws) for ws in g.values())
    print(f"{len(g)} modules, {n_edges} imports, {len(found)} cycle(s)")
    for comp in found:
        print(f"cycle ({len(comp)} modules): " + ", ".join(comp))
        inner = set(comp)
        for v in comp:
            for w in sorted(g[v] & inner):
                print(f"    {v} -> {w}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
