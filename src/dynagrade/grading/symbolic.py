"""Grading of formulas: equivalence by evaluation at seeded random points.

The reference expression is parsed with the same parser as the answer and evaluated
at points drawn uniformly from the declared domains (seeded from the reference text,
so a verdict never changes between runs), converted to SI. Points where the
reference is undefined are redrawn; an answer undefined where the reference is
defined is wrong. Point i agrees when ``|a_i - e_i| <= rtol * max(|e_i|, 1e-3*M)``
with M the median of |e| over the points (an absolute 1e-12 when the reference is
identically 0). Before that, when every variable has a unit, the answer's dimension
must match the reference's.

A variable may be written under its name or any spelling of its printed symbol and
aliases (``spec.spellings``), resolved by the parser's name lookup.

When the spec says an additive constant does not matter (``up_to_constant``: the
variables the constant does not depend on, e.g. the coordinate of a potential energy
V(θ) whose zero level is a convention), the answer is compared by its differences
``f(x_i) - f(x_i°)`` with the reference's, where ``x_i°`` is sample point i with those
variables set to their values at the first point: point i agrees when
``|Δa_i - Δe_i| <= t_i + t_i°`` (the two points' tolerances). An answer right only up to
such a constant is correct, and its feedback says the constant was ignored.

The module is the kind's grading half (:mod:`.kinds`): besides grading it reads an answer
without the reference (``read_symbolic``) and builds the spec of a ``dynagrade compare`` record
(``build_symbolic``).
"""

from __future__ import annotations

from ..i18n import N_, _
import math
import zlib
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from . import units
from .dims import DimensionIssue, dimension, show
from .errors import AnswerError, SpecError
from .evaluate import evaluate
from .feedback import reading_hints
from .nodes import BinOp, Call, Expr, Neg, Num, names_in, to_text, walk
from .onpaper import notes
from .parser import parse_expression
from .quantity import unit_info
from .spec import SymbolicSpec
from .timing import Deadline
from .tolerance import median, point_tolerance
from .precise import agree_precisely, extended
from .tosympy import exactly_equal
from .verdict import Verdict, unreadable
from . import records
from .readability import Readability
from .records import Common

_MAX_DRAWS = 12


@dataclass(frozen=True)
class _Reference:
    tree: Expr
    names: frozenset
    env: dict
    values: np.ndarray
    tol: np.ndarray
    dims: dict | None
    dim: tuple | None
    swapped: np.ndarray | None
    known: tuple
    domains: dict
    rtol: float
    extended: tuple | None
    based: dict | None = None
    base: np.ndarray | None = None
    base_tol: np.ndarray | None = None


def _parse_reference(text, names, what: str) -> Expr:
    if not isinstance(text, str):
        raise SpecError(f"the {what} of a symbolic part must be an expression string, got {text!r}")
    try:
        return parse_expression(text, names)
    except AnswerError as error:
        raise SpecError(f"cannot read the {what} {text!r}: {error}") from None


@lru_cache(maxsize=256)
def _reference(spec: SymbolicSpec, expected: str) -> _Reference:
    names = frozenset(spec.variables)
    tree = _parse_reference(expected, names, "reference")
    factors: dict[str, float] = {}
    dims: dict[str, tuple] = {}
    for name, var in spec.variables.items():
        factors[name], dim = unit_info(var.unit) if var.unit is not None else (1.0, None)
        if dim is not None:
            dims[name] = dim
    all_dims = dims if len(dims) == len(spec.variables) else None
    env, values = _sample(spec, expected, tree, factors)
    tol = point_tolerance(values, spec.rtol)
    ref_dim = None
    if all_dims is not None:
        try:
            ref_dim = dimension(tree, all_dims)
        except DimensionIssue:
            all_dims = None  # an inhomogeneous reference: skip dimension checks
    swapped = None
    if any(isinstance(n, Call) and n.func in ("sin", "cos") for n in walk(tree)):
        swapped = _values(_swap_sin_cos(tree), env, values.shape)
    based = _based(env, spec.constant_in)
    known = []
    for wrong in spec.misconceptions:
        wrong_tree = _parse_reference(wrong.value, names, f"misconception {wrong.name!r}")
        known.append((wrong, _values(wrong_tree, env, values.shape),
                      None if based is None else _values(wrong_tree, based, values.shape)))
    domains = {n: (v.domain[0] * factors[n], v.domain[1] * factors[n]) for n, v in spec.variables.items()}
    base = None if based is None else _values(tree, based, values.shape)
    return _Reference(tree, names, env, values, tol, all_dims, ref_dim, swapped, tuple(known), domains, spec.rtol,
                      extended(tree, env), based, base,
                      None if base is None else point_tolerance(base, spec.rtol))


def _based(env: dict, constant_in: tuple) -> dict | None:
    """The sample points with the variables ``constant_in`` moved to their first values
    (None when no additive constant is ignored)."""
    if not constant_in:
        return None
    return {n: np.full_like(v, v[0]) if n in constant_in else v for n, v in env.items()}


def _values(tree: Expr, env: dict, shape) -> np.ndarray:
    return np.broadcast_to(np.asarray(evaluate(tree, env), dtype=np.float64), shape)


def _sample(spec: SymbolicSpec, expected: str, tree: Expr, factors: dict):
    seed = zlib.crc32(("|".join(sorted(spec.variables)) + "|" + expected).encode())
    rng = np.random.default_rng(seed)
    want = spec.points
    env_parts: dict[str, list] = {n: [] for n in spec.variables}
    kept: list[np.ndarray] = []
    count = 0
    for _ in range(_MAX_DRAWS):
        batch = {n: _uniform(rng, *v.domain, 2 * want) * factors[n] for n, v in spec.variables.items()}
        vals = _values(tree, batch, (2 * want,))
        ok = np.isfinite(vals)
        for n in batch:
            env_parts[n].append(batch[n][ok])
        kept.append(vals[ok])
        count += int(ok.sum())
        if count >= want:
            break
    if count < 4:
        raise SpecError(f"the reference {expected!r} is undefined on almost all of the declared domain")
    env = {n: np.concatenate(parts)[:want] for n, parts in env_parts.items()}
    values = np.concatenate(kept)[:want]
    return env, values


def _uniform(rng, low: float, high: float, size: int) -> np.ndarray:
    """Points drawn uniformly from [low, high], also when high - low overflows (±1e308)."""
    if math.isfinite(high - low):
        return rng.uniform(low, high, size=size)
    u = rng.uniform(0.0, 1.0, size=size)
    return low * (1.0 - u) + high * u


def _swap_sin_cos(tree: Expr) -> Expr:
    if isinstance(tree, Call):
        func = {"sin": "cos", "cos": "sin"}.get(tree.func, tree.func)
        return Call(func, tuple(_swap_sin_cos(a) for a in tree.args))
    if isinstance(tree, BinOp):
        return BinOp(tree.op, _swap_sin_cos(tree.left), _swap_sin_cos(tree.right))
    if isinstance(tree, Neg):
        return Neg(_swap_sin_cos(tree.operand))
    return tree


def grade_symbolic(spec: SymbolicSpec, expected, answer: str) -> Verdict:
    """The verdict on a formula answer (see :func:`dynagrade.grading.grade`)."""
    ref = _reference(spec, expected)
    deadline = Deadline()  # the reference (and the units it loads) is prepared outside the budget
    try:
        tree = parse_expression(answer, ref.names, spec.spellings)
    except AnswerError as error:
        return unreadable(str(error))
    reveal = " " + _("The expected answer is {answer}.").format(answer=to_text(ref.tree)) \
        if spec.reveal else ""
    hint = "".join(" " + h for h in reading_hints(tree))
    if ref.dims is not None and ref.dim is not None:
        try:
            dim = dimension(tree, ref.dims)
        except DimensionIssue as issue:
            return Verdict(False, 0.0, _("Not correct: {problem}.").format(problem=issue.message)
                           + hint + reveal, misconception="dimensions")
        if not units.same(dim, ref.dim, ignore_angle=True):
            return Verdict(False, 0.0, _("Not correct: your expression has units of {given}, "
                                         "expected {wanted}.").format(given=show(dim),
                                                                      wanted=show(ref.dim))
                           + hint + reveal, misconception="dimensions")
    values = _values(tree, ref.env, ref.values.shape)
    if np.any(np.isinf(values)) and not names_in(tree):
        return Verdict(False, 0.0, _("Not correct: your expression overflows (it is too large to "
                                     "compute).") + reveal)
    if not np.all(np.isfinite(values)):
        return Verdict(False, 0.0, _("Not correct: your expression is undefined for some allowed values of "
                                     "the variables (a division by zero, the root or logarithm of a negative "
                                     "number, or a number too large to compute) where the expected one is "
                                     "defined.") + reveal)
    if _equivalent(tree, ref, values, deadline):
        return _form_verdict(spec, ref, tree, " ".join(notes(tree)))
    base = None if ref.based is None else _values(tree, ref.based, values.shape)
    if base is not None and ref.base is not None and ref.base_tol is not None and \
            _same_differences(values, base, ref.values, ref.base, ref.tol + ref.base_tol):
        return _form_verdict(spec, ref, tree, " ".join([constant_ignored(spec)] + notes(tree)))
    hints = " ".join(reading_hints(tree))
    with np.errstate(all="ignore"):  # ratios of values near the float limit overflow
        found = _misconception(spec, ref, values, base)
    if found is not None:
        name, feedback, score = found
        return Verdict(False, score, " ".join(x for x in (feedback, hints) if x) + reveal, misconception=name)
    read = to_text(tree)
    read = read if len(read) <= 120 else read[:120] + "…"
    text = _("Not correct: your expression (read as {answer}) is not equivalent to the expected "
             "one.").format(answer=read)
    return Verdict(False, 0.0, " ".join(x for x in (text, hints) if x) + reveal)


def _equivalent(tree: Expr, ref: _Reference, values: np.ndarray, deadline: Deadline) -> bool:
    """Float values within the tolerance; else, both being finite, the values in high
    precision decide, and when those cannot, the exact check if the float values are
    within 100 times the tolerance."""
    diff = np.abs(values - ref.values)
    if np.all(diff <= ref.tol):
        return True
    precise = agree_precisely(tree, ref.tree, ref.env, values, ref.values, ref.tol, ref.rtol, deadline,
                              ref.extended)
    if precise is not None:
        return precise
    return bool(np.all(diff <= 100 * ref.tol)) and \
        bool(exactly_equal(tree, ref.tree, ref.domains, min(0.3, deadline.remaining())))


def constant_ignored(spec: SymbolicSpec) -> str:
    """What a formula right up to an additive constant is told."""
    names = [n for n in spec.variables if n in spec.constant_in]
    if len(names) == len(spec.variables):
        return _("Your expression differs from the expected one by an additive constant, which "
                 "this part ignores: only changes of its value matter.")
    return _("Your expression differs from the expected one by an additive constant (one "
             "independent of {names}), which this part ignores: only changes of its value "
             "matter.").format(names=", ".join(names))


def _same_differences(values: np.ndarray, values_base: np.ndarray, expected: np.ndarray,
                      expected_base: np.ndarray, tol: np.ndarray) -> bool:
    """Whether two formulas differ by a constant: their changes from the base points
    (``values - values_base`` and ``expected - expected_base``) agree within ``tol``."""
    with np.errstate(all="ignore"):
        change = (values - values_base) - (expected - expected_base)
    return bool(np.all(np.isfinite(change)) and np.all(np.abs(change) <= tol))


def _form_verdict(spec: SymbolicSpec, ref: _Reference, tree: Expr, note: str = "") -> Verdict:
    problems = []
    if "no_decimals" in spec.form:
        if any(isinstance(n, Num) and n.value != int(n.value) for n in walk(tree)) or \
                any(isinstance(n, Num) and any(c in n.text for c in ".,") for n in walk(tree)):
            problems.append(_("write exact numbers (fractions like 1/2) instead of decimals"))
    if "simplified" in spec.form:
        if sum(1 for _ in walk(tree)) > sum(1 for _ in walk(ref.tree)) + 2:
            problems.append(_("simplify your expression further"))
    if "no_functions" in spec.form:
        if any(isinstance(n, Call) for n in walk(tree)):
            problems.append(_("write it without functions (no sin, sqrt, exp, …)"))
    if problems:
        return Verdict(False, spec.form_credit,
                       _("Your expression is equivalent, but {problems}.").format(
                           problems=_(" and ").join(problems)) +
                       (" " + note if note else ""), misconception="form")
    return Verdict(True, 1.0, _("Correct.") + (" " + note if note else ""))


def _agrees(values: np.ndarray, target: np.ndarray, ref: _Reference) -> bool:
    """Whether ``values`` match ``target`` under the reference's tolerance rule."""
    if not np.all(np.isfinite(target)):
        return False
    return bool(np.all(np.abs(values - target) <= point_tolerance(target, ref.rtol)))


def _misconception(spec: SymbolicSpec, ref: _Reference, values: np.ndarray,
                   base: np.ndarray | None = None):
    """The misconception that explains ``values`` (``base``: the answer at the base points
    of a part that ignores an additive constant), as (name, feedback, score), or None."""
    for wrong, wrong_values, wrong_base in ref.known:
        if _agrees(values, wrong_values, ref) and not _agrees(ref.values, wrong_values, ref):
            return wrong.name, wrong.feedback, wrong.score
        if base is not None and np.all(np.isfinite(wrong_values)) and _same_differences(
                values, base, wrong_values, wrong_base,
                point_tolerance(wrong_values, ref.rtol) + point_tolerance(wrong_base, ref.rtol)):
            return wrong.name, wrong.feedback, wrong.score
    if not spec.generic_misconceptions:
        return None
    e = ref.values
    nonzero = np.abs(e) > 0
    if np.count_nonzero(nonzero) >= 3:
        ratio = values[nonzero] / e[nonzero]
        c = median(ratio)
        if np.all(np.abs(ratio - c) <= 1e-6 * max(abs(c), 1e-300)) and c != 0:
            if abs(c + 1) < 1e-6:
                return (N_("sign"), _("Your expression has the wrong sign: check the direction you "
                                      "took as positive."), 0.0)
            if abs(c - 2) < 1e-6:
                return (N_("factor 2"), _("Your expression is twice the expected one: check for an "
                                          "extra factor of 2."), 0.0)
            if abs(c - 0.5) < 1e-6:
                return (N_("factor 1/2"), _("Your expression is half the expected one: check for a "
                                            "missing factor of 2."), 0.0)
            k = math.log10(abs(c))
            if abs(k - round(k)) < 1e-6 and c > 0 and round(k) != 0:
                return (N_("power of ten"), _("Your expression is off by a factor 10^{exponent}.")
                        .format(exponent=round(k)), 0.0)
    if ref.swapped is not None and _agrees(values, ref.swapped, ref) and not _agrees(e, ref.swapped, ref):
        return (N_("sin/cos"), _("Your expression has sin where cos belongs (or the other way "
                                   "round): check which angle you used."), 0.0)
    if np.all(nonzero):
        with np.errstate(all="ignore"):
            reciprocal = 1.0 / e
        if _agrees(values, reciprocal, ref) and not _agrees(e, reciprocal, ref):
            return (N_("reciprocal"), _("Your expression is the reciprocal of the expected one: is a "
                                          "fraction upside down?"), 0.0)
    if np.count_nonzero(nonzero) >= 3:
        ratio = values[nonzero] / e[nonzero]
        c = median(ratio)
        if c != 0 and np.all(np.abs(ratio - c) <= 1e-6 * abs(c)):
            return (N_("constant factor"), _("Your expression differs from the expected one by a "
                                               "constant factor."), 0.0)
    offset = values - e
    d = median(offset)
    if d != 0 and np.all(np.abs(offset - d) <= ref.tol) and names_in(ref.tree):
        return (N_("constant term"), _("Your expression differs from the expected one by a constant "
                                        "term."), 0.0)
    return None


def read_symbolic(spec: SymbolicSpec, text: str) -> Readability:
    """How ``text`` reads as an answer to ``spec`` (:func:`.readability.readability`)."""
    allowed = tuple(spec.variables)
    tree = parse_expression(text, allowed, spec.spellings)
    unknown = sorted(names_in(tree) - set(allowed))
    if unknown:
        listed = ", ".join(allowed) or _("none")
        return Readability(False, _("'{name}' is not a name of this part (allowed: {names})")
                           .format(name=unknown[0], names=listed))
    return Readability(True, " ".join([_("reads as {answer}").format(answer=to_text(tree))]
                                      + notes(tree)))


def build_symbolic(record: dict, common: Common):
    """A symbolic record's spec and reference (``dynagrade compare``, :mod:`.compare`)."""
    expected = records.string(record, "expected", required=True)
    form = record.get("form") or ()
    if not isinstance(form, (list, tuple)) or not all(isinstance(f, str) for f in form):
        raise records.RecordError("field 'form' must be a list of strings")
    spec = SymbolicSpec(records.variables(record), **common.relative_tolerance(),
                        misconceptions=common.misconceptions, form=tuple(form),
                        reveal=common.reveal, up_to_constant=records.constant_in(record))
    return spec, expected
