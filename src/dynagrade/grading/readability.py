"""Can this answer be graded? The check an exam may show before its key is released.

``readability(spec, text)`` reads an answer the way grading would — a number with a unit
of the right dimension, a vector with the right number of components, a formula in the
declared names only, one of the options — and says how it was read ("reads as 45 km/h =
12.5 m/s"). It never sees the reference answer, so it cannot reveal whether the answer
is right: exam mode shows this message, homework shows the verdict too.

Never raises because of ``text``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable

from .errors import AnswerError
from .feedback import show_value
from .spec import ChoiceSpec, NumericSpec, SymbolicSpec, VectorSpec


@dataclass(frozen=True)
class Readability:
    """Whether an answer can be graded, and how it was read (or why not)."""

    readable: bool
    message: str


def readability(spec, text: str) -> Readability:
    """How ``text`` reads as an answer to a part with ``spec`` (a grading spec)."""
    if not isinstance(text, str) or not text.strip():
        return Readability(False, "no answer yet")
    reader = next((READERS[c] for c in type(spec).__mro__ if c in READERS), None)
    if reader is None:
        return Readability(False, "this kind of answer cannot be checked here")
    try:
        return reader(spec, text)
    except AnswerError as error:
        return Readability(False, str(error))
    except (RecursionError, MemoryError):
        return Readability(False, "the answer cannot be read (too large or too deeply nested)")
    except Exception:  # a reader's own failure on odd input: still an answer, not a crash
        return Readability(False, "the answer cannot be read; write a number, a unit and "
                                  "operators only")


def _numeric(spec: NumericSpec, text: str) -> Readability:
    from .numeric import _read_in_part_unit
    from .quantity import read_quantity, unit_info

    quantity = read_quantity(text)
    if not math.isfinite(quantity.value):
        return Readability(False, "the answer is not a finite number")
    factor, dim = unit_info(spec.unit)
    reading = _read_in_part_unit(spec, quantity, factor, dim)
    if not reading.unit_ok:
        return Readability(False, f"unit problem: {reading.unit_problem}")
    shown = show_value(reading.value, spec.unit)
    if quantity.dim is None:
        where = f" (a bare number is read in {spec.unit})" if spec.unit else ""
        return Readability(True, f"reads as {shown}{where}")
    if not reading.converted:
        return Readability(True, f"reads as {shown}")
    return Readability(True, f"reads as {text.strip()} = {shown}")


def _vector(spec: VectorSpec, text: str) -> Readability:
    from .parser import parse_vector
    from .quantity import unit_info
    from .vector import _read

    components, unit_tree = parse_vector(text)
    factor, dim = unit_info(spec.unit)
    values, problem = _read(spec, components, unit_tree, text, factor, dim)
    if problem:
        return Readability(False, f"unit problem: {problem}")
    if len(values) != spec.size:
        return Readability(False, f"the answer needs {spec.size} components, it has "
                                  f"{len(values)}")
    if not all(math.isfinite(v) for v in values):
        return Readability(False, "a component is not a finite number")
    shown = ", ".join(show_value(float(v), None) for v in values)
    unit = f" {spec.unit}" if spec.unit else ""
    return Readability(True, f"reads as ({shown}){unit}")


def _symbolic(spec: SymbolicSpec, text: str) -> Readability:
    from .nodes import names_in, to_text
    from .parser import parse_expression

    allowed = tuple(spec.variables)
    tree = parse_expression(text, allowed, spec.spellings)
    unknown = sorted(names_in(tree) - set(allowed))
    if unknown:
        listed = ", ".join(allowed) or "none"
        return Readability(False, f"'{unknown[0]}' is not a name of this part (allowed: "
                                  f"{listed})")
    return Readability(True, f"reads as {to_text(tree)}")


def _choice(spec: ChoiceSpec, text: str) -> Readability:
    from .choice import _split

    picks = _split(spec, text)
    if isinstance(picks, str):
        return Readability(False, picks)
    if not spec.multiple and len(set(picks)) > 1:
        return Readability(False, "choose only one option")
    chosen = [o for o in spec.options if any(o.replace(" ", "").casefold() == p for p in picks)]
    return Readability(True, "reads as " + ", ".join(chosen))


#: how each kind of spec is read (the kinds of :data:`dynagrade.grading.dispatch.GRADERS`)
READERS: dict[type, Callable[[Any, str], Readability]] = {NumericSpec: _numeric, VectorSpec: _vector, SymbolicSpec: _symbolic,
           ChoiceSpec: _choice}
