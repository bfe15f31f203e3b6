"""The bounded space of mistakes that misconception discovery (:mod:`.discover`) tries
on one part: perturbations of the reference, each evaluated at a student's own
parameters.

Two routes, neither of which ever reads a student's text:

- **through the exercise's own solver**, re-run with perturbed parameters (SI):
  every parameter times 2, times ½ and with its sign flipped; an angle (``deg`` or
  ``rad``) whose number in degrees is taken as radians (a calculator in radian mode)
  and the reverse, and its complement ``π/2 − α`` (sin and cos of it swapped, tan and
  cot); ``g`` (named ``g``, or a constant of about 9.81 m/s²) as 10 and as 9.8; every
  two parameters of one unit swapped (``m1`` and ``m2``); and, on the result itself, a
  missing square (the result squared) and a missing root (its square root);
- **through the reference formula**, where a formula part of the exercise ``equals``
  this part (``Symbolic(..., equals="x_max")``): in the exercise's own formula tree
  (parsed by the grader's parser), each term of a sum dropped, doubled or its sign
  flipped, each square and square root removed, each ``sin`` and ``cos`` swapped.

The grader already tries a sign, a factor 2 or ½, a power of ten and the reciprocal on
the whole result (:mod:`dynagrade.grading.misconceptions`), so those never reach
discovery and are not repeated here. A perturbation that fails at some parameters
(a square root of a negative number, a solver that raises) gives no value there.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace
from itertools import combinations
from typing import Any, Callable, Iterator, Mapping, Sequence

from ..exercise.kinds import MoodleForm
from ..exercise.model import Exercise
from ..exercise.params import Constant, ParamValues
from ..exercise.parts import Part
from ..grading.nodes import BinOp, Call, Expr, Neg, Num, to_text

#: angle units: a parameter in one of these is an angle
ANGLE_UNITS = ("deg", "rad")
#: the values of g a student may use instead of the exercise's
G_VALUES = (10.0, 9.8)


@dataclass(frozen=True)
class Perturbation:
    """One mistake: its name (the report's and the proposed ``Misconception``'s), the
    family it belongs to, the Python expression in ``p`` that computes its wrong answer
    in SI (for the exercise file), and the function that does."""

    name: str
    family: str
    code: str
    #: the wrong answer (SI) at the parameters ``p`` (SI), or None where it fails
    compute: Callable[[ParamValues], Any]
    #: the imports ``code`` needs in an exercise file
    imports: tuple[str, ...] = ()

    def value(self, params: ParamValues) -> Any:
        """The wrong answer at ``params`` (SI), None where the perturbation fails (its
        numpy warnings silenced: failing is expected of many)."""
        import numpy as np

        try:
            with warnings.catch_warnings(), np.errstate(all="ignore"):
                warnings.simplefilter("ignore")
                return self.compute(params)
        except Exception:  # noqa: BLE001 - a perturbation outside its domain has no value
            return None


def space(exercise: Exercise, part: Part,
          reruns: Sequence[Rerun] | None = None) -> list[Perturbation]:
    """Every perturbation tried on ``part`` of ``exercise``, simplest first; ``reruns``
    are the exercise's :func:`solver_reruns` (made once for all its parts, so that each
    perturbed solve runs once per draw, whichever part asks)."""
    found = list(_through_solver(exercise, part,
                                 solver_reruns(exercise) if reruns is None else reruns))
    formula = _formula_of(exercise, part)
    if formula is not None:
        found += _through_formula(formula, part.name)
    seen: set[str] = set()
    unique = []
    for perturbation in found:
        if perturbation.name not in seen:
            seen.add(perturbation.name)
            unique.append(perturbation)
    return unique


# -- through the solver --------------------------------------------------------------------

_PARAMS = "from dynagrade.exercise import ParamValues"


@dataclass(frozen=True)
class Rerun:
    """A change of the parameters, and the exercise's solver re-run with it (every
    part's answer); ``shown`` is the change as the entries of a dict in ``p``."""

    name: str
    family: str
    shown: str
    imports: tuple[str, ...]
    run: Callable[[ParamValues], Mapping[str, Any]]


def solver_reruns(exercise: Exercise) -> list[Rerun]:
    """Every change of the exercise's parameters the space tries (module docstring)."""
    def rerun(name: str, family: str, changes: Callable[[dict], dict], shown: str,
              imports: tuple[str, ...] = ()) -> Rerun:
        def run(p: ParamValues) -> Mapping[str, Any]:
            return exercise.solve(ParamValues(changes(dict(p))))
        return Rerun(name, family, shown, imports, run)

    found = []
    for param in exercise.params:
        x = param.name
        found += [rerun(f"{x} doubled", "factor 2 or ½ on a parameter",
                        _mapped(x, _times(2.0)), f'"{x}": 2 * p.{x}'),
                  rerun(f"{x} halved", "factor 2 or ½ on a parameter",
                        _mapped(x, _times(0.5)), f'"{x}": p.{x} / 2'),
                  rerun(f"sign of {x} flipped", "sign flip", _mapped(x, _times(-1.0)),
                        f'"{x}": -p.{x}')]
        if param.unit in ANGLE_UNITS:
            found += [rerun(f"{x} in degrees taken as radians", "degrees and radians",
                            _mapped(x, math.degrees), f'"{x}": math.degrees(p.{x})',
                            ("import math",)),
                      rerun(f"{x} in radians taken as degrees", "degrees and radians",
                            _mapped(x, math.radians), f'"{x}": math.radians(p.{x})',
                            ("import math",)),
                      rerun(f"sin and cos of {x} swapped", "trigonometric function swapped",
                            _mapped(x, _complement), f'"{x}": math.pi / 2 - p.{x}',
                            ("import math",))]
        if _is_g(param):
            found += [rerun(f"{x} = {g:g}", "g = 10 or 9.8", _mapped(x, _constant(g)),
                            f'"{x}": {g!r}') for g in G_VALUES]
    for a, b in combinations(exercise.params, 2):
        if a.unit is not None and a.unit == b.unit:
            found.append(rerun(f"{a.name} and {b.name} swapped",
                               "parameters of one kind swapped", _swapped(a.name, b.name),
                               f'"{a.name}": p.{b.name}, "{b.name}": p.{a.name}'))
    return found


def _through_solver(exercise: Exercise, part: Part, reruns: Sequence[Rerun]
                    ) -> Iterator[Perturbation]:
    solver = getattr(exercise.solve, "__name__", "")
    solver = solver if solver.isidentifier() else "EXERCISE.solve"
    name = part.name
    for rerun in reruns:
        yield Perturbation(rerun.name, rerun.family,
                           f'{solver}(ParamValues({{**p, {rerun.shown}}}))["{name}"]',
                           _answer_of(rerun.run, name), (_PARAMS, *rerun.imports))
    if part.moodle is MoodleForm.NUMBER:  # the answer is one number (exercise.kinds)
        result = f'{solver}(p)["{name}"]'
        reference = _answer_of(exercise.solve, name)
        yield Perturbation("result squared (a missing root)", "a missing square or root",
                           f"{result} ** 2", lambda p: float(reference(p)) ** 2)
        yield Perturbation("square root of the result (a missing square)",
                           "a missing square or root", f"math.sqrt({result})",
                           lambda p: math.sqrt(float(reference(p))), ("import math",))


def _answer_of(run: Callable[[ParamValues], Mapping[str, Any]], name: str
               ) -> Callable[[ParamValues], Any]:
    """Part ``name``'s answer (SI) of ``run``, which runs once per draw: every part and
    perturbation asking for it at the same parameters shares one solve."""
    def answer(p: ParamValues) -> Any:
        solved = p.once(run) if isinstance(p, ParamValues) else run(p)
        return solved[name]
    return answer


def _mapped(name: str, change: Callable[[float], float]) -> Callable[[dict], dict]:
    """The parameters with ``name``'s value changed by ``change``."""
    def changes(values: dict) -> dict:
        return {**values, name: change(values[name])}
    return changes


def _swapped(a: str, b: str) -> Callable[[dict], dict]:
    """The parameters with the values of ``a`` and ``b`` swapped."""
    def changes(values: dict) -> dict:
        return {**values, a: values[b], b: values[a]}
    return changes


def _times(factor: float) -> Callable[[float], float]:
    def change(value: float) -> float:
        return factor * value
    return change


def _constant(new: float) -> Callable[[float], float]:
    def change(value: float) -> float:
        return new
    return change


def _complement(angle: float) -> float:
    """``π/2 − angle``: its sine is the angle's cosine."""
    return math.pi / 2 - angle


def _is_g(param) -> bool:
    """Whether the parameter is the gravitational acceleration."""
    if param.unit != "m/s^2":
        return False
    return param.name == "g" or (isinstance(param, Constant) and 9.7 <= param.value <= 9.9)


# -- through the formula -------------------------------------------------------------------

def _formula_of(exercise: Exercise, part: Part) -> tuple[Expr, tuple[str, ...]] | None:
    """The parsed reference formula of the formula part that ``equals`` ``part``, with
    its variables (None when the exercise has none)."""
    from ..grading.parser import parse_expression

    for other in exercise.parts:
        if getattr(other, "equals", None) == part.name:
            names = other.variable_names()
            try:
                return parse_expression(str(getattr(other, "expected")), names), names
            except Exception:  # noqa: BLE001 - an unparsable formula gives no perturbations
                return None
    return None


def _through_formula(formula: tuple[Expr, tuple[str, ...]], name: str
                     ) -> Iterator[Perturbation]:
    tree, names = formula
    for label, family, mutated in _mutations(tree):
        text = to_text(mutated)
        yield Perturbation(label, family, f'evaluate_expression("{text}", p)',
                           _evaluator(mutated, names),
                           ("from dynagrade.grading import evaluate_expression",))


def _evaluator(tree: Expr, names: Sequence[str]) -> Callable[[ParamValues], float]:
    def compute(p: Mapping[str, float]) -> float:
        import numpy as np

        from ..grading.evaluate import evaluate

        value = float(np.asarray(evaluate(tree, {n: np.float64(p[n]) for n in names})))
        if not math.isfinite(value):
            raise ValueError("not finite")
        return value
    return compute


def _mutations(tree: Expr) -> Iterator[tuple[str, str, Expr]]:
    """Each single change of the formula tree, with its name and family."""
    for node, rebuild in _subtrees(tree):
        if isinstance(node, BinOp) and node.op in "+-":
            right = Neg(node.right) if node.op == "-" else node.right
            shown = to_text(node)
            for term, kept in ((node.left, right), (right, node.left)):
                yield (f"term {to_text(term)} of {shown} dropped", "a term of a sum dropped "
                       "or doubled", rebuild(kept))
            yield (f"term {to_text(node.left)} of {shown} doubled", "a term of a sum dropped "
                   "or doubled", rebuild(replace(node, left=BinOp("*", Num(2.0), node.left))))
            yield (f"term {to_text(right)} of {shown} doubled", "a term of a sum dropped or "
                   "doubled", rebuild(replace(node, right=BinOp("*", Num(2.0), node.right))))
            flipped = "-" if node.op == "+" else "+"
            yield (f"sign of {to_text(right)} in {shown} flipped", "sign flip",
                   rebuild(replace(node, op=flipped)))
        elif isinstance(node, BinOp) and node.op == "^" and isinstance(node.right, Num) \
                and node.right.value in (2.0, 0.5):
            what = "square" if node.right.value == 2.0 else "root"
            yield (f"{what} of {to_text(node.left)} missing", "a missing square or root",
                   rebuild(node.left))
        elif isinstance(node, Call) and node.func == "sqrt" and len(node.args) == 1:
            yield (f"root of {to_text(node.args[0])} missing", "a missing square or root",
                   rebuild(node.args[0]))
        elif isinstance(node, Call) and node.func in ("sin", "cos"):
            other = "cos" if node.func == "sin" else "sin"
            yield (f"{node.func} for {other} in {to_text(node)}",
                   "trigonometric function swapped", rebuild(replace(node, func=other)))


def _subtrees(tree: Expr, rebuild: Callable[[Expr], Expr] = lambda t: t
              ) -> Iterator[tuple[Expr, Callable[[Expr], Expr]]]:
    """Every subtree of ``tree`` with the function that puts a replacement for it back
    into the whole tree."""
    yield tree, rebuild
    if isinstance(tree, Neg):
        yield from _subtrees(tree.operand, lambda t: rebuild(Neg(t)))
    elif isinstance(tree, BinOp):
        yield from _subtrees(tree.left, lambda t: rebuild(replace(tree, left=t)))
        yield from _subtrees(tree.right, lambda t: rebuild(replace(tree, right=t)))
    elif isinstance(tree, Call):
        for index in range(len(tree.args)):
            yield from _subtrees(tree.args[index], _argument_put_back(tree, index, rebuild))


def _argument_put_back(call: Call, index: int, rebuild: Callable[[Expr], Expr]
                       ) -> Callable[[Expr], Expr]:
    """The function that puts a replacement for ``call``'s argument ``index`` back."""
    def put_back(tree: Expr) -> Expr:
        return rebuild(replace(call, args=call.args[:index] + (tree,) + call.args[index + 1:]))
    return put_back
