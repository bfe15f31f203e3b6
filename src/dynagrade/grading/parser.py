"""Recursive-descent (Pratt) parser: tokens -> immutable expression tree.

Two modes share one grammar:

* expression mode (symbolic answers): names are the declared variables, the
  constants ``pi`` and ``e`` (a declared variable of the same name wins) and
  function calls; a name made of declared names written together (``mg``) is read
  as their product, the longest declared name winning (``v0`` stays one name);
* quantity mode (numbers with units): names are units, constants or functions.

Grammar, loosest first: sums ``+ -``; products ``* /`` and products written
without an operator (``2g``, ``m g``, ``2(a+b)``, ``(a)(b)``), all left-associative
at the same level (so ``1/2g`` is ``(1/2)·g``); unary ``- +``; powers ``^``/``**``
(right-associative, ``-x^2`` is ``-(x^2)``) and superscripts. A function is called with
brackets, or as written on paper (``sin^2 x``, ``m g sin α``: :mod:`.onpaper`); an answer in
LaTeX is read through :mod:`.latex`, which hands the tokens of its plain reading over
with the LaTeX's positions. The parser never
evaluates anything and stops with a positioned :class:`AnswerError` on the first
problem. Limits: :data:`lexer.MAX_LENGTH` characters, :data:`lexer.MAX_TOKENS`
tokens, :data:`MAX_DEPTH` levels of nesting, :data:`MAX_TERMS` terms in a flat sum or
product.
"""

from __future__ import annotations

from ..i18n import _, ngettext
from dataclasses import dataclass
from functools import lru_cache

from . import latex, onpaper
from .errors import AnswerError
from .lexer import COMMA, END, EQUALS, LPAR, NAME, NUM, OP, ROOT, RPAR, SEMI, SUP, Token
from .functions import FUNCTIONS
from .names import CONSTANTS, REFUSED_FUNCTIONS, canonical_function, is_plain, suggest
from .nodes import BinOp, Call, Const, Expr, Name, Neg, Num, Unit, nesting_and_terms

#: Deepest nesting accepted: brackets, function calls, unary signs and powers, and the
#: height of the tree once chains of ``+ -`` and of ``* /`` are flattened.
MAX_DEPTH = 100
#: Most terms in one flat sum or product (``a + b - c`` has three).
MAX_TERMS = 1000

#: Most tree nodes one character of an answer can make (a superscript: power, number and
#: sign; and a product written without an operator between two operands), so answers
#: shorter than MAX_DEPTH / 4 characters cannot exceed a limit and are not measured.
_NODES_PER_CHARACTER = 4

_BP_SUM, _BP_PRODUCT, _BP_UNARY, _BP_POWER, _BP_SUPERSCRIPT = 10, 20, 30, 40, 50
_BP_ROOT = 35  # √ takes the next operand with its exponent: √x² is √(x²)
_CLOSERS = {"(": ")", "[": "]", "{": "}"}
_STARTS_OPERAND = {NUM, NAME, LPAR, ROOT}


@dataclass(frozen=True)
class Vocabulary:
    """What names mean while parsing: declared variables, or units (quantity mode)."""

    variables: frozenset = frozenset()
    quantity: bool = False
    #: (spelling, variable) pairs: further names of the variables (:func:`names.alias_table`)
    aliases: tuple = ()

    @property
    def plain_aliases(self) -> dict[str, str]:
        """The aliases that are one name token, resolved in the name lookup."""
        return _plain(self.aliases)[0]

    @property
    def spelled_symbols(self) -> tuple:
        """The aliases the tokenizer reads whole (``v_2(0)``), longest first."""
        return _plain(self.aliases)[1]


@lru_cache(maxsize=256)
def _plain(aliases: tuple) -> tuple[dict, tuple]:
    plain = {spelling: name for spelling, name in aliases if is_plain(spelling)}
    spelled = sorted(((s, n) for s, n in aliases if not is_plain(s)), key=lambda p: -len(p[0]))
    return plain, tuple(spelled)


def parse_expression(text: str, variables=(), aliases=None) -> Expr:
    """Parse a formula in the declared ``variables`` (expression mode).

    ``aliases`` maps further spellings to variable names (``{"lambda": "lat",
    "v_2(0)": "v02"}``): a spelling is resolved by the name lookup, never evaluated."""
    pairs = tuple(sorted(dict(aliases or {}).items()))
    return _parse(text, Vocabulary(frozenset(variables), quantity=False, aliases=pairs),
                  decimal_comma=False)


def parse_quantity(text: str, *, decimal_comma: bool = True) -> Expr:
    """Parse a number possibly with a unit (quantity mode); ``12,5`` is 12.5."""
    return _parse(text, Vocabulary(quantity=True), decimal_comma=decimal_comma)


def parse_vector(text: str) -> tuple[list[Expr], Expr | None]:
    """Parse ``[1.2, -3.4]``, ``(1.2, -3.4) m/s`` or ``1.2, -3.4``.

    Returns the components and the unit written after the closing bracket (or None).
    Components are separated by commas, or by semicolons when the answer uses any
    (then commas are decimal commas: ``(1,5; 2,5)``).
    """
    decimal_comma = ";" in text
    tokens = latex.tokenize(text, max_depth=MAX_DEPTH, quantity=True, decimal_comma=decimal_comma)
    parser = _Parser(tokens, text, Vocabulary(quantity=True))
    separator = SEMI if decimal_comma else COMMA
    opener = parser.peek()
    bracketed = opener.kind == LPAR and _matching_close(tokens, 0) is not None and \
        _has_top_level(tokens, separator)
    components: list[Expr] = []
    if bracketed:
        parser.advance()
    if parser.peek().kind in (END, RPAR):
        raise AnswerError(_("the vector has no components"), parser.peek().pos, text)
    while True:
        components.append(parser.expression(0))
        token = parser.peek()
        if token.kind == separator:
            parser.advance()
            continue
        break
    unit = None
    if bracketed:
        close = parser.peek()
        if close.kind != RPAR:
            raise AnswerError(_("expected '{closer}' to close the vector").format(closer=_CLOSERS[opener.value]), close.pos, text)
        if close.value != _CLOSERS[opener.value]:
            raise AnswerError(_("'{opener}' is closed by '{closer}'").format(opener=opener.value, closer=close.value), close.pos, text)
        parser.advance()
        if parser.peek().kind != END:
            unit = parser.expression(0)
    parser.expect_end()
    for part in components + ([unit] if unit is not None else []):
        check_limits(part)
    return components, unit


def _matching_close(tokens: list[Token], start: int) -> int | None:
    level = 0
    for k in range(start, len(tokens)):
        if tokens[k].kind == LPAR:
            level += 1
        elif tokens[k].kind == RPAR:
            level -= 1
            if level == 0:
                return k
    return None


def _has_top_level(tokens: list[Token], separator: str) -> bool:
    level = 0
    for token in tokens:
        if token.kind == LPAR:
            level += 1
        elif token.kind == RPAR:
            level -= 1
        elif token.kind == separator and level == 1:
            return True
    return False


@lru_cache(maxsize=1024)
def _parse(text: str, vocabulary: Vocabulary, *, decimal_comma: bool) -> Expr:
    """The tree of ``text``, kept for the texts read last: the server reads an answer to
    say how it reads and then grades it, and a tree's nodes never change. (A text that
    cannot be read raises every time; only trees are kept.)"""
    tokens = latex.tokenize(text, max_depth=MAX_DEPTH, quantity=vocabulary.quantity,
                            decimal_comma=decimal_comma, names=vocabulary.variables,
                            spellings=vocabulary.spelled_symbols)
    # "v = 12 m/s": the name on the left of a single '=' is ignored.
    if len(tokens) > 2 and tokens[0].kind == NAME and tokens[1].kind == EQUALS:
        tokens = tokens[2:]
    parser = _Parser(tokens, text, vocabulary)
    if parser.peek().kind == END:
        raise AnswerError(_("the answer is empty"))
    tree = parser.expression(0)
    parser.expect_end()
    if len(text) * _NODES_PER_CHARACTER > MAX_DEPTH:
        check_limits(tree)
    return tree


def check_limits(tree: Expr) -> None:
    """Refuse a tree nested more than :data:`MAX_DEPTH` levels (chains of ``+ -`` and
    ``* /`` count once) or with a chain of more than :data:`MAX_TERMS` terms."""
    nesting, terms = nesting_and_terms(tree)
    if nesting > MAX_DEPTH:
        raise AnswerError(_("the expression is too complex (nested more than {levels} levels)").format(levels=MAX_DEPTH))
    if terms > MAX_TERMS:
        raise AnswerError(_("the expression is too long (a sum or product of more than {terms} terms)").format(terms=MAX_TERMS))


class _Parser:
    def __init__(self, tokens: list[Token], text: str, vocabulary: Vocabulary):
        self.tokens = tokens
        self.text = text
        self.vocabulary = vocabulary
        self.index = 0
        self.level = 0

    # -- token stream -------------------------------------------------------------------
    def peek(self, offset: int = 0) -> Token:
        try:
            return self.tokens[self.index + offset]
        except IndexError:
            return self.tokens[-1]

    def advance(self) -> Token:
        token = self.tokens[self.index]
        self.index += 1
        return token

    def error(self, message: str, token: Token) -> AnswerError:
        return AnswerError(message, token.pos, self.text)

    def expect_end(self) -> None:
        token = self.peek()
        if token.kind == END:
            return
        if token.kind == RPAR:
            raise self.error(_("unexpected '{token}' (no matching opening bracket)").format(token=token.value), token)
        if token.kind in (COMMA, SEMI):
            raise self.error(self._comma_message(), token)
        if token.kind == NUM:
            raise self.error(_("missing operator before '{token}'?").format(token=token.value), token)
        if token.kind == EQUALS:
            raise self.error(_("give only the value or the expression, not an equation"), token)
        raise self.error(_("unexpected '{token}'").format(token=token.value), token)

    def _comma_message(self) -> str:
        if self.vocabulary.quantity:
            return _("unexpected comma: separate thousands without commas, and write decimals as "
                     "12.5 or 12,5")
        return _("unexpected comma: commas only separate the arguments of a function like "
                 "atan2(y, x); write decimals with '.'")

    # -- Pratt loop ---------------------------------------------------------------------
    def expression(self, rbp: int) -> Expr:
        self.level += 1
        if self.level > MAX_DEPTH:
            raise self.error(_("the expression is nested too deeply (more than {levels} levels)").format(levels=MAX_DEPTH), self.peek())
        try:
            left = self.nud(self.advance())
            while True:
                token = self.peek()
                bp = self.left_binding_power(token)
                if bp <= rbp:
                    return left
                left = self.led(token, left)
        finally:
            self.level -= 1

    def left_binding_power(self, token: Token) -> int:
        if token.kind == OP:
            return {"+": _BP_SUM, "-": _BP_SUM, "*": _BP_PRODUCT, "/": _BP_PRODUCT, "^": _BP_POWER}[token.value]
        if token.kind == SUP:
            return _BP_SUPERSCRIPT
        if token.kind in _STARTS_OPERAND:
            return _BP_PRODUCT  # a product written without an operator
        return 0

    def nud(self, token: Token) -> Expr:
        kind = token.kind
        if kind == NUM:
            return Num(float(token.value.replace(",", ".")), token.value)
        if kind == NAME:
            return self.name(token)
        if kind == LPAR:
            if token.value != "(" and not self.vocabulary.quantity:
                raise self.error(_("use round brackets ( ) for grouping"), token)
            if self.peek().kind == RPAR:
                raise self.error(_("empty brackets"), self.peek())
            inner = self.expression(0)
            self.close(token)
            return inner
        if kind == OP and token.value in "+-":
            operand = self.expression(_BP_UNARY)
            return Neg(operand) if token.value == "-" else operand
        if kind == ROOT:
            if self.peek().kind in (END, RPAR, OP, COMMA, SEMI):
                raise self.error(_("'{root}' needs something to take the root of").format(root=self.text[token.pos]), token)
            return Call(token.value, (self.expression(_BP_ROOT),))
        if kind == END:
            raise self.error(_("the answer ends too early: something is missing here"), token)
        if kind == RPAR:
            raise self.error(_("unexpected '{token}'").format(token=token.value), token)
        if kind in (COMMA, SEMI):
            raise self.error(self._comma_message(), token)
        if kind == SUP:
            raise self.error(_("an exponent needs something before it"), token)
        if kind == EQUALS:
            raise self.error(_("give only the value or the expression, not an equation"), token)
        raise self.error(_("unexpected '{token}': something is missing before it").format(token=token.value), token)

    def led(self, token: Token, left: Expr) -> Expr:
        if token.kind == OP:
            self.advance()
            if token.value == "^":
                return BinOp("^", left, self.expression(_BP_POWER - 1))
            bp = _BP_SUM if token.value in "+-" else _BP_PRODUCT
            if self.peek().kind == OP and self.peek().value in "*/^":
                raise self.error(_("two operators in a row: '{operators}'").format(operators=token.value + self.peek().value), self.peek())
            return BinOp(token.value, left, self.expression(bp))
        if token.kind == SUP:
            self.advance()
            exponent = int(token.value)
            node: Expr = Num(float(abs(exponent)), str(abs(exponent)))
            return BinOp("^", left, Neg(node) if exponent < 0 else node)
        # Product written without an operator.
        if token.kind == NUM and not (self.vocabulary.quantity and token.value == "1"
                                      and self.peek(1).kind == OP and self.peek(1).value == "/"):
            raise self.error(_("missing operator before '{token}'?").format(token=token.value), token)
        return BinOp("*", left, self.expression(_BP_PRODUCT), implicit=True)

    def close(self, opener: Token) -> None:
        token = self.peek()
        want = _CLOSERS[opener.value]
        if token.kind != RPAR:
            if token.kind == END:
                raise AnswerError(_("missing '{closer}' to close the '{opener}' opened here").format(closer=want, opener=opener.value),
                                  opener.pos, self.text)
            if token.kind in (COMMA, SEMI):
                raise self.error(self._comma_message(), token)
            raise self.error(_("expected '{closer}'").format(closer=want), token)
        if token.value != want:
            raise self.error(_("'{opener}' is closed by '{closer}'").format(opener=opener.value, closer=token.value), token)
        self.advance()

    # -- names --------------------------------------------------------------------------
    def name(self, token: Token) -> Expr:
        word = token.value
        follows_bracket = self.peek().kind == LPAR and self.peek().value == "("
        if self.peek().kind == LPAR and self.peek().value == "[" and not self.vocabulary.quantity:
            raise self.error(_("subscripts like a[0] are not allowed"), self.peek())
        if word.startswith("_"):
            raise self.error(_("names starting with '_' are not allowed ('{name}')").format(name=word[:30]), token)
        function = canonical_function(word)
        if function and follows_bracket and word not in self.vocabulary.variables:
            return self.call(token, function)
        if function and word not in self.vocabulary.variables:
            written = onpaper.application(self, token, function, quantity=self.vocabulary.quantity,
                                          product_power=_BP_PRODUCT)
            if written is not None:
                return written
        if self.vocabulary.quantity:
            return self.quantity_name(token, function)
        variables = self.vocabulary.variables
        if word in variables:
            return Name(word)
        alias = self.vocabulary.plain_aliases.get(word)
        if alias is not None:
            return Name(alias)
        spelled = _without_underscores(variables).get(word.replace("_", ""))
        if spelled and "_" in word:
            return Name(spelled)
        if word in CONSTANTS:
            return Const(word)
        if function:
            raise self.error(_("write {function}(...) with brackets around its argument").format(function=word), token)
        if word in REFUSED_FUNCTIONS:
            raise self.error(f"'{word}': {_(REFUSED_FUNCTIONS[word])}", token)
        pieces = _split_name(word, variables, follows_bracket)
        if pieces:
            return self.product_of_pieces(token, pieces)
        if spelled:
            return Name(spelled)
        pool = list(variables) + list(CONSTANTS) + list(FUNCTIONS)
        hint = suggest(word, pool) if len(word) <= 40 else None
        word = word if len(word) <= 30 else word[:30] + "…"
        did_you_mean = _("; did you mean '{hint}'?").format(hint=hint) if hint else ""
        if follows_bracket:
            raise self.error(_("unknown function '{name}'").format(name=word) + did_you_mean,
                             token)
        known = ", ".join(sorted(variables)) if variables else _("none")
        raise self.error(_("unknown name '{name}'{did_you_mean} (the variables are: {names})")
                         .format(name=word, did_you_mean=did_you_mean, names=known), token)

    def is_function(self, token: Token) -> bool:
        """Whether a name token names a function rather than a declared variable."""
        return token.kind == NAME and token.value not in self.vocabulary.variables and \
            canonical_function(token.value) is not None

    def product_of_pieces(self, token: Token, pieces: list[str]) -> Expr:
        """Read the first piece now and put the others back into the token stream, so
        that ``mv^2`` is m·v² (the exponent binds to the last piece only)."""
        rest = [Token(NAME, piece, token.pos) for piece in pieces[1:]]
        self.tokens[self.index:self.index] = rest
        first = pieces[0]
        return Name(first) if first in self.vocabulary.variables else Const(first)

    def quantity_name(self, token: Token, function: str | None) -> Expr:
        """In a number-with-unit answer a bare name is a unit (``min``, ``sec`` too)."""
        word = token.value
        if word in CONSTANTS:
            return Const(word)
        if word in REFUSED_FUNCTIONS and self.peek().kind == LPAR:
            raise self.error(f"'{word}': {_(REFUSED_FUNCTIONS[word])}", token)
        if word.lower() in ("nan", "inf", "infinity"):
            raise self.error(_("'{word}' is not a valid answer: give a finite number").format(word=word), token)
        return Unit(word, token.pos)

    def call(self, token: Token, function: str) -> Expr:
        opener = self.advance()
        arity = FUNCTIONS[function].arity
        if self.peek().kind == RPAR:
            raise self.error(_("{function}() needs an argument").format(function=token.value), self.peek())
        args = [self.expression(0)]
        while self.peek().kind == COMMA:
            comma = self.advance()
            if len(args) >= arity:
                raise self.error(ngettext("{function} takes {n} argument", "{function} takes {n} arguments", arity).format(function=token.value, n=arity), comma)
            args.append(self.expression(0))
        self.close(opener)
        if len(args) != arity:
            raise self.error(ngettext("{function} takes {n} argument", "{function} takes {n} arguments", arity).format(function=token.value, n=arity), token)
        return Call(function, tuple(args))


@lru_cache(maxsize=256)
def _without_underscores(variables: frozenset) -> dict[str, str]:
    """Declared names by their spelling without ``_`` (``omegan`` -> ``omega_n``), leaving
    out spellings two declared names share."""
    spellings: dict[str, list[str]] = {}
    for name in variables:
        spellings.setdefault(name.replace("_", ""), []).append(name)
    return {key: names[0] for key, names in spellings.items() if len(names) == 1}


def _split_name(word: str, variables: frozenset, follows_bracket: bool) -> list[str] | None:
    """Read ``word`` as declared names written together (``mg`` -> m, g).

    Longest pieces first; constants may appear as pieces when not declared; a function
    may end the run when a bracket follows (``msin(a)``). None when no reading exists.
    """
    if not variables or len(word) > 40:
        return None
    pieces = set(variables) | set(CONSTANTS)
    return _split_cached(word, frozenset(pieces), follows_bracket)


@lru_cache(maxsize=4096)
def _split_cached(word: str, pieces: frozenset, follows_bracket: bool) -> list[str] | None:
    lengths = sorted({len(p) for p in pieces}, reverse=True)

    def search(start: int) -> list[str] | None:
        if start == len(word):
            return []
        if follows_bracket:
            tail = word[start:]
            if canonical_function(tail) and start > 0:
                return [tail]
        for length in lengths:
            piece = word[start:start + length]
            if len(piece) == length and piece in pieces:
                rest = search(start + length)
                if rest is not None:
                    return [piece] + rest
        return None

    result = search(0)
    if result is None or len(result) < 2:
        return None
    return result
