"""Vectors written with basis vectors, as the notes write them: ``3 e1 + 2 e2``.

A vector part reads ``3 e1 + 2 e2``, ``3e_1+2e_2``, ``3*e1 + 2*e2``, ``3i+2j``,
``(3 e1 + 2 e2) m/s`` and, in a part that declares the polar or path basis of the notes
(``VectorSpec(basis=("e_r", "e_phi"))``, the polar basis {e_r, e_ϕ} of section 1.1.3,
eq. (1.27); ``("e_t", "e_n")``, the path basis {e_t, e_n, e_b} of section 1.1.4), ``3 e_r
+ 2 e_φ``. Without a declared basis a part of 2 or 3 components has the Cartesian basis
e1, e2, e3 of the notes, also spelled ``e_1``, ``e₁``, ``e_x`` and ``i``, ``j``, ``k``
(``î``, ``ĵ``, ``k̂``). A declared basis vector is spelled as declared, with its Greek
letter typed or spelled out (``e_φ``, ``e_phi``, ``e_{phi}``).

The answer is parsed by the ordinary quantity parser (a basis vector comes out of it as
a unit's name, ``Unit("e1")``, and is never looked up) and split into components by linearity: every term of the sum holds exactly one basis
vector as a factor (``3 m/s e1``, ``e2*2``, ``-e2``), never in a denominator, a power or
a function; the coefficients of one basis vector add up, and a missing one is 0. So a
basis-vector sum reads as the same components as its bracket form ``(3, 2)``, and
nothing is evaluated here.

``3e1+2e2`` would be the number 30 + 200 for the tokenizer; in a vector part with the
numbered basis, in an answer without separators (no comma or semicolon between
components), a number glued to one of its ``e1``..``e3`` is read as a coefficient and a
basis vector instead, with a note saying so. ``(3e1, 2e2)`` stays (30, 200), and
``1.5e-3``, ``2e10`` stay numbers.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..i18n import _
from . import lexer
from .errors import AnswerError
from .names import GREEK
from .nodes import BinOp, Expr, Neg, Num, Unit, to_text, walk
from .parser import check_limits, parse_quantity

#: The Cartesian basis of the notes, one family of spellings per component.
CARTESIAN: tuple[tuple[str, ...], ...] = (
    ("e1", "e_1", "e_x", "i"), ("e2", "e_2", "e_y", "j"), ("e3", "e_3", "e_z", "k"))
#: Basis vectors of the notes' other bases (polar, cylindrical, spherical, path):
#: named in a refusal when a part does not declare them.
OTHER_BASES = ("e_r", "e_phi", "e_theta", "e_z", "e_t", "e_n", "e_b")

_SUBSCRIPT_DIGIT = {chr(0x2080 + k): str(k) for k in range(10)}
_BRACED = re.compile(r"(?<![A-Za-z_])e_\{([^{}]{1,12})\}")
_E_SUBSCRIPT = re.compile(r"(?<![A-Za-z_])e_?([" + "".join(_SUBSCRIPT_DIGIT) + "])")
_E_GREEK = re.compile(r"(?<![A-Za-z_])e_([" + "".join(GREEK) + "])")
_E_VARIANT = re.compile(r"(?<![A-Za-z_])e_var(phi|theta)\b")
#: what every spelling of a known basis vector starts with (a quick test before tokenizing)
_MAYBE_BASIS = re.compile(r"(?<![A-Za-z_])(?:e[_0-9{\u2080-\u2089]|[ijkîĵ](?![A-Za-z_]))")
_KNOWN = dict.fromkeys([n for family in CARTESIAN for n in family] + list(OTHER_BASES), 0)
#: Greek letters by their spelled-out names (the first letter of a name: φ, not ϕ)
_LETTERS = {spelled: letter for letter, spelled in reversed(list(GREEK.items()))}
_HATS = {"î": "i", "ĵ": "j", "i\u0302": "i", "j\u0302": "j", "k\u0302": "k"}
_GLUED = re.compile(r"(?<![0-9A-Za-z_.,])([0-9]+(?:[.,][0-9]+)?|[.,][0-9]+)(e[1-9])(?![0-9A-Za-z_])")
_E_VECTOR = re.compile(r"(?<![0-9A-Za-z_])(e_?[1-3]|e_[xyz]|e_(?:r|phi|theta|t|n|b))(?![0-9A-Za-z_])")
_IJK = re.compile(r"(?:[0-9)]\s*\*?\s*|^\s*[-+]?\s*)([ijk])(?![0-9A-Za-z_])")


@dataclass(frozen=True)
class BasisReading:
    """A vector answer read from basis vectors: one tree per component (None where the
    answer leaves the basis vector out: 0) and a note when the reading needs one."""

    components: list[Expr | None]
    note: str = ""


def basis_index(size: int, basis: tuple[str, ...] = ()) -> dict[str, int]:
    """Each basis vector's spelling (after :func:`normalise`) -> its component, for a
    part of ``size`` components with the declared ``basis`` (the Cartesian basis of
    the notes when none is declared and there are 2 or 3 components)."""
    index: dict[str, int] = {}
    if not basis:
        if size in (2, 3):
            for k, family in enumerate(CARTESIAN[:size]):
                index.update({name: k for name in family})
        return index
    for k, name in enumerate(basis):
        family = next((f for f in CARTESIAN if name in f), (name,))
        index.update({spelling: k for spelling in family})
    return index


def normalise(text: str) -> str:
    """Basis vectors in one spelling: ``e₁`` -> ``e_1``, ``e_φ`` -> ``e_phi``,
    ``e_{r}`` -> ``e_r``, ``e_varphi`` -> ``e_phi``, ``î`` -> ``i``."""
    for hat, letter in _HATS.items():
        if hat in text:
            text = text.replace(hat, letter)
    if "e" not in text:
        return text
    text = _BRACED.sub(r"e_\1", text)
    text = _E_SUBSCRIPT.sub(lambda m: "e_" + _SUBSCRIPT_DIGIT[m.group(1)], text)
    text = _E_GREEK.sub(lambda m: "e_" + GREEK[m.group(1)], text)
    return _E_VARIANT.sub(r"e_\1", text)


def read_basis(size: int, basis: tuple[str, ...], text: str) -> BasisReading | None:
    """The components of ``text`` written with basis vectors, or None when ``text`` uses
    none (then it is read in brackets). :class:`AnswerError` when it uses them wrongly."""
    index = basis_index(size, basis)
    if not index or (not basis and not _MAYBE_BASIS.search(text)):
        return None
    text = normalise(text)
    tokens = _tokens(text)
    if tokens is None:
        return None
    note = ""
    if not any(t.kind in (lexer.COMMA, lexer.SEMI) for t in tokens):
        unglued = _GLUED.sub(lambda m: f"{m.group(1)} {m.group(2)}"
                             if m.group(2) in index else m.group(), text)
        if unglued != text:
            note = _("Read {typed} as basis vectors ({read}), not as powers of ten.").format(
                typed=text.strip(), read=unglued.strip())
            text, tokens = unglued, _tokens(unglued)
    names = _basis_names(tokens or [], {**_KNOWN, **index})
    foreign = [name for name in names if name not in index]
    if foreign:
        raise AnswerError(_("'{name}' is not a basis vector of this part; write the vector "
                            "as {example} or in brackets as {bracket}").format(
            name=foreign[0], **examples(size, basis)))
    if tokens is None or not names:
        return None
    if any(t.kind in (lexer.COMMA, lexer.SEMI) for t in tokens):
        raise AnswerError(_("write the vector either with basis vectors ({example}) or in "
                            "brackets ({bracket}), not both").format(**examples(size, basis)))
    tree = parse_quantity(text, decimal_comma=True)
    check_limits(tree)
    found = _coefficients(tree, index, size, basis)
    return BasisReading([found.get(k) for k in range(size)], note)


def examples(size: int, basis: tuple[str, ...] = ()) -> dict[str, str]:
    """How to write a vector of the part, for refusals: ``{"example": "1 e1 + 2 e2",
    "bracket": "(1, 2)"}``."""
    names = basis or (tuple(f[0] for f in CARTESIAN[:size]) if size in (2, 3) else ())
    if not names:
        numbers = ", ".join(str(k + 1) for k in range(min(size, 3))) + (", …" if size > 3 else "")
        return {"example": f"({numbers})", "bracket": f"({numbers})"}
    return {"example": " + ".join(f"{k + 1} {_printed(n)}" for k, n in enumerate(names)),
            "bracket": "(" + ", ".join(str(k + 1) for k in range(len(names))) + ")"}


def vector_given(text: str) -> str | None:
    """The basis vector an answer to a scalar part is written with (``e1``, ``e_r``, or
    ``i`` when two of ``i``, ``j``, ``k`` follow numbers), or None."""
    text = normalise(text)
    m = _E_VECTOR.search(text)
    if m:
        return m.group(1)
    letters = {m.group(1) for m in _IJK.finditer(text)}
    return sorted(letters)[0] if len(letters) >= 2 else None


def _printed(name: str) -> str:
    """A basis vector as the notes print it: ``e_phi`` -> ``e_φ``."""
    head, _sep, tail = name.partition("_")
    return f"{head}_{_LETTERS.get(tail, tail)}" if tail else name


def _tokens(text: str) -> list[lexer.Token] | None:
    try:
        return lexer.tokenize(text, quantity=True, decimal_comma=True)
    except AnswerError:
        return None


def _basis_names(tokens: list[lexer.Token], index: dict) -> list[str]:
    return [t.value for t in tokens if t.kind == lexer.NAME and t.value in index]


def _coefficients(tree: Expr, index: dict[str, int], size: int,
                  basis: tuple[str, ...]) -> dict[int, Expr]:
    """Each component's coefficient in a sum of terms, each a product holding one
    basis vector (or a bracketed sum of such terms) as a factor."""
    found: dict[int, Expr] = {}
    for subtracted, term in _signed(tree, "+-")[0]:
        factors, negated = _signed(term, "*/")
        carriers = [k for k, (_down, f) in enumerate(factors) if _holds_basis(f, index)]
        if not carriers:
            raise AnswerError(_("'{term}' has no basis vector: give every term its basis "
                                "vector ({example}), or write the vector in brackets "
                                "({bracket})").format(term=to_text(term), **examples(size, basis)))
        if len(carriers) > 1:
            raise AnswerError(_("'{term}' multiplies basis vectors; write the vector as "
                                "{example}").format(term=to_text(term), **examples(size, basis)))
        down, carrier = factors[carriers[0]]
        if down:
            raise AnswerError(_("'{term}' divides by a basis vector; write the vector as "
                                "{example}").format(term=to_text(term), **examples(size, basis)))
        if isinstance(carrier, Unit) and carrier.id in index:
            inner: dict[int, Expr] = {index[carrier.id]: Num(1.0, "1")}
        elif isinstance(carrier, BinOp) and carrier.op in "+-":
            inner = _coefficients(carrier, index, size, basis)
        else:
            raise AnswerError(_("'{term}' puts a basis vector inside a function or a power; "
                                "write the vector as {example}").format(
                term=to_text(term), **examples(size, basis)))
        rest = [f for k, f in enumerate(factors) if k != carriers[0]]
        for k, coefficient in inner.items():
            for f_down, factor in rest:
                coefficient = BinOp("/" if f_down else "*", coefficient, factor)
            if subtracted != negated:
                coefficient = Neg(coefficient)
            found[k] = BinOp("+", found[k], coefficient) if k in found else coefficient
    return found


def _signed(tree: Expr, ops: str) -> tuple[list[tuple[bool, Expr]], bool]:
    """The operands of a chain of ``ops`` (``"+-"``: a sum's terms, each with whether it
    is subtracted; ``"*/"``: a product's factors, each with whether it divides), in
    order, and whether a sign inside a product (``3*-e1``) negates it. A sign in front
    of a term flips that term. Iterative, so a long chain is safe."""
    out: list[tuple[bool, Expr]] = []
    stack: list[tuple[bool, Expr]] = [(False, tree)]
    negated = False
    while stack:
        flag, node = stack.pop()
        if isinstance(node, BinOp) and node.op in ops:
            stack.append((flag != (node.op in "-/"), node.right))
            stack.append((flag, node.left))
        elif isinstance(node, Neg) and ops == "+-":
            stack.append((not flag, node.operand))
        elif isinstance(node, Neg):
            negated = not negated
            stack.append((flag, node.operand))
        else:
            out.append((flag, node))
    return out, negated


def _holds_basis(node: Expr, index: dict[str, int]) -> bool:
    return any(isinstance(n, Unit) and n.id in index for n in walk(node))
