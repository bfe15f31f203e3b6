"""Tokenizer: answer text -> tokens, with Unicode and number-format normalisation.

Reads ``^``/``**``, ``×``/``·`` for products, every minus sign of
:data:`names.MINUS_SIGNS` (also in a number's exponent: ``1.2e−3``), superscript
exponents (``m/s²``, ``10⁻³``), ``√``, ``π`` and Greek letters (as their ASCII
names), and numbers ``1.2``, ``.5``, ``1.2e3``, ``1.2E+03`` (and ``12,5`` where a
decimal comma is allowed). A number token's value is its literal with ASCII signs.
A number glued to a lone ``e``/``E`` (``2e``, ``1.2e−``) is refused unless that letter
is a declared name: it is an unfinished exponent, never a product with Euler's number.

A name is a letter (ASCII or Greek) followed by letters, digits, ``_`` and subscript
digits: ``ω_n`` is ``omega_n``, ``θ_0`` is ``theta_0``, ``x₁`` is ``x_1``. A formula's
variables may also be written as their printed symbols (``v_{02}``, ``v_2(0)``): such a
spelling, given in ``spellings``, is read whole as the variable's name. In number-with-unit answers, where names are
units, a Greek letter stands alone (``2πrad`` is 2·pi·rad, ``µm`` a micrometre).
Everything else is refused with a positioned message.
"""

from __future__ import annotations

from ..i18n import N_, _
import re
from typing import NamedTuple

from .errors import AnswerError
from .names import GREEK, MINUS_SIGNS, OPERATOR_CHARS, PLUS_SIGNS, SUBSCRIPTS, SUPERSCRIPTS

#: Longest answer accepted, in characters.
MAX_LENGTH = 2000
#: Most tokens accepted in one answer.
MAX_TOKENS = 1000

_SIGN = "[" + re.escape(MINUS_SIGNS + PLUS_SIGNS) + "]"
_EXPONENT = f"(?:[eE]{_SIGN}?[0-9]+)?"
_NUMBER = re.compile(r"(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)" + _EXPONENT)
_NUMBER_COMMA = re.compile(r"(?:[0-9]+(?:[.,][0-9]+|\.)?|\.[0-9]+)" + _EXPONENT)
_ASCII_SIGNS = str.maketrans({**{c: "-" for c in MINUS_SIGNS}, **{c: "+" for c in PLUS_SIGNS}})
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_DIGITS = frozenset("0123456789")
_LETTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ")
_NAME_CHARS = _LETTERS | _DIGITS | {"_"}
_NAME_TAIL = re.compile(r"[0-9_]*")
_FORMULA_NAME = re.compile("[A-Za-z0-9_" + re.escape("".join(GREEK) + "".join(SUBSCRIPTS)) + "]+")
_SUBSCRIPT_DIGITS = re.compile("_?([" + "".join(SUBSCRIPTS) + "]+)")
_SPELLED_OUT = str.maketrans(GREEK)
_SUPERSCRIPT_VALUE = re.compile(r"[+-]?[0-9]+")

NUM, NAME, OP, LPAR, RPAR, COMMA, SEMI, SUP, ROOT, EQUALS, END = (
    "number", "name", "operator", "(", ")", ",", ";", "superscript", "root", "=", "end")

_BRACKETS = {"(": LPAR, "[": LPAR, "{": LPAR, ")": RPAR, "]": RPAR, "}": RPAR}
_REFUSED_CHARS = {
    "'": N_("quotes are not allowed in an answer"),
    '"': N_("quotes are not allowed in an answer"),
    "!": N_("factorials are not supported"),
    "∞": N_("infinity is not a valid answer"),
    "=": "",
    "%": N_("percent signs are not supported; give a plain number"),
    "\\": N_("backslashes are not allowed (no LaTeX commands)"),
    "$": N_("dollar signs are not allowed (no LaTeX)"),
    ":": N_("':' is not allowed in an answer"),
    "@": N_("'@' is not allowed in an answer"),
    "#": N_("'#' is not allowed in an answer"),
    "&": N_("'&' is not allowed in an answer"),
    "|": N_("use abs(...) instead of |...|"),
    "<": N_("comparisons are not allowed in an answer"),
    ">": N_("comparisons are not allowed in an answer"),
}


class Token(NamedTuple):
    """One token: its kind, its text (numbers with ASCII signs) and where it starts."""

    kind: str
    value: str
    pos: int


def tokenize(text: str, *, quantity: bool = False, decimal_comma: bool = False,
             names: frozenset = frozenset(), spellings: tuple = ()) -> list[Token]:
    """Split ``text`` into tokens.

    ``quantity`` selects number-with-unit answers (``°`` is the unit ``deg``, ``µm``
    is a micrometre); ``decimal_comma`` reads ``12,5`` as 12.5; ``names`` are the
    declared names (a declared ``e`` may follow a number: ``2e``); ``spellings`` are
    (spelling, name) pairs of printed symbols that are no plain name (``v_2(0)``), each
    read whole, longest first, as one name token.
    """
    if not isinstance(text, str):
        raise AnswerError(_("the answer must be text"))
    if len(text) > MAX_LENGTH:
        raise AnswerError(_("the answer is too long ({length} characters; at most {limit})").format(
            length=len(text), limit=MAX_LENGTH))
    number_re = _NUMBER_COMMA if decimal_comma else _NUMBER
    tokens: list[Token] = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch.isspace():
            i += 1
            continue
        if len(tokens) >= MAX_TOKENS:
            raise AnswerError(_("the answer is too long (more than {limit} symbols)").format(
                limit=MAX_TOKENS), i, text)
        if ch in _DIGITS or (ch == "." and i + 1 < n and text[i + 1] in _DIGITS):
            token, i = _number(text, i, number_re, decimal_comma, names)
            tokens.append(token)
            continue
        whole = _spelled_symbol(text, i, spellings) if spellings else None
        if whole is not None:
            tokens.append(Token(NAME, whole[0], i))
            i = whole[1]
            continue
        if ch in _LETTERS or ch == "_" or (ch in GREEK and not quantity):
            word, end = _unit_name(text, i) if quantity else _name(text, i)
            if end < n and text[end] == "." and end + 1 < n and (text[end + 1] in _LETTERS or text[end + 1] == "_"):
                raise AnswerError(_("attribute access like a.b is not allowed"), end, text)
            tokens.append(Token(NAME, word, i))
            i = end
            continue
        if ch in ("µ", "μ") and quantity and i + 1 < n and text[i + 1] in _LETTERS:
            m = _match_at(_NAME, text, i + 1)
            tokens.append(Token(NAME, "u" + m.group(), i))
            i = m.end()
            continue
        if ch in GREEK:
            m = _match_at(_NAME_TAIL, text, i + 1)
            tokens.append(Token(NAME, GREEK[ch] + m.group(), i))
            i = m.end()
            continue
        if ch in SUPERSCRIPTS:
            j = i
            while j < n and text[j] in SUPERSCRIPTS:
                j += 1
            exponent = "".join(SUPERSCRIPTS[c] for c in text[i:j])
            if not _SUPERSCRIPT_VALUE.fullmatch(exponent):
                raise AnswerError(_("this superscript is not a whole-number exponent"), i, text)
            tokens.append(Token(SUP, exponent, i))
            i = j
            continue
        if ch == "°":
            if not quantity:
                raise AnswerError(_("the degree sign is only allowed after a number; "
                                    "formulas use radians"), i, text)
            tokens.append(Token(NAME, "deg", i))
            i += 1
            continue
        if ch in ("√", "∛"):
            tokens.append(Token(ROOT, "sqrt" if ch == "√" else "cbrt", i))
            i += 1
            continue
        op = OPERATOR_CHARS.get(ch, ch)
        if op == "*" and i + 1 < n and OPERATOR_CHARS.get(text[i + 1], text[i + 1]) == "*":
            tokens.append(Token(OP, "^", i))
            i += 2
            continue
        if op in "+-*/^" and len(op) == 1:
            tokens.append(Token(OP, op, i))
            i += 1
            continue
        if op in _BRACKETS:
            tokens.append(Token(_BRACKETS[op], op, i))
            i += 1
            continue
        if op == ",":
            tokens.append(Token(COMMA, ",", i))
            i += 1
            continue
        if op == ";":
            tokens.append(Token(SEMI, ";", i))
            i += 1
            continue
        if op == "=":
            tokens.append(Token(EQUALS, "=", i))
            i += 1
            continue
        if ch in _REFUSED_CHARS:
            raise AnswerError(_(_REFUSED_CHARS[ch]), i, text)
        shown = ch if ch.isprintable() else f"U+{ord(ch):04X}"
        raise AnswerError(_("unexpected character '{character}'").format(character=shown), i, text)
    tokens.append(Token(END, "", n))
    return tokens


def _number(text: str, i: int, number_re, decimal_comma: bool, names: frozenset) -> tuple[Token, int]:
    """The number starting at ``i`` (its literal with ASCII signs) and where it ends."""
    n = len(text)
    end = number_re.match(text, i).end()
    if end < n and text[end] == "." and end + 1 < n and text[end + 1] in _DIGITS:
        raise AnswerError(_("a number cannot have two decimal points"), end, text)
    if end < n and text[end] == "," and decimal_comma and end + 1 < n and text[end + 1] in _DIGITS:
        raise AnswerError(_("a number cannot have two decimal commas"), end, text)
    if end < n and text[end] in "eE" and text[end] not in names:
        after = text[end + 1] if end + 1 < n else ""
        if after in MINUS_SIGNS or after in PLUS_SIGNS or not (after in _NAME_CHARS or after in GREEK):
            mantissa = text[i:end]
            raise AnswerError(_("'{number}' is an unfinished number: write the exponent's digits "
                                "({number}3, {number}-3), or '{mantissa}*e' for a product with "
                                "Euler's number").format(number=mantissa + text[end],
                                                         mantissa=mantissa), end, text)
    literal = text[i:end].translate(_ASCII_SIGNS)
    value = float(literal.replace(",", "."))
    if value == float("inf"):
        raise AnswerError(_("this number is too large"), i, text)
    return Token(NUM, literal, i), end


def _name(text: str, i: int) -> tuple[str, int]:
    """A formula's name at ``i``: a letter, then letters, digits, ``_`` and subscript
    digits; Greek letters are spelled out (``ω_n`` -> ``omega_n``) and subscript digits
    follow an ``_`` (``x₁`` -> ``x_1``)."""
    m = _match_at(_FORMULA_NAME, text, i)
    word = _SUBSCRIPT_DIGITS.sub(lambda s: "_" + "".join(SUBSCRIPTS[c] for c in s.group(1)),
                                 m.group())
    return word.translate(_SPELLED_OUT), m.end()


def _spelled_symbol(text: str, i: int, spellings: tuple) -> tuple[str, int] | None:
    """The variable whose printed spelling starts at ``i`` (and where it ends), or None.

    A spelling that ends in a letter or digit must not run on into a longer name."""
    if i > 0 and (text[i - 1] in _NAME_CHARS or text[i - 1] in GREEK):
        return None
    for spelling, name in spellings:
        if text.startswith(spelling, i):
            end = i + len(spelling)
            if spelling[-1] in _NAME_CHARS and end < len(text) and (
                    text[end] in _NAME_CHARS or text[end] in GREEK or text[end] in SUBSCRIPTS):
                continue
            return name, end
    return None


def _unit_name(text: str, i: int) -> tuple[str, int]:
    """A unit's name at ``i``: ASCII letters, digits and ``_``."""
    m = _match_at(_NAME, text, i)
    return m.group(), m.end()


def _match_at(pattern: re.Pattern[str], text: str, i: int) -> re.Match[str]:
    """The match of ``pattern`` at ``i``, where the caller has seen a character that
    starts one (a letter before a name) or the pattern also matches nothing."""
    m = pattern.match(text, i)
    assert m is not None, (pattern.pattern, text, i)
    return m
