"""The shape of the mechanics package, checked by reading its source (ast), never by trust:
one taxonomy (the core never imports the worked-example subpackage), unique public names,
one argument convention, type hints, and no scipy at import.
"""
import ast
from pathlib import Path

import pytest

import dynagrade.mechanics

PACKAGE = Path(dynagrade.mechanics.__file__).parent
EXAMPLES = PACKAGE / "examples"
CORE_MODULES = sorted(p for p in PACKAGE.glob("*.py") if p.name != "__init__.py")
EXAMPLE_MODULES = sorted(p for p in EXAMPLES.glob("*.py") if p.name != "__init__.py")
ALL_MODULES = CORE_MODULES + EXAMPLE_MODULES


def _tree(path):
    return ast.parse(path.read_text(encoding="utf-8"), filename=str(path))


def _imported_modules(tree):
    """Every module an import statement anywhere in the tree names (`from a import b` names
    both `a` and `a.b`, since b may be a module)."""
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = "." * node.level + (node.module or "")
            names.add(base)
            names.update(f"{base}.{alias.name}" for alias in node.names)
    return names


def _public_functions(path):
    return [node for node in _tree(path).body
            if isinstance(node, ast.FunctionDef) and not node.name.startswith("_")]


def _label(path):
    return str(path.relative_to(PACKAGE))


def test_the_example_subpackage_holds_the_worked_example_modules():
    assert {p.stem for p in EXAMPLE_MODULES} >= {"looping", "incline", "projectile"}
    assert not {p.stem for p in CORE_MODULES} & {p.stem for p in EXAMPLE_MODULES}


@pytest.mark.parametrize("path", CORE_MODULES + [PACKAGE / "__init__.py"], ids=_label)
def test_no_core_module_imports_the_example_subpackage(path):
    imported = _imported_modules(_tree(path))
    offending = sorted(n for n in imported
                       if n.startswith("dynagrade.mechanics.examples") or n.startswith(".examples")
                       or n == "dynagrade.mechanics.examples")
    assert not offending, f"{_label(path)} imports {offending}"


@pytest.mark.parametrize("path", ALL_MODULES, ids=_label)
def test_the_mechanics_package_imports_nothing_else_of_dynagrade(path):
    imported = _imported_modules(_tree(path))
    outside = sorted(n for n in imported
                     if n.startswith("dynagrade") and not n.startswith("dynagrade.mechanics"))
    assert not outside, f"{_label(path)} imports {outside}"


def test_the_import_scan_sees_an_import_of_the_examples():
    """The scan above would catch the import energy.py once had."""
    tree = ast.parse("def f():\n    from dynagrade.mechanics.examples.incline import distance_up_slope\n")
    assert "dynagrade.mechanics.examples.incline" in _imported_modules(tree)
    tree = ast.parse("from dynagrade.mechanics.examples import incline\n")
    assert "dynagrade.mechanics.examples" in _imported_modules(tree)


def test_no_two_public_functions_of_the_mechanics_package_share_a_name():
    homes = {}
    for path in ALL_MODULES:
        for node in _public_functions(path):
            homes.setdefault(node.name, []).append(_label(path))
    shared = {name: where for name, where in homes.items() if len(where) > 1}
    assert not shared, f"public functions defined in several modules: {shared}"
    assert len(homes) > 300          # the scan really read the package
