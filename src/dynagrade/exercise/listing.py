"""What ``dynagrade list`` shows of an exercise, read from its file without running it.

An exercise file is the author's code: importing it runs its imports and whatever it
computes at module level. Listing the bank needs only the identity and the names, units
and points of parameters and parts, which an exercise file states as literals in its
``EXERCISE = Exercise(...)`` call. They are read here with :mod:`ast`, as students'
sheets are; a file that states one of them otherwise (a computed value) is loaded
instead, so the listing is always right and only its speed depends on the file.

Usage::

    listing = read_listing(path)     # an ExerciseListing, or None: load the file
    listing.summary()                # as Exercise.summary()
"""

from __future__ import annotations

import ast
import inspect
import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from ..errors import DynagradeError
from . import parts as _parts
from .params import Parameter
from .parts import Part

#: The calls that declare parameters; only name, unit and symbol are listed.
_PARAMETER_CALLS = ("Uniform", "Choice", "Constant")


@dataclass(frozen=True)
class ExerciseListing:
    """An exercise's identity, parameters and parts: what a listing needs, no solver."""

    id: str
    title: str
    source: str
    chapter: int
    topics: tuple[str, ...]
    params: tuple[Parameter, ...]
    parts: tuple[Part, ...]
    figured: bool
    path: str | None = None
    #: the Symbolic parts' formulas as the file writes them, for the loader's check
    #: (:mod:`.formula_check`: part name, what, text, variable names)
    formulas: tuple[tuple[str, str, str, tuple[str, ...]], ...] = ()

    @classmethod
    def of(cls, exercise) -> "ExerciseListing":
        """The listing of a loaded :class:`~dynagrade.exercise.model.Exercise`."""
        return cls(exercise.id, exercise.title, exercise.source, exercise.chapter,
                   tuple(exercise.topics), exercise.params, exercise.parts,
                   exercise.figure is not None, exercise.path)

    def summary(self) -> dict:
        """The exercise's identity and parts, as ``dynagrade list --json`` prints them."""
        return summary(self)


def summary(exercise) -> dict:
    """The summary of an exercise or a listing (anything with their attributes)."""
    return {
        "id": exercise.id, "title": exercise.title, "source": exercise.source,
        "chapter": exercise.chapter, "topics": list(exercise.topics),
        "parts": [{"name": p.name, "kind": p.kind, "unit": p.unit, "points": p.points,
                   "label": p.label} for p in exercise.parts],
        "params": [{"name": p.name, "unit": p.unit, "symbol": p.symbol or p.name}
                   for p in exercise.params],
    }


#: the first number of a source ("Example 4.3"): its chapter
_SOURCE_CHAPTER = re.compile(r"(\d+)(?:\.\d+)*")


def chapter_of(source: str) -> int:
    """The chapter of the notes a source names ("Example 4.3" -> 4), 0 when none."""
    match = _SOURCE_CHAPTER.search(source)
    return int(match.group(1)) if match else 0


class _NotLiteral(DynagradeError):
    """A value the file computes: the listing cannot be read without running the file."""


def read_listing(path: str | Path) -> ExerciseListing | None:
    """The listing of the exercise file at ``path``, or ``None`` when the file does not
    state everything a listing needs as literals (then load the file)."""
    path = Path(path)
    try:
        tree = ast.parse(path.read_bytes(), filename=str(path))
    except (SyntaxError, ValueError):
        return None
    names = _module_constants(tree)
    call = names.get("EXERCISE")
    if not (isinstance(call, ast.Call) and _callee(call) == "Exercise"):
        return None
    fields = {k.arg: k.value for k in call.keywords if k.arg}
    try:
        source = _literal(fields["source"], names)
        chapter = (_literal(fields["chapter"], names) if "chapter" in fields
                   else chapter_of(source))
        part_calls = _calls(fields["parts"], names)
        return ExerciseListing(
            id=_literal(fields["id"], names), title=_literal(fields["title"], names),
            source=source, chapter=chapter,
            topics=tuple(_literal(fields["topics"], names)) if "topics" in fields else (),
            params=tuple(_parameter(c, names) for c in _calls(fields["params"], names)),
            parts=tuple(_part(c, names) for c in part_calls),
            figured=_states_figure(fields.get("figure")),
            path=str(path.resolve()),
            formulas=tuple(f for c in part_calls for f in _written_formula(c, names)))
    except (KeyError, TypeError, ValueError, _NotLiteral):
        return None


def _module_constants(tree: ast.Module) -> dict[str, ast.expr]:
    """The expressions assigned to plain names at module level (the last one wins)."""
    names = {}
    for node in tree.body:
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    names[target.id] = node.value
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) \
                and node.value is not None:
            names[node.target.id] = node.value
    return names


def _callee(call: ast.Call) -> str | None:
    func = call.func
    return func.id if isinstance(func, ast.Name) else \
        func.attr if isinstance(func, ast.Attribute) else None


def _resolved(node: ast.expr, names: dict[str, ast.expr]) -> ast.expr:
    seen = set()
    while isinstance(node, ast.Name) and node.id in names and node.id not in seen:
        seen.add(node.id)
        node = names[node.id]
    return node


def _literal(node: ast.expr, names: dict[str, ast.expr]):
    """The value of a literal, following module-level names; else :class:`_NotLiteral`."""
    node = _resolved(node, names)
    if isinstance(node, ast.Tuple):
        return tuple(_literal(e, names) for e in node.elts)
    if isinstance(node, ast.List):
        return [_literal(e, names) for e in node.elts]
    try:
        return ast.literal_eval(node)
    except ValueError:
        raise _NotLiteral(ast.dump(node)) from None


def _calls(node: ast.expr, names: dict[str, ast.expr]) -> list[ast.Call]:
    node = _resolved(node, names)
    if not isinstance(node, (ast.Tuple, ast.List)):
        raise _NotLiteral("not a literal sequence")
    calls = []
    for element in node.elts:
        call = _resolved(element, names)
        if not isinstance(call, ast.Call):
            raise _NotLiteral("not a call")
        calls.append(call)
    return calls


def _arguments(call: ast.Call, cls: type, wanted: tuple[str, ...]) -> dict:
    """The ``wanted`` arguments of ``cls(...)`` as written in ``call``, bound to ``cls``'s
    parameters by position and keyword (a call Python would refuse, or one that unpacks
    ``*args`` or ``**kwargs``, is :class:`_NotLiteral`: the file is loaded instead)."""
    names = _parameter_names(cls)
    if len(call.args) > len(names) or any(isinstance(a, ast.Starred) for a in call.args):
        raise _NotLiteral("positional arguments")
    bound = dict(zip(names, call.args))
    for keyword in call.keywords:
        if keyword.arg is None or keyword.arg not in names or keyword.arg in bound:
            raise _NotLiteral(f"keyword {keyword.arg}")
        bound[keyword.arg] = keyword.value
    return {name: bound[name] for name in wanted if name in bound}


@cache
def _parameter_names(cls: type) -> tuple[str, ...]:
    """The names of ``cls(...)``'s parameters, in order (a class of the exercise model
    takes neither ``*args`` nor ``**kwargs``)."""
    return tuple(inspect.signature(cls).parameters)


def _parameter(call: ast.Call, names) -> Parameter:
    callee = _callee(call)
    if callee is None or callee not in _PARAMETER_CALLS:
        raise _NotLiteral("not a parameter")
    from . import params

    written = _arguments(call, getattr(params, callee), ("name", "unit", "symbol"))
    return Parameter(**{k: _literal(v, names) for k, v in written.items()})


def _part(call: ast.Call, names) -> Part:
    cls = _parts.part_class(_callee(call) or "")
    if cls is None:
        raise _NotLiteral("not a part kind")
    written = _arguments(call, cls, ("name", "label", "points", "unit"))
    return cls(**{k: _literal(v, names) for k, v in written.items()})


def _variable_key(key: ast.expr | None, names: dict[str, ast.expr]):
    """A key of a Symbolic part's ``variables`` as written (None: ``**other``, whose names
    are not written out)."""
    if key is None:
        raise _NotLiteral("unpacked variables")
    return _literal(key, names)


def _written_formula(call: ast.Call, names) -> list[tuple[str, str, str, tuple[str, ...]]]:
    """The formulas of a Symbolic part's call (:mod:`.formula_check`): its expected
    formula and its misconceptions, with its variables' names; empty for another kind.
    A Symbolic part that writes any of them otherwise is :class:`_NotLiteral` (the file
    is loaded, and the loaded exercise checked)."""
    cls = getattr(_parts, _callee(call) or "")
    if "expected" not in _parameter_names(cls):
        return []
    written = _arguments(call, cls, ("name", "expected", "variables", "misconceptions"))
    name = _literal(written["name"], names)
    variables = _resolved(written.get("variables", ast.Tuple(elts=[])), names)
    keys = variables.keys if isinstance(variables, ast.Dict) else [variables]
    variable_names = tuple(n for key in keys for n in _flat(_variable_key(key, names)))
    formulas = [(name, "expected formula", _literal(written["expected"], names),
                 variable_names)]
    for wrong in _calls(written.get("misconceptions", ast.Tuple(elts=[])), names):
        label, value = (_arguments(wrong, _parts.Misconception, ("name", "value"))[k]
                        for k in ("name", "value"))
        formulas.append((name, f"misconception {_literal(label, names)!r}",
                         _literal(value, names), variable_names))
    return formulas


def _flat(value) -> tuple:
    """A name, or the names of a tuple or list, as a tuple."""
    return tuple(value) if isinstance(value, (tuple, list)) else (value,)


def _states_figure(node: ast.expr | None) -> bool:
    return node is not None and not (isinstance(node, ast.Constant) and node.value is None)
