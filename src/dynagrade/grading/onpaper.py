"""Functions as written on paper: ``sin^2(x)``, ``sin²x``, ``cos^-1(x)``, ``sin 2α``.

The parser hands a function name over to :func:`application` when no bracket follows the
name directly. The rules, in the order they are tried (docs/grading.md, "Functions as
written on paper"):

* **A power right after the name** is a whole number, written ``^2``, ``^(2)``, ``^{2}``,
  ``**2`` or ``²``: ``sin^2(x)`` and ``sin²x`` are sin(x)², as on paper.
* **The power −1** (``cos^-1(x)``, ``cos⁻¹ x``) of ``sin``, ``cos`` and ``tan`` is the
  inverse function, as on a calculator: arccos, with a note (:func:`notes`). Other
  negative powers, and −1 of another function, are refused with the two readings to
  choose from.
* **Without a bracket** (formulas only; in a number with a unit a name after a number
  is a unit, ``2 sec``) the argument is the run of factors written without an operator
  right after the name, each with its own power: ``sin x``, ``sin 2α``, ``sin ω t`` is
  sin(ωt), ``sin x^2`` is sin(x²). The run ends at ``+``, ``-``, a closing bracket, a
  comma, the end, or another function (``sin α cos β`` is sin(α)·cos(β), ``m g sin α``
  is m·g·sin(α)). Where paper is ambiguous — ``*``, ``/``, an opening bracket or ``√``
  right after the run (``sin x/2``) — the answer is refused with both readings.

Nothing is evaluated: this builds the parser's own nodes.
"""

from __future__ import annotations

from typing import Protocol

from ..i18n import _
from .errors import AnswerError
from .lexer import COMMA, END, EQUALS, LPAR, NAME, NUM, OP, RPAR, SEMI, SUP, Token
from .names import canonical_function
from .nodes import BinOp, Call, Expr, Num, walk

#: Functions whose power −1 is read as their inverse, as calculators print them.
INVERSES: dict[str, str] = {"sin": "asin", "cos": "acos", "tan": "atan"}
#: The printed name of each inverse, for the note.
_ARC = {"asin": "arcsin", "acos": "arccos", "atan": "arctan"}
#: Tokens after which the argument of a function written without brackets ends.
_ENDS_RUN = {END, RPAR, COMMA, SEMI, EQUALS}


class Reader(Protocol):
    """The parts of the parser that reading a function on paper uses."""

    text: str

    def peek(self, offset: int = 0) -> Token: ...
    def advance(self) -> Token: ...
    def expression(self, rbp: int) -> Expr: ...
    def call(self, token: Token, function: str) -> Expr: ...
    def is_function(self, token: Token) -> bool: ...


def application(reader: Reader, token: Token, function: str, *, quantity: bool,
                product_power: int) -> Expr | None:
    """The function ``function`` (named by ``token``) applied as written on paper, or
    None when nothing after the name makes it so (the parser then says what to write).

    ``product_power`` is the parser's binding power of a product: each factor of an
    argument written without brackets is read with it, so it keeps its own power."""
    power, length = _power(reader, token, quantity)
    opens = _opens(reader.peek(length))
    if power is None and not opens and (quantity or not _starts_factor(reader)):
        return None
    if quantity and not opens:
        return None  # a unit with a power: m/sec^2
    for _token in range(length):
        reader.advance()
    if power is not None and power < 0 and power != -1:
        raise _refusal(reader, token, _(
            "write 1/{function}(x)^{power} for a negative power of {function}").format(
            function=token.value, power=-power))
    if power == -1 and function not in INVERSES:
        raise _refusal(reader, token, _(
            "'{function}^-1' could be the reciprocal or the inverse function: write "
            "1/{function}(x) for the reciprocal, or the inverse function by its name").format(
            function=token.value))
    if opens:
        called = reader.call(token, function)
    elif quantity or not _starts_factor(reader):
        raise AnswerError(_("write {function}(...) with brackets around its argument").format(
            function=token.value), reader.peek().pos, reader.text)
    else:
        called = Call(function, (_argument_run(reader, token, product_power),))
    if power == -1:
        assert isinstance(called, Call)
        return Call(INVERSES[function], called.args, written=f"{token.value}^-1")
    if power is None:
        return called
    return BinOp("^", called, Num(float(power), str(power)))


def notes(tree: Expr) -> list[str]:
    """What a reader should know about functions written on paper in ``tree``: a power
    −1 read as the inverse function."""
    for node in walk(tree):
        if isinstance(node, Call) and node.written:
            function = node.written.split("^")[0]
            return [_("Note: {written} is read as {inverse}, the inverse function (as on a "
                      "calculator); for the reciprocal write 1/{function}(...).").format(
                written=node.written, inverse=_ARC[node.func], function=function)]
    return []


def _opens(token: Token) -> bool:
    return token.kind == LPAR and token.value == "("


def _power(reader: Reader, token: Token, quantity: bool) -> tuple[int | None, int]:
    """The whole-number power written right after a function's name and how many tokens
    it takes, or (None, 0) when there is none. Raises when a power is written there but
    is no whole number (in a formula; in a number with a unit the name may be a unit)."""
    first = reader.peek()
    if first.kind == SUP:
        return int(first.value), 1
    if first.kind != OP or first.value != "^":
        return None, 0
    # ^2, ^-1, ^(2), ^{-1}: count the tokens of each shape before consuming any
    shapes = ([NUM], [OP, NUM], [LPAR, NUM, RPAR], [LPAR, OP, NUM, RPAR])
    for shape in shapes:
        tokens = [reader.peek(1 + k) for k in range(len(shape))]
        if [t.kind for t in tokens] != shape:
            continue
        signs = [t.value for t in tokens if t.kind == OP]
        number = next(t for t in tokens if t.kind == NUM)
        if signs not in ([], ["-"]) or not number.value.isdigit():
            break
        return (-int(number.value) if signs else int(number.value)), 1 + len(shape)
    if quantity:
        return None, 0
    raise _refusal(reader, token, _(
        "a power written right after {function} must be a whole number ({function}^2(x) is "
        "{function}(x)^2); otherwise write the power after the argument: "
        "{function}(x)^...").format(function=token.value))


def _starts_factor(reader: Reader) -> bool:
    """Whether a factor of an argument written without brackets starts here."""
    token = reader.peek()
    return token.kind == NUM or (token.kind == NAME and not reader.is_function(token))


def _argument_run(reader: Reader, token: Token, product_power: int) -> Expr:
    """The factors written without an operator after a function's name, as one product."""
    start = reader.peek().pos
    argument = reader.expression(product_power)
    while reader.peek().kind == NAME and not reader.is_function(reader.peek()):
        argument = BinOp("*", argument, reader.expression(product_power), implicit=True)
    after = reader.peek()
    if after.kind in _ENDS_RUN or after.kind in (NAME, NUM) or \
            (after.kind == OP and after.value in "+-"):
        return argument
    written = reader.text[start:after.pos].strip()
    operator = after.value if after.kind == OP else "·"
    raise AnswerError(_(
        "'{function} {argument}' without brackets is ambiguous before '{token}': write "
        "{inside} or {outside}").format(
        function=token.value, argument=written, token=reader.text[after.pos:after.pos + 1],
        inside=f"{token.value}({written} {operator} …)",
        outside=f"{token.value}({written}) {operator} …"), after.pos, reader.text)


def _refusal(reader: Reader, token: Token, message: str) -> AnswerError:
    return AnswerError(message, token.pos, reader.text)

