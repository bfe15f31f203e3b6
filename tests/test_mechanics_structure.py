"""The shape of the mechanics package, checked by reading its source (ast), never by trust:
one taxonomy (the core never imports the worked-example subpackage), unique public names,
one argument convention, type hints, and no scipy at import.
"""
import ast
import importlib
import inspect
import json
import subprocess
import sys
import typing
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
            prefix = "." * node.level
            base = prefix + (node.module or "")
            names.add(base)
            names.update(f"{base}.{alias.name}" if node.module else prefix + alias.name
                         for alias in node.names)
    return names


def _names_the_examples(module):
    """Whether an imported module name (absolute or relative) is the example subpackage or in it."""
    return "examples" in module.lstrip(".").split(".")


def _public_functions(path):
    return [node for node in _tree(path).body
            if isinstance(node, ast.FunctionDef) and not node.name.startswith("_")]


def _label(path):
    return str(path.relative_to(PACKAGE))


def test_the_example_subpackage_holds_the_worked_example_modules():
    assert {p.stem for p in EXAMPLE_MODULES} >= {"looping", "incline", "projectile", "hoop"}
    assert not {p.stem for p in CORE_MODULES} & {p.stem for p in EXAMPLE_MODULES}


@pytest.mark.parametrize("path", CORE_MODULES + [PACKAGE / "__init__.py"], ids=_label)
def test_no_core_module_imports_the_example_subpackage(path):
    imported = _imported_modules(_tree(path))
    offending = sorted(n for n in imported if _names_the_examples(n))
    assert not offending, f"{_label(path)} imports {offending}"


@pytest.mark.parametrize("path", ALL_MODULES, ids=_label)
def test_the_mechanics_package_imports_nothing_else_of_dynagrade(path):
    imported = _imported_modules(_tree(path))
    outside = sorted(n for n in imported
                     if n.startswith("dynagrade") and not n.startswith("dynagrade.mechanics"))
    assert not outside, f"{_label(path)} imports {outside}"


def test_the_import_scan_sees_an_import_of_the_examples():
    """The scan above would catch the import energy.py once had, in any spelling."""
    for source in ("from dynagrade.mechanics.examples.incline import distance_up_slope\n",
                   "def f():\n    from dynagrade.mechanics.examples import incline\n",
                   "import dynagrade.mechanics.examples.incline\n",
                   "from . import examples\n",
                   "from .examples.incline import time_up_slope\n"):
        assert any(_names_the_examples(n) for n in _imported_modules(ast.parse(source))), source
    assert not any(_names_the_examples(n) for n in _imported_modules(
        ast.parse("from dynagrade.mechanics import energy, particle\n")))


def test_no_two_public_functions_of_the_mechanics_package_share_a_name():
    homes = {}
    for path in ALL_MODULES:
        for node in _public_functions(path):
            homes.setdefault(node.name, []).append(_label(path))
    shared = {name: where for name, where in homes.items() if len(where) > 1}
    assert not shared, f"public functions defined in several modules: {shared}"
    assert len(homes) > 300          # the scan really read the package


# Names a public signature must not use, with the name to use instead (the argument
# convention of dynagrade/mechanics/__init__.py): mostly spelled-out names of quantities the
# notes write with a symbol, and the second name a quantity once had.
USE_INSTEAD = {
    "mass": "m (M for a system's total mass)",
    "radius": "R",
    "height": "h",
    "length": "L or l",
    "angle": "phi, theta or alpha",
    "angle_from": "phi1",
    "angle_to": "phi2",
    "initial_speed": "v0",
    "initial_velocity": "v0",
    "initial_position": "x0 or r0",
    "initial_rate": "phidot1 or omega0",
    "time": "t",
    "gravity": "g",
    "stiffness": "k",
    "damping": "c",
    "line_density": "rhoA",
    "mass_per_length": "rhoA",
    "pivot_distance": "pivot_to_centre (as in rigid_impact)",
}


def _parameters(node):
    args = node.args
    return [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs]


@pytest.mark.parametrize("path", ALL_MODULES, ids=_label)
def test_public_signatures_name_quantities_by_their_symbol(path):
    offending = [f"{node.name}({name}): use {USE_INSTEAD[name]}"
                 for node in _public_functions(path) for name in _parameters(node)
                 if name in USE_INSTEAD]
    assert not offending, offending


def test_mass_is_m_throughout_the_mechanics_package():
    """The split that motivated the convention: m in 43 signatures, mass in 31."""
    names = [name for path in ALL_MODULES for node in _public_functions(path)
             for name in _parameters(node)]
    assert names.count("m") > 60
    assert "mass" not in names


def test_h_means_a_height_not_a_finite_difference_step():
    from dynagrade.mechanics import energy
    assert "h" not in inspect.signature(energy.curl).parameters
    assert "h" not in inspect.signature(energy.is_conservative).parameters


@pytest.mark.parametrize("path", ALL_MODULES, ids=_label)
def test_modules_share_helpers_only_through_the_common_module(path):
    """A private name imported from a sibling module is a helper in the wrong home."""
    borrowed = [f"{node.module}.{alias.name}" for node in ast.walk(_tree(path))
                if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("dynagrade.mechanics")
                and node.module != "dynagrade.mechanics._common"
                for alias in node.names if alias.name.startswith("_")]
    assert not borrowed, f"{_label(path)} imports private helpers {borrowed}"


def test_no_private_helper_is_defined_in_two_modules():
    homes = {}
    for path in ALL_MODULES:
        for node in _tree(path).body:
            if isinstance(node, ast.FunctionDef) and node.name.startswith("_"):
                homes.setdefault(node.name, []).append(_label(path))
    assert not {name: where for name, where in homes.items() if len(where) > 1}


def test_the_common_module_imports_no_other_mechanics_module():
    imported = _imported_modules(_tree(PACKAGE / "_common.py"))
    assert not [n for n in imported if n.startswith("dynagrade")]


def _module_names():
    names = []
    for path in [PACKAGE / "__init__.py", EXAMPLES / "__init__.py"] + ALL_MODULES:
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        names.append(".".join(("dynagrade",) + (parts[:-1] if parts[-1] == "__init__" else parts)))
    return names


# Modules allowed to import scipy at import time, with the reason.  None today: every
# integration, root search and eigen-solve imports scipy inside the function doing it.
SCIPY_AT_IMPORT = {}


def test_importing_any_mechanics_module_leaves_scipy_unimported():
    """Imports every module of the package one after the other in a fresh interpreter and
    notes which import first brought scipy in; then calls one integrating function to show
    the check sees scipy when it is loaded."""
    program = (
        "import importlib, json, sys\n"
        "culprits = []\n"
        f"for name in {_module_names()!r}:\n"
        "    had = 'scipy' in sys.modules\n"
        "    importlib.import_module(name)\n"
        "    if not had and 'scipy' in sys.modules:\n"
        "        culprits.append(name)\n"
        "from dynagrade.mechanics import kinematics\n"
        "kinematics.velocity_from_acceleration(lambda t: 1.0, 2.0, 0.0)\n"
        "print(json.dumps([culprits, 'scipy' in sys.modules]))\n")
    out = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    culprits, loaded_on_use = json.loads(out.stdout)
    assert [c for c in culprits if c.rpartition(".")[2] not in SCIPY_AT_IMPORT] == []
    assert loaded_on_use


def _unannotated(node):
    args = node.args
    every = args.posonlyargs + args.args + args.kwonlyargs + [a for a in (args.vararg, args.kwarg) if a]
    missing = [a.arg for a in every if a.annotation is None]
    if node.returns is None:
        missing.append("return")
    return missing


@pytest.mark.parametrize("path", ALL_MODULES, ids=_label)
def test_every_public_function_has_type_hints(path):
    missing = {node.name: _unannotated(node) for node in _public_functions(path) if _unannotated(node)}
    assert not missing, f"{_label(path)}: no hint for {missing}"


@pytest.mark.parametrize("name", [n for n in _module_names() if not n.endswith(".examples")
                                  and n != "dynagrade.mechanics"])
def test_the_type_hints_name_real_types(name):
    """Every hint resolves in its module (a misspelt or unimported alias would not)."""
    module = importlib.import_module(name)
    functions = [f for n, f in inspect.getmembers(module, inspect.isfunction)
                 if not n.startswith("_") and f.__module__ == name]
    for function in functions:
        hints = typing.get_type_hints(function)
        assert "return" in hints, function.__name__


def test_the_hint_check_sees_a_missing_hint():
    node = ast.parse("def f(m: float, v) -> float:\n    return m * v\n").body[0]
    assert _unannotated(node) == ["v"]
