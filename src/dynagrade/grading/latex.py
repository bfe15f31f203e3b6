r"""LaTeX answers: the subset students paste from the notes or an editor, read as the
plain syntax.

An answer with a backslash or a dollar sign is translated character by character into
the plain syntax (``\frac{v_0^2}{g}\sin(2\alpha)`` -> ``(v_0^2)/g sin(2 α)``), which
the ordinary tokenizer then reads; every token keeps the position of the LaTeX it came
from, so a caret points into what the student typed. The LaTeX is never evaluated or
handed to TeX or sympy: the translation only writes brackets, operators and names, and
the plain syntax's limits apply to the result.

The subset (docs/grading.md, "LaTeX"):

* ``\frac{a}{b}`` (also ``\dfrac``, ``\tfrac``, and ``\frac12``), ``\sqrt{x}``,
  ``\sqrt[n]{x}`` (``\sqrt[3]`` is ``cbrt``), ``\cdot``, ``\times``, ``\div``;
* braces: ``^{...}`` and ``_{...}`` (``v_0^2``, ``e^{-\zeta\omega_n t}``, ``\omega_{n}``),
  and ``{...}`` elsewhere as round brackets; ``\left( ... \right)`` and ``\left| ...
  \right|`` (the absolute value);
* Greek letters (``\alpha``, ``\varphi`` is φ, ...) read as their Unicode letters, so
  they reach the declared names as typed Greek does; ``\Delta x`` is one name, as the
  notes print it;
* function commands (``\sin``, ``\arccos``, ``\exp``, ``\ln``, ...);
* accents naming time derivatives as :func:`.names.typed_forms` spells them:
  ``\dot{\varphi}`` is ``phidot``, ``\ddot{x}`` is ``xddot``;
* ``\mathrm{...}``, ``\text{...}``, ``\operatorname{...}`` (units, ``\mathrm{e}``);
* the spaces ``\,`` ``\;`` ``\:`` ``\!`` ``\ `` ``\quad`` and math delimiters ``$``,
  ``\(``, ``\)``, ``\[``, ``\]``.

Any other command is refused with a caret at its backslash.
"""

from __future__ import annotations

import re
from typing import NamedTuple

from ..i18n import _
from . import lexer
from .errors import AnswerError
from .lexer import LPAR, NAME, NUM, OP, ROOT, RPAR, Token
from .names import ACCENTS, GREEK, LATEX_VARIANTS, canonical_function, suggest

#: Greek letter commands -> the Unicode letter the tokenizer reads (``\varphi`` -> φ).
GREEK_COMMANDS: dict[str, str] = {
    **{spelled: letter for letter, spelled in reversed(list(GREEK.items()))},
    **{variant: next(k for k, v in GREEK.items() if v == plain)
       for variant, plain in LATEX_VARIANTS.items()},
}
#: Commands that stand for a character of the plain syntax.
_SYMBOLS = {"cdot": "*", "times": "*", "ast": "*", "div": "/", "{": "(", "}": ")",
            "lbrace": "(", "rbrace": ")"}
#: Commands that are spacing, or open and close math mode.
_SPACES = frozenset({",", ";", ":", "!", " ", "quad", "qquad", "(", ")", "[", "]"})
_FRACTIONS = frozenset({"frac", "dfrac", "tfrac"})
#: Commands whose braced argument is plain text (a unit, ``\mathrm{e}``, a function name).
_WRAPPERS = frozenset({"mathrm", "text", "textrm", "mathit", "operatorname", "mathbf",
                       "boldsymbol", "mbox"})
#: Letters that join the name after them, as the notes print them (``\Delta x`` is Δx).
_JOINS_NAME = frozenset({"Delta", "delta"})
_OPENERS = {"(": "(", "[": "(", "\\{": "(", "\\lbrace": "(", "|": "abs(", "\\vert": "abs(",
            "\\lvert": "abs(", ".": ""}
_CLOSERS = {")": ")", "]": ")", "\\}": ")", "\\rbrace": ")", "|": ")", "\\vert": ")",
            "\\rvert": ")", ".": ""}
_STARTS_OPERAND = frozenset({NUM, NAME, LPAR, ROOT})
_COMMAND = re.compile(r"\\(?:[A-Za-z]+|.)", re.DOTALL)
#: A fraction's numerator or denominator that needs no brackets: a number or one letter
#: (``\frac{2}{mg}`` is 2/(m·g), so ``mg`` keeps its brackets).
_ATOM = re.compile(r"[0-9.]+|[A-Za-z]")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_NAME_CHARS = re.compile(r"[A-Za-z0-9_\\]")
#: Every command the translation knows, for "did you mean".
_KNOWN = sorted({*GREEK_COMMANDS, *_SYMBOLS, *_FRACTIONS, *_WRAPPERS, *ACCENTS, "sqrt",
                 "left", "right", "sin", "cos", "tan", "arcsin", "arccos", "arctan", "exp",
                 "ln", "sinh", "cosh", "tanh", "quad"} - {"{", "}"})


def is_latex(text: str, *, quantity: bool = False) -> bool:
    """Whether an answer is read as LaTeX: it has a backslash, a dollar sign, or a
    formula has a brace, which the plain syntax refuses; or braces follow ``_`` or ``^``
    (``F_{max}``, ``m^{2}``), which the LaTeX reads as the plain syntax did where it read
    them at all (``v_{02}`` is ``v_02`` either way, ``m^{2}`` is ``m^(2)``)."""
    return "\\" in text or "$" in text or "_{" in text or "^{" in text or \
        (not quantity and "{" in text)


def tokenize(text: str, *, max_depth: int, **options) -> list[Token]:
    """The tokens of an answer (:func:`.lexer.tokenize` with its ``options``), LaTeX
    read as the plain syntax; positions are the LaTeX's. ``max_depth`` bounds the
    nesting of braces, as the parser bounds that of brackets."""
    quantity = options.get("quantity", False)
    if not isinstance(text, str) or not is_latex(text, quantity=quantity) or \
            len(text) > lexer.MAX_LENGTH:
        return lexer.tokenize(text, **options)
    plain, origin, closers = translate(text, quantity=quantity, max_depth=max_depth)
    try:
        tokens = lexer.tokenize(plain, **options)
    except AnswerError as error:
        where = None if error.position is None else _source(origin, error.position, text)
        raise AnswerError(error.message, where, text) from None
    read: list[Token] = []
    for token in tokens:
        token = token._replace(pos=_source(origin, token.pos, text))
        if not quantity and read and read[-1].kind == RPAR and read[-1].value == ")" and \
                read[-1].pos in closers and token.kind in _STARTS_OPERAND:
            # \frac{a}{b}c is printed as a fraction times c: a product with an operator,
            # so the note on a/2g (a division written without brackets) is not given
            read.append(Token(OP, "*", token.pos))
        read.append(token)
    return read


def plain_text(text: str, *, quantity: bool = False) -> str:
    """How a LaTeX answer reads in the plain syntax, spaces tidied, for a preview (the
    answer itself when it is no LaTeX or cannot be translated)."""
    if not isinstance(text, str) or not is_latex(text, quantity=quantity):
        return text
    try:
        plain = translate(text, quantity=quantity, max_depth=100).plain
    except AnswerError:
        return text
    return " ".join(plain.split())


class Translation(NamedTuple):
    """The plain syntax of a LaTeX answer."""

    plain: str
    #: for each character of ``plain``, the position in the LaTeX it comes from
    origin: list[int]
    #: the LaTeX positions of the closing brackets of printed groups (a fraction, braces,
    #: ``\right)``), after which an operand is a product with an operator
    closers: frozenset[int]


def translate(text: str, *, quantity: bool = False, max_depth: int = 100) -> Translation:
    """The plain-syntax text of a LaTeX answer. Raises :class:`AnswerError` at a command
    outside the subset."""
    translator = _Translator(text, quantity, max_depth)
    translator.run(0, len(text), 0)
    return Translation("".join(translator.out), translator.origin, frozenset(translator.closers))


def _source(origin: list[int], position: int, text: str) -> int:
    return origin[position] if position < len(origin) else len(text)


class _Translator:
    """Writes the plain syntax of ``text`` piece by piece, with each piece's origin."""

    def __init__(self, text: str, quantity: bool, max_depth: int):
        self.text = text
        self.quantity = quantity
        self.max_depth = max_depth
        self.out: list[str] = []
        self.origin: list[int] = []
        self.closers: list[int] = []
        self.join_next = False

    def emit(self, piece: str, position: int) -> None:
        self.out.append(piece)
        self.origin.extend([position] * len(piece))

    def close_group(self, position: int) -> None:
        """A ``)`` that closes a printed group, at the LaTeX's ``position``."""
        self.closers.append(position)
        self.emit(")", position)

    def error(self, message: str, position: int) -> AnswerError:
        return AnswerError(message, position, self.text)

    # -- the scan ---------------------------------------------------------------------------
    def run(self, start: int, end: int, depth: int) -> None:
        """Translate ``text[start:end]``, ``depth`` groups deep."""
        if depth > self.max_depth:
            raise self.error(_("the expression is nested too deeply (more than {levels} "
                               "levels)").format(levels=self.max_depth), start)
        text = self.text
        i = start
        while i < end:
            ch = text[i]
            if ch == "\\":
                i = self.command(i, end, depth)
            elif ch == "{":
                close = self.closing(i, end)
                self.emit("(", i)
                self.run(i + 1, close, depth + 1)
                self.close_group(close)
                i = close + 1
            elif ch == "}":
                raise self.error(_("unexpected '}' (no matching '{')"), i)
            elif ch in "_^":
                i = self.script(i, end, depth)
            elif ch == "$":
                self.emit(" ", i)
                i += 1
            elif ch.isspace() and self.join_next:
                i += 1
            else:
                self.join_next = False
                self.emit(ch, i)
                i += 1

    def closing(self, opening: int, end: int) -> int:
        """The position of the ``}`` that closes the ``{`` at ``opening``."""
        level = 0
        for k in range(opening, end):
            if k > opening and self.text[k - 1] == "\\":
                continue  # \{ and \} are brackets, not groups
            if self.text[k] == "{":
                level += 1
            elif self.text[k] == "}":
                level -= 1
                if level == 0:
                    return k
        raise self.error(_("missing '}' to close the '{' opened here"), opening)

    def argument(self, i: int, end: int, command: int) -> tuple[int, int, int]:
        """A command's argument after ``i``: a braced group, a command or one character
        (TeX's rule: ``\\frac12``). Returns its content's start and end and where the
        text goes on."""
        while i < end and self.text[i].isspace():
            i += 1
        if i >= end or self.text[i] == "}":
            raise self.error(_("'{command}' needs an argument in braces: {command}{{...}}")
                             .format(command=self.word(command)), command)
        if self.text[i] == "{":
            close = self.closing(i, end)
            return i + 1, close, close + 1
        if self.text[i] == "\\":
            word_end = _COMMAND.match(self.text, i, end)
            if word_end is None:
                raise self.error(_("a backslash must start a LaTeX command"), i)
            return i, word_end.end(), word_end.end()
        return i, i + 1, i + 1

    def word(self, command: int) -> str:
        """The command starting at ``command`` as written (``\\frac``)."""
        match = _COMMAND.match(self.text, command)
        return match.group() if match else "\\"

    def script(self, i: int, end: int, depth: int) -> int:
        """``^{...}`` as a bracketed power, ``_{...}`` as a name's subscript; without
        braces the plain syntax reads what follows."""
        ch = self.text[i]
        self.emit(ch, i)
        j = i + 1
        if j < end and self.text[j] == "\\" and ch == "_":
            self.join_next = True
            return j
        if j >= end or self.text[j] != "{":
            return j
        close = self.closing(j, end)
        if ch == "^":
            self.emit("(", j)
            self.run(j + 1, close, depth + 1)
            self.emit(")", close)
            return close + 1
        subscript = self.sub_translation(j + 1, close, depth).strip()
        if not _NAME.fullmatch("x" + subscript.translate(_SPELLED)):
            raise self.error(_("a subscript holds letters and digits only: v_{0}, "
                               "\\omega_{n}"), i)
        self.emit(subscript, j + 1)
        if close + 1 < end and _NAME_CHARS.match(self.text[close + 1]):
            self.emit(" ", close)
        return close + 1

    def sub_translation(self, start: int, end: int, depth: int) -> str:
        """The plain text of ``text[start:end]`` on its own (an accent's letter)."""
        inner = _Translator(self.text, self.quantity, self.max_depth)
        inner.join_next = True
        inner.run(start, end, depth + 1)
        return "".join(inner.out)

    # -- commands ---------------------------------------------------------------------------
    def command(self, i: int, end: int, depth: int) -> int:
        match = _COMMAND.match(self.text, i, end)
        if match is None:
            raise self.error(_("a backslash must start a LaTeX command"), i)
        name, after = match.group()[1:], match.end()
        joined, self.join_next = self.join_next, False
        if name in _SPACES:
            self.emit(" ", i)
            return after
        if name in _SYMBOLS:
            self.emit(_SYMBOLS[name], i)
            return after
        if name in GREEK_COMMANDS:
            self.emit(("" if joined else " ") + GREEK_COMMANDS[name], i)
            self.join_next = name in _JOINS_NAME or (self.quantity and name == "mu")
            return after
        if name in _FRACTIONS:
            return self.fraction(i, after, end, depth)
        if name == "sqrt":
            return self.root(i, after, end, depth)
        if name in ("left", "right"):
            return self.delimiter(i, after, end, name == "left")
        if name in ACCENTS:
            return self.accent(i, name, after, end, depth)
        if name in _WRAPPERS:
            start, stop, goes_on = self.argument(after, end, i)
            self.emit("" if joined else " ", i)
            self.run(start, stop, depth + 1)
            self.emit(" ", stop)
            return goes_on
        if canonical_function(name):
            self.emit(f" {name} ", i)
            return after
        hint = suggest(name, _KNOWN) if len(name) <= 30 else None
        did_you_mean = _(" (did you mean '\\{hint}'?)").format(hint=hint) if hint else ""
        raise self.error(_("'\\{command}' is not LaTeX the grader reads; write this part in "
                           "plain syntax{did_you_mean}").format(command=name[:30],
                                                                did_you_mean=did_you_mean), i)

    def wrapped(self, start: int, end: int, depth: int) -> None:
        """``text[start:end]`` in brackets, unless it is one number or name."""
        if _ATOM.fullmatch(self.text[start:end].strip()):
            self.run(start, end, depth + 1)
            return
        self.emit("(", start)
        self.run(start, end, depth + 1)
        self.emit(")", end - 1 if end > start else start)

    def fraction(self, i: int, after: int, end: int, depth: int) -> int:
        """``\\frac{a}{b}`` -> ``((a)/(b))``, each inner bracket only where needed."""
        top_start, top_end, goes_on = self.argument(after, end, i)
        bottom_start, bottom_end, goes_on = self.argument(goes_on, end, i)
        self.emit(" (", i)
        self.wrapped(top_start, top_end, depth)
        self.emit("/", i)
        self.wrapped(bottom_start, bottom_end, depth)
        self.close_group(goes_on - 1)
        return goes_on

    def root(self, i: int, after: int, end: int, depth: int) -> int:
        """``\\sqrt{x}`` -> ``sqrt(x)``; ``\\sqrt[3]{x}`` -> ``cbrt(x)``; ``\\sqrt[n]{x}``
        -> ``((x)^(1/n))``."""
        index = None
        j = after
        while j < end and self.text[j].isspace():
            j += 1
        if j < end and self.text[j] == "[":
            close = self.text.find("]", j, end)
            if close < 0:
                raise self.error(_("missing ']' to close the root's index"), j)
            index, j = (j + 1, close), close + 1
        start, stop, goes_on = self.argument(j, end, i)
        degree = None if index is None else self.text[index[0]:index[1]].strip()
        if degree in (None, "2", "3"):
            self.emit(" cbrt(" if degree == "3" else " sqrt(", i)
            self.run(start, stop, depth + 1)
            self.emit(")", goes_on - 1)
            return goes_on
        assert index is not None
        self.emit(" ((", i)
        self.run(start, stop, depth + 1)
        self.emit(")^(1/", i)
        self.wrapped(index[0], index[1], depth)
        self.emit("))", goes_on - 1)
        return goes_on

    def delimiter(self, i: int, after: int, end: int, left: bool) -> int:
        r"""``\left(`` -> ``(``, ``\left|`` -> ``abs(``, ``\right)`` -> ``)``."""
        j = after
        while j < end and self.text[j].isspace():
            j += 1
        match = _COMMAND.match(self.text, j, end) if j < end and self.text[j] == "\\" else None
        written = match.group() if match else self.text[j:j + 1]
        table = _OPENERS if left else _CLOSERS
        if written not in table:
            raise self.error(_("'\\left' and '\\right' need a bracket after them: "
                               "\\left( ... \\right)"), i)
        if table[written] == ")":
            self.close_group(i)
        else:
            self.emit(table[written], i)
        return j + len(written)

    def accent(self, i: int, name: str, after: int, end: int, depth: int) -> int:
        r"""``\dot{\varphi}`` -> ``phidot``: the name as :func:`.names.typed_forms` spells it."""
        start, stop, goes_on = self.argument(after, end, i)
        letter = self.sub_translation(start, stop, depth).strip().translate(_SPELLED)
        if not _NAME.fullmatch(letter):
            raise self.error(_("'\\{accent}' takes one name: \\{accent}{{x}}, "
                               "\\{accent}{{\\varphi}}").format(accent=name), i)
        self.emit(" " + letter + name, i)
        return goes_on


#: Unicode Greek letters -> their spelled names, to spell an accented name.
_SPELLED = str.maketrans(GREEK)
