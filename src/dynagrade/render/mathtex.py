"""The TeX math of exercise statements, rendered without TeX and without a network.

Statements write math between dollar signs in the TeX subset that physics statements
need: letters and numbers, Greek letters, sub- and superscripts, ``\\frac``, ``\\sqrt``,
``\\mathrm``/``\\text``/``\\mathbf``, accents (``\\dot``, ``\\vec``, ...), common
operators and function names, and spacing. One parser turns it into a small tree that
three writers print: MathML Core (which browsers lay out natively), typst math, and a
spoken form (the alternative text of an equation in a tagged PDF).

Usage::

    to_mathml(r"x_{1,\\max} = \\frac{v_0^2}{g}")   # '<math ...>...</math>'
    to_typst(r"\\alpha = 30")                     # 'α = 30'
    to_speech(r"\\mathbf{r} = \\frac{a}{2}")       # 'bold r equals fraction a over 2 end
                                                 #  fraction'

A command outside the subset is shown as its own text, and listed by :func:`unknown_commands`
so that an author can be told.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass, field
from functools import lru_cache

__all__ = ["parse", "to_mathml", "to_typst", "to_speech", "unknown_commands", "MathNode"]

_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ϵ",
    "varepsilon": "ε", "zeta": "ζ", "eta": "η", "theta": "θ", "vartheta": "ϑ",
    "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ",
    "pi": "π", "varpi": "ϖ", "rho": "ρ", "varrho": "ϱ", "sigma": "σ", "varsigma": "ς",
    "tau": "τ", "upsilon": "υ", "phi": "ϕ", "varphi": "φ", "chi": "χ", "psi": "ψ",
    "omega": "ω", "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ",
    "Pi": "Π", "Sigma": "Σ", "Upsilon": "Υ", "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω",
    "ell": "ℓ", "hbar": "ℏ", "infty": "∞", "partial": "∂", "nabla": "∇",
}
_UPRIGHT_GREEK = set("ΓΔΘΛΞΠΣΥΦΨΩ∞∂∇")
_OPERATORS = {
    "cdot": "⋅", "times": "×", "pm": "±", "mp": "∓", "le": "≤", "leq": "≤", "ge": "≥",
    "geq": "≥", "ne": "≠", "neq": "≠", "approx": "≈", "equiv": "≡", "sim": "∼",
    "propto": "∝", "to": "→", "rightarrow": "→", "leftarrow": "←", "Rightarrow": "⇒",
    "Leftrightarrow": "⇔", "circ": "∘", "degree": "°", "ldots": "…", "dots": "…",
    "cdots": "⋯", "sum": "∑", "int": "∫", "oint": "∮", "prod": "∏", "parallel": "∥",
    "perp": "⊥", "angle": "∠", "in": "∈", "mid": "∣", "langle": "⟨", "rangle": "⟩",
    "lvert": "|", "rvert": "|", "vert": "|", "Vert": "‖", "lbrace": "{", "rbrace": "}",
    "colon": ":", "ll": "≪", "gg": "≫", "times_": "×",
}
_FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan",
              "sinh", "cosh", "tanh", "ln", "log", "exp", "max", "min", "det", "lim",
              "sgn", "tr", "arg", "dim", "ker"}
_SPACES = {",": 0.1667, ":": 0.2222, ">": 0.2222, ";": 0.2778, " ": 0.25, "!": 0.0,
           "quad": 1.0, "qquad": 2.0, "enspace": 0.5, "thinspace": 0.1667}
_ACCENTS = {"dot": "˙", "ddot": "¨", "vec": "→", "hat": "^", "bar": "¯", "tilde": "~",
            "overline": "¯", "check": "ˇ", "breve": "˘"}
_FONTS = {"mathrm": "upright", "text": "text", "textrm": "text", "mathit": "italic",
          "mathbf": "bold", "boldsymbol": "bold", "bm": "bold", "operatorname": "upright",
          "mathsf": "upright", "mathtt": "upright"}
_ESCAPED = {"{": "{", "}": "}", "%": "%", "$": "$", "&": "&", "#": "#", "_": "_",
            "|": "‖"}
_TOKEN = re.compile(r"\\[A-Za-z]+|\\.|\d+(?:\.\d+)?|\.\d+|[A-Za-z]|\s+|.", re.S)

MAX_TEX_LENGTH = 5000
MAX_DEPTH = 50


# -- the tree -----------------------------------------------------------------------------


@dataclass(frozen=True)
class MathNode:
    """One node of the math tree.

    ``kind`` is one of: row, ident, number, op, text, space, script, frac, sqrt, accent.
    """

    kind: str
    text: str = ""
    children: tuple["MathNode", ...] = ()
    style: str = ""  # ident: "", "upright", "bold", "italic"; op: "stretchy"
    width: float = 0.0  # space, in em


def _row(items) -> MathNode:
    items = tuple(items)
    return items[0] if len(items) == 1 else MathNode("row", children=items)


_EMPTY = MathNode("row")


@dataclass
class _Parser:
    tokens: list[str]
    position: int = 0
    unknown: list[str] = field(default_factory=list)
    depth: int = 0

    def peek(self) -> str | None:
        return self.tokens[self.position] if self.position < len(self.tokens) else None

    def take(self) -> str | None:
        token = self.peek()
        if token is not None:
            self.position += 1
        return token

    def row(self, closing: tuple[str, ...] = (), font: str = "") -> MathNode:
        """Atoms until one of ``closing`` (consumed) or the end."""
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ValueError("math nested too deeply")
        items: list[MathNode] = []
        while True:
            token = self.peek()
            if token is None:
                break
            if token in closing:
                self.take()
                break
            if token in ("^", "_"):
                self.take()
                base = items.pop() if items else _EMPTY
                items.append(self._attach(base, token, font))
                continue
            atom = self.atom(font)
            if atom is not None:
                if font in ("upright", "text") and atom.kind == "ident" and items \
                        and items[-1].kind == "ident" and items[-1].style == atom.style \
                        and atom.text.isalpha() and items[-1].text.isalpha():
                    items[-1] = MathNode("ident", items[-1].text + atom.text, style=atom.style)
                else:
                    items.append(atom)
        self.depth -= 1
        return _row(items)

    def _attach(self, base: MathNode, mark: str, font: str) -> MathNode:
        script = self.argument(font)
        sub, sup = (base.children[1], base.children[2]) if base.kind == "script" \
            else (None, None)
        core = base.children[0] if base.kind == "script" else base
        if base.kind == "script" and ((mark == "_" and sub is None) or
                                      (mark == "^" and sup is None)):
            sub = script if mark == "_" else sub
            sup = script if mark == "^" else sup
        else:
            core = base
            sub, sup = (script, None) if mark == "_" else (None, script)
        return MathNode("script", children=(core, sub, sup))

    def argument(self, font: str = "") -> MathNode:
        """A command's argument: a braced group or a single atom."""
        while self.peek() is not None and self.peek().isspace():
            self.take()
        if self.peek() == "{":
            self.take()
            return self.row(("}",), font)
        atom = self.atom(font)
        return atom if atom is not None else _EMPTY

    def atom(self, font: str = "") -> MathNode | None:
        token = self.take()
        if token is None:
            return None
        if token.isspace():
            return MathNode("space", width=0.25) if font == "text" else None
        if token == "{":
            return self.row(("}",), font)
        if token[0].isdigit() or (token[0] == "." and len(token) > 1):
            return MathNode("number", token)
        if token.isalpha():
            style = {"upright": "upright", "text": "upright", "bold": "bold"}.get(font, "")
            return MathNode("ident", token, style=style)
        if token.startswith("\\"):
            return self.command(token[1:], font)
        if token == "'":
            return MathNode("op", "′")
        if token == "-":
            return MathNode("op", "−")
        if token == "~":
            return MathNode("space", width=0.25)
        return MathNode("op", token)

    def command(self, name: str, font: str) -> MathNode | None:
        if name in _GREEK:
            char = _GREEK[name]
            style = "bold" if font == "bold" else ("upright" if char in _UPRIGHT_GREEK else "")
            return MathNode("ident", char, style=style)
        if name in _OPERATORS:
            return MathNode("op", _OPERATORS[name])
        if name in _FUNCTIONS:
            return MathNode("ident", name, style="function")
        if name in _SPACES:
            return MathNode("space", width=_SPACES[name])
        if name in _ESCAPED:
            return MathNode("op", _ESCAPED[name])
        if name == "\\":
            return MathNode("space", width=1.0)
        if name == "frac" or name == "dfrac" or name == "tfrac":
            numerator = self.argument(font)
            return MathNode("frac", children=(numerator, self.argument(font)))
        if name == "sqrt":
            index = None
            if self.peek() == "[":
                self.take()
                index = self.row(("]",), font)
            body = self.argument(font)
            return MathNode("sqrt", children=(body,) if index is None else (body, index))
        if name in _ACCENTS:
            return MathNode("accent", _ACCENTS[name], children=(self.argument(font),))
        if name in _FONTS:
            inner = _FONTS[name]
            if inner == "text":
                return MathNode("text", self._raw_group())
            return self.argument(inner)
        if name in ("left", "right", "big", "Big", "bigl", "bigr", "Bigl", "Bigr"):
            delimiter = self.take() or ""
            if delimiter.startswith("\\"):
                node = self.command(delimiter[1:], font)
                delimiter = node.text if node is not None and node.kind == "op" else ""
            if delimiter == ".":
                return None
            return MathNode("op", delimiter, style="stretchy") if delimiter else None
        self.unknown.append("\\" + name)
        return MathNode("text", "\\" + name)

    def _raw_group(self) -> str:
        """The text of a braced group, as written (for ``\\text{...}``)."""
        while self.peek() is not None and self.peek().isspace():
            self.take()
        if self.peek() != "{":
            return self.take() or ""
        self.take()
        depth, parts = 1, []
        while self.peek() is not None:
            token = self.take()
            if token == "{":
                depth += 1
            elif token == "}":
                depth -= 1
                if depth == 0:
                    break
            parts.append(token[1:] if token.startswith("\\") and len(token) == 2 else token)
        return "".join(parts)


@lru_cache(maxsize=4096)
def _parse(tex: str) -> tuple[MathNode, tuple[str, ...]]:
    if len(tex) > MAX_TEX_LENGTH:
        raise ValueError(f"math of {len(tex)} characters is too long")
    parser = _Parser(_TOKEN.findall(tex))
    nodes = []
    while parser.peek() is not None:
        nodes.append(parser.row(("}",)))  # a stray closing brace ends a row: go on
    return _row(nodes), tuple(parser.unknown)


def parse(tex: str) -> MathNode:
    """The tree of the TeX math ``tex`` (without the dollar signs)."""
    return _parse(tex)[0]


def unknown_commands(tex: str) -> tuple[str, ...]:
    """Commands in ``tex`` outside the supported subset (shown as plain text)."""
    return _parse(tex)[1]


# -- MathML -------------------------------------------------------------------------------


@lru_cache(maxsize=4096)  # the same symbols recur on every student's sheet
def to_mathml(tex: str, display: bool = False) -> str:
    """``tex`` as a MathML Core ``<math>`` element (no scripts, no network).

    There is no ``alttext``: a screen reader speaks the MathML itself, and the TeX source
    would be read out as "backslash frac"."""
    body = _mathml(parse(tex))
    mode = "block" if display else "inline"
    return f'<math display="{mode}">{body}</math>'


def _bold_character(char: str) -> str:
    """``char`` as its Mathematical Bold character (U+1D400 and following), so that bold
    survives without CSS and a screen reader says "bold r"; other characters unchanged."""
    code = ord(char)
    if "A" <= char <= "Z":
        return chr(0x1D400 + code - ord("A"))
    if "a" <= char <= "z":
        return chr(0x1D41A + code - ord("a"))
    if "0" <= char <= "9":
        return chr(0x1D7CE + code - ord("0"))
    if 0x391 <= code <= 0x3A9:
        return chr(0x1D6B9) if code == 0x3A2 else chr(0x1D6A8 + code - 0x391)
    if 0x3B1 <= code <= 0x3C9:
        return chr(0x1D6C2 + code - 0x3B1)
    return _BOLD_SYMBOLS.get(char, char)


_BOLD_SYMBOLS = {"∇": "\U0001D6C1", "∂": "\U0001D6DB", "ϵ": "\U0001D6DC", "ϑ": "\U0001D6DD",
                 "ϰ": "\U0001D6DE", "ϕ": "\U0001D6DF", "ϱ": "\U0001D6E0", "ϖ": "\U0001D6E1"}


def bold_text(text: str) -> str:
    """``text`` in Mathematical Bold characters (see :func:`_bold_character`)."""
    return "".join(_bold_character(char) for char in text)


def _mathml(node: MathNode) -> str:
    kind = node.kind
    if kind == "row":
        return "<mrow>" + "".join(_mathml(c) for c in node.children) + "</mrow>"
    if kind == "ident":
        text = html.escape(node.text, quote=False)
        if node.style == "bold":
            return f'<mi mathvariant="bold">{bold_text(text)}</mi>'
        if node.style in ("upright", "function") and len(node.text) == 1:
            return f'<mi mathvariant="normal">{text}</mi>'
        return f"<mi>{text}</mi>"
    if kind == "number":
        return f"<mn>{node.text}</mn>"
    if kind == "op":
        text = html.escape(node.text, quote=False)
        if node.style == "stretchy":
            return f'<mo stretchy="true">{text}</mo>'
        return f"<mo>{text}</mo>"
    if kind == "text":
        return f"<mtext>{html.escape(node.text, quote=False)}</mtext>"
    if kind == "space":
        return f'<mspace width="{node.width:.4g}em"></mspace>'
    if kind == "script":
        base, sub, sup = node.children
        inner = _mathml(base) + (_mathml(sub) if sub is not None else "") \
            + (_mathml(sup) if sup is not None else "")
        tag = "msubsup" if sub is not None and sup is not None else \
            "msub" if sub is not None else "msup"
        return f"<{tag}>{inner}</{tag}>"
    if kind == "frac":
        return "<mfrac>" + "".join(_wrapped(c) for c in node.children) + "</mfrac>"
    if kind == "sqrt":
        if len(node.children) == 2:
            return "<mroot>" + _wrapped(node.children[0]) + _wrapped(node.children[1]) \
                + "</mroot>"
        return "<msqrt>" + _mathml(node.children[0]) + "</msqrt>"
    if kind == "accent":
        mark = html.escape(node.text, quote=False)
        return (f'<mover accent="true">{_wrapped(node.children[0])}'
                f'<mo stretchy="false">{mark}</mo></mover>')
    raise ValueError(f"unknown math node {kind!r}")


def _wrapped(node: MathNode) -> str:
    """A node as exactly one MathML element (an argument of mfrac, mroot, mover)."""
    text = _mathml(node)
    return text if node.kind != "row" or text.startswith("<mrow>") else f"<mrow>{text}</mrow>"


# -- spoken form --------------------------------------------------------------------------

_SPOKEN_OPERATORS = {
    "=": "equals", "+": "plus", "−": "minus", "±": "plus or minus", "⋅": "times",
    "×": "cross", "/": "over", "<": "is less than", ">": "is greater than",
    "≤": "is less than or equal to", "≥": "is greater than or equal to",
    "≠": "is not equal to", "≈": "is approximately", "→": "to", "∝": "is proportional to",
    "′": "prime", "°": "degrees", "∑": "sum", "∫": "integral", "∥": "parallel to",
    "⊥": "perpendicular to", "≪": "is much less than", "≫": "is much greater than",
}
_SPOKEN_ACCENTS = {"˙": "{} dot", "¨": "{} double dot", "→": "vector {}", "^": "{} hat",
                   "¯": "{} bar", "~": "{} tilde", "ˇ": "{} check", "˘": "{} breve"}
_SPOKEN_POWERS = {"2": "squared", "3": "cubed"}


@lru_cache(maxsize=4096)  # the same symbols recur on every student's sheet
def to_speech(tex: str) -> str:
    """``tex`` read out in English words, as a screen reader would say it ("v sub 0
    squared over 2 g"); symbols it has no word for are kept."""
    return " ".join(_speech(parse(tex)).split())


def _speech(node: MathNode) -> str:
    kind = node.kind
    if kind == "row":
        return " ".join(_speech(c) for c in node.children)
    if kind == "ident":
        return f"bold {node.text}" if node.style == "bold" else node.text
    if kind in ("number", "text"):
        return node.text
    if kind == "op":
        return _SPOKEN_OPERATORS.get(node.text, node.text)
    if kind == "space":
        return ""
    if kind == "script":
        base, sub, sup = node.children
        words = _speech(base)
        if sub is not None:
            words += f" sub {_speech(sub)}"
        if sup is not None:
            power = _speech(sup)
            words += " " + (_SPOKEN_POWERS.get(power) or
                            (power if power == "prime" else f"to the power {power} end power"))
        return words
    if kind == "frac":
        numerator, denominator = (_speech(c) for c in node.children)
        return f"fraction {numerator} over {denominator} end fraction"
    if kind == "sqrt":
        if len(node.children) == 2:
            return (f"root of index {_speech(node.children[1])} of "
                    f"{_speech(node.children[0])} end root")
        return f"square root of {_speech(node.children[0])} end root"
    if kind == "accent":
        return _SPOKEN_ACCENTS.get(node.text, "{} " + node.text).format(
            _speech(node.children[0]))
    raise ValueError(f"unknown math node {kind!r}")


# -- typst --------------------------------------------------------------------------------

_TYPST_SPECIAL = set("\\/()[]{}_^&#$\",;:'*!@~<>=|+-.`")


@lru_cache(maxsize=4096)  # the same symbols recur on every student's sheet
def to_typst(tex: str) -> str:
    """``tex`` as typst math (the text between typst's ``$`` signs)."""
    return _typst(parse(tex)).strip()


def _typst(node: MathNode) -> str:
    kind = node.kind
    if kind == "row":
        return " ".join(_typst(c) for c in node.children)
    if kind == "ident":
        text = node.text
        if node.style == "function":
            return f'op("{text}")'
        if len(text) > 1:
            shown = f'"{typst_string(text)}"'
            return f"bold({shown})" if node.style == "bold" else shown
        if node.style == "bold":
            return f"bold({text})"
        if node.style == "upright" and text.isalpha():
            return f"upright({text})"
        return text
    if kind == "number":
        return node.text
    if kind == "op":
        return "".join("\\" + c if c in _TYPST_SPECIAL else c for c in node.text)
    if kind == "text":
        return f'"{typst_string(node.text)}"'
    if kind == "space":
        if node.width <= 0:
            return ""
        return {0.1667: "thin", 0.2222: "med", 0.2778: "thick", 1.0: "quad",
                2.0: "wide"}.get(node.width, f"#h({node.width:.4g}em)")
    if kind == "script":
        base, sub, sup = node.children
        args = [_typst_arg(base)]
        if sub is not None:
            args.append("b: " + _typst_arg(sub))
        if sup is not None:
            args.append("t: " + _typst_arg(sup))
        return "attach(" + ", ".join(args) + ")"
    if kind == "frac":
        return f"frac({_typst_arg(node.children[0])}, {_typst_arg(node.children[1])})"
    if kind == "sqrt":
        if len(node.children) == 2:
            return f"root({_typst_arg(node.children[1])}, {_typst_arg(node.children[0])})"
        return f"sqrt({_typst_arg(node.children[0])})"
    if kind == "accent":
        return f"accent({_typst_arg(node.children[0])}, {node.text})" \
            if node.text not in "^~" else \
            f"accent({_typst_arg(node.children[0])}, \\{node.text})"
    raise ValueError(f"unknown math node {kind!r}")


def _typst_arg(node: MathNode) -> str:
    text = _typst(node)
    return text if text.strip() else '""'


def typst_string(text: str) -> str:
    """``text`` as the inside of a typst string literal (the one escaper of the renderers)."""
    return (text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n")
            .replace("\r", "\\r"))
