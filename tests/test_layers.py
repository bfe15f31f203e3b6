"""The packages of dynagrade import downwards only (docs/design.md, "Layers").

Every import of every module is read with :mod:`ast` (those inside functions and
``TYPE_CHECKING`` blocks too: a lazy import is still a dependency) and resolved to the
package of dynagrade it names; each package may import only the packages listed for it.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import dynagrade

SOURCE = Path(dynagrade.__file__).parent

#: the modules beside the layers, which every layer may import (and which import nothing
#: of dynagrade): the error root and the interface's languages
BESIDE_THE_LAYERS = ("errors", "i18n")

#: what each package may import, besides itself and the modules beside the layers
ALLOWED = {
    "mechanics": set(),
    "grading": set(),
    "exercise": {"grading"},
    "runs": {"exercise"},
    "exam": {"exercise", "grading", "runs"},
    "render": {"exam", "exercise", "grading", "runs"},
    "generation": {"exam", "exercise", "grading", "render", "runs"},
    "classgrade": {"exam", "exercise", "grading", "render", "runs"},
    "serve": {"classgrade", "exam", "exercise", "generation", "grading", "render", "runs"},
}


def _package_of(path: Path) -> str:
    relative = path.relative_to(SOURCE).parts
    return relative[0] if len(relative) > 1 else relative[0].removesuffix(".py")


def _imported_packages(path: Path) -> set[str]:
    """The top-level packages of dynagrade that the module at ``path`` imports."""
    package_parts = path.relative_to(SOURCE.parent).with_suffix("").parts[:-1]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package_parts[:len(package_parts) - node.level + 1]
                target = (*base, *(node.module.split(".") if node.module else ()))
                names = [(*target, alias.name) for alias in node.names] \
                    if len(target) == 1 else [target]
            else:
                names = [tuple((node.module or "").split("."))]
        elif isinstance(node, ast.Import):
            names = [tuple(alias.name.split(".")) for alias in node.names]
        else:
            continue
        for name in names:
            if name[0] == "dynagrade" and len(name) > 1 and name[1] != "__name__":
                found.add(name[1].removesuffix(".py"))
    return found


MODULES = sorted(p for p in SOURCE.rglob("*.py") if _package_of(p) in ALLOWED)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(SOURCE)))
def test_a_module_imports_only_the_packages_below_its_own(path):
    own = _package_of(path)
    upward = _imported_packages(path) - ALLOWED[own] - {own, *BESIDE_THE_LAYERS}
    assert not upward, f"{path.relative_to(SOURCE)} ({own}) imports {sorted(upward)}"


def test_the_scan_sees_relative_lazy_and_absolute_imports(tmp_path):
    package = tmp_path / "dynagrade" / "render"
    package.mkdir(parents=True)
    module = package / "example.py"
    module.write_text("from ..exam.manifest import Manifest\n"
                      "from .. import classgrade\n"
                      "def later():\n    import dynagrade.serve.app\n")
    global SOURCE
    kept, SOURCE = SOURCE, tmp_path / "dynagrade"
    try:
        assert _imported_packages(module) == {"exam", "classgrade", "serve"}
    finally:
        SOURCE = kept
    assert len(MODULES) > 100


def test_every_package_of_dynagrade_has_its_place_in_the_layers():
    packages = {p.name for p in SOURCE.iterdir()
                if p.is_dir() and (p / "__init__.py").exists()} - {"bank", "templates"}
    assert packages == set(ALLOWED)


def _module_name(path: Path) -> str:
    parts = path.relative_to(SOURCE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imported_modules(path: Path, known: set[str]) -> set[str]:
    """The modules of dynagrade that the module at ``path`` imports (lazy ones too)."""
    package = _module_name(path) if path.name == "__init__.py" \
        else _module_name(path).rsplit(".", 1)[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            base = package.split(".")
            if node.level:
                base = base[:len(base) - node.level + 1]
                stem = ".".join([*base, *([node.module] if node.module else [])])
            else:
                stem = node.module or ""
            candidates = [f"{stem}.{alias.name}" for alias in node.names] + [stem]
        elif isinstance(node, ast.Import):
            candidates = [alias.name for alias in node.names]
        else:
            continue
        found.update(c for c in candidates if c in known)
    own = _module_name(path)
    ancestors = {own.rsplit(".", n)[0] for n in range(1, own.count(".") + 1)}
    return found - {own} - ancestors  # a parent package is imported before any module


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The groups of modules that import each other, round a circle (Tarjan's strongly
    connected components of more than one module)."""
    index, low, stack, on_stack, groups = {}, {}, [], set(), []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for nxt in graph[node]:
            if nxt not in index:
                visit(nxt)
                low[node] = min(low[node], low[nxt])
            elif nxt in on_stack:
                low[node] = min(low[node], index[nxt])
        if low[node] == index[node]:
            group = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                group.append(member)
                if member == node:
                    break
            if len(group) > 1:
                groups.append(sorted(group))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return groups


def test_no_modules_import_each_other_in_a_circle():
    """A circle (listing ↔ model ↔ solution, once) means neither module can be read,
    tested or moved without the other; lazy and type-only imports count."""
    paths = {_module_name(p): p for p in SOURCE.rglob("*.py")}
    graph = {name: _imported_modules(path, set(paths)) for name, path in paths.items()}
    assert sum(map(len, graph.values())) > 300  # the scan sees the imports
    assert _cycles(graph) == []


def test_the_circle_check_finds_a_circle():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
