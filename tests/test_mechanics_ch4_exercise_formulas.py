"""The equations of motion that chapter-4 exercises expect as formulas are the ones the
core derives with the Lagrange equations (the exercises' `verify` cross-check covers the
formulas tied to a numeric part; these have state variables and are checked here)."""
import importlib.util
from pathlib import Path

import numpy as np
import pytest

from dynagrade.grading import evaluate_expression
from deferred import deferred

sp = deferred("sympy")

BANK = Path(__file__).resolve().parents[1] / "exercises" / "ch4_vibrations"


def load(name):
    spec = importlib.util.spec_from_file_location(f"_bank_{name}", BANK / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def sample_points(variables, n, rng):
    return [{k: rng.uniform(v.min, v.max) for k, v in variables.items()} for _ in range(n)]


def part(exercise, name):
    return next(p for p in exercise.parts if p.name == name)


@pytest.mark.parametrize("module, part_name, index, rename", [
    ("pendulum_torsion_spring", "theta_ddot", None, {}),
    ("elastic_pendulum", "r_ddot", 0, {"r_dot": "rdot", "phi_dot": "phidot"}),
])
def test_expected_equation_of_motion_is_the_lagrange_derivation(module, part_name, index, rename):
    mod = load(module)
    derived = mod.acceleration() if index is None else mod.accelerations()[index]
    symbols = sorted(derived.free_symbols, key=str)
    names = [rename.get(str(s), str(s)) for s in symbols]
    f = sp.lambdify(symbols, derived)
    p = part(mod.EXERCISE, part_name)
    rng = np.random.default_rng(4)
    for point in sample_points(p.variables, 25, rng):
        expected = evaluate_expression(p.expected, point)
        assert expected == pytest.approx(f(*[point[n] for n in names]), rel=1e-9, abs=1e-9)
