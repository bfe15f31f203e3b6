"""Figure labels as SVG text: the small TeX subset labels use, written with Unicode.

A label is plain Unicode text ("v₀ = 3 m/s", "θ = 30°") with optional ``$...$`` math in
the subset mathtext labels were written in: Greek letters (``\\theta``, ``\\omega``,
``\\Delta``, ``\\varphi`` …), sub- and superscripts (``v_0``, ``\\omega_{n}``, ``x^2``),
accents as combining marks (``\\dot x`` is "ẋ", ``\\ddot x`` "ẍ", ``\\vec``, ``\\hat``,
``\\bar``), ``\\mathrm{..}``/``\\text{..}``, a few symbols (``\\cdot``, ``\\circ``,
``\\times``, ``\\pm``, ``\\infty``, ``\\partial``) and spacing commands. Sub- and
superscripts become ``<tspan>`` elements shifted with ``dy`` (which every viewer and typst
honour) at 70 % of the size. A command outside the subset is an error naming the label.

Usage::

    runs = label_runs(r"$\\omega_{n}$ = 3 1/s")   # [("ω", 0), ("n", -1), (" = 3 1/s", 0)]
    plain_label(r"$\\dot x$")                      # "ẋ"
    svg_tspans(runs, 10.0)                        # the text element's content
    label_width(runs, 10.0)                       # points
"""

from __future__ import annotations

import html

from ..errors import DefinitionError
from .text_metrics import text_width

GREEK = {name: chr(code) for name, code in (
    ("alpha", 0x3B1), ("beta", 0x3B2), ("gamma", 0x3B3), ("delta", 0x3B4),
    ("epsilon", 0x3F5), ("varepsilon", 0x3B5), ("zeta", 0x3B6), ("eta", 0x3B7),
    ("theta", 0x3B8), ("vartheta", 0x3D1), ("iota", 0x3B9), ("kappa", 0x3BA),
    ("lambda", 0x3BB), ("mu", 0x3BC), ("nu", 0x3BD), ("xi", 0x3BE), ("pi", 0x3C0),
    ("rho", 0x3C1), ("sigma", 0x3C3), ("tau", 0x3C4), ("upsilon", 0x3C5), ("phi", 0x3D5),
    ("varphi", 0x3C6), ("chi", 0x3C7), ("psi", 0x3C8), ("omega", 0x3C9),
    ("Gamma", 0x393), ("Delta", 0x394), ("Theta", 0x398), ("Lambda", 0x39B),
    ("Xi", 0x39E), ("Pi", 0x3A0), ("Sigma", 0x3A3), ("Phi", 0x3A6), ("Psi", 0x3A8),
    ("Omega", 0x3A9))}
SYMBOLS = {"cdot": "·", "circ": "°", "degree": "°", "times": "×", "pm": "±",
           "infty": "∞", "partial": "∂", "prime": "′", "cdots": "⋯", "ldots": "…",
           "to": "→", "approx": "≈", "leq": "≤", "geq": "≥", "neq": "≠", "sqrt": "√",
           ",": "\u2009", ";": " ", ":": " ", " ": " ", "quad": "\u2003", "!": "",
           "%": "%", "$": "$", "{": "{", "}": "}", "_": "_", "#": "#", "&": "&"}
ACCENTS = {"dot": "\u0307", "ddot": "\u0308", "vec": "\u20d7", "hat": "\u0302",
           "bar": "\u0304", "tilde": "\u0303"}
WRAPPERS = ("mathrm", "text", "mathit", "mathbf", "boldsymbol", "mathsf", "operatorname")
#: the size of a sub- or superscript relative to its base, and how far (in ems of the
#: base) it sits below or above the baseline
SCRIPT_SIZE, SUB_SHIFT, SUP_SHIFT = 0.7, 0.22, 0.38


def label_runs(label: str) -> list[tuple[str, int]]:
    """``label`` as runs of text and their level: 0 on the baseline, -1 subscript,
    +1 superscript (runs of one level merged)."""
    runs: list[tuple[str, int]] = []
    parts = label.split("$")
    if len(parts) % 2 == 0:
        raise DefinitionError(f"figure label {label!r}: a '$' opens math that no '$' closes")
    for k, part in enumerate(parts):
        if k % 2 == 0:
            _add(runs, part.replace("\\$", "$"), 0)
        else:
            for text, level in _Math(part, label).runs():
                _add(runs, text, level)
    return runs


def plain_label(label: str) -> str:
    """``label`` as plain Unicode text (scripts written on the line)."""
    return "".join(text for text, _ in label_runs(label))


def label_width(runs: list[tuple[str, int]], size: float) -> float:
    """The width (pt) of ``runs`` set at ``size`` points."""
    return sum(text_width(text, size * (SCRIPT_SIZE if level else 1.0)) for text, level in runs)


def svg_tspans(runs: list[tuple[str, int]], size: float) -> str:
    """The content of an SVG ``<text>`` of ``size`` points showing ``runs``: text on the
    baseline as is, scripts in ``<tspan>`` elements moved off it by ``dy`` and back."""
    out, offset = [], 0.0
    for text, level in runs:
        target = {0: 0.0, -1: SUB_SHIFT * size, 1: -SUP_SHIFT * size}[level]
        escaped = html.escape(text, quote=False)
        if level == 0 and offset == 0.0:
            out.append(escaped)
            continue
        shift = f' dy="{_number(target - offset)}"' if target != offset else ""
        scale = f' font-size="{_number(SCRIPT_SIZE * size)}"' if level else ""
        out.append(f"<tspan{shift}{scale}>{escaped}</tspan>")
        offset = target
    return "".join(out)


def _number(value: float) -> str:
    text = f"{value:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def _add(runs: list[tuple[str, int]], text: str, level: int) -> None:
    if not text:
        return
    if runs and runs[-1][1] == level:
        runs[-1] = (runs[-1][0] + text, level)
    else:
        runs.append((text, level))


class _Math:
    """A reader of one ``$...$`` span of a label."""

    def __init__(self, source: str, label: str):
        self.source, self.label, self.at = source, label, 0

    def fail(self, why: str):
        raise DefinitionError(f"figure label {self.label!r}: {why} (labels know Greek "
                              "letters, _ and ^, \\dot, \\mathrm and a few symbols)")

    def runs(self, level: int = 0, stop: str = "") -> list[tuple[str, int]]:
        runs: list[tuple[str, int]] = []
        while self.at < len(self.source):
            char = self.source[self.at]
            if char == stop:
                self.at += 1
                return runs
            if char in "_^":
                self.at += 1
                inner = 1 if char == "^" else -1
                for text, _ in self.group(inner):
                    _add(runs, text, inner)
                continue
            for text, inner in self.group(level):
                _add(runs, text, inner)
        if stop:
            self.fail("a '{' is not closed")
        return runs

    def group(self, level: int) -> list[tuple[str, int]]:
        """One token or one ``{...}`` group at ``level``."""
        if self.at >= len(self.source):
            self.fail("a script or accent has nothing to act on")
        char = self.source[self.at]
        if char == "{":
            self.at += 1
            return self.runs(level, stop="}")
        if char == "\\":
            return self.command(level)
        self.at += 1
        if char == " ":
            return []
        if char == "}":
            self.fail("a '}' closes nothing")
        return [("′" if char == "'" else char, level)]

    def command(self, level: int) -> list[tuple[str, int]]:
        start = self.at + 1
        end = start
        while end < len(self.source) and self.source[end].isalpha():
            end += 1
        if end == start:                 # a one-character command: \, \; \% ...
            end = start + 1
        name = self.source[start:end]
        self.at = end
        if name in GREEK:
            return [(GREEK[name], level)]
        if name in SYMBOLS:
            return [(SYMBOLS[name], level)]
        if name in ACCENTS:
            while self.at < len(self.source) and self.source[self.at] == " ":
                self.at += 1
            inner = self.group(level)
            if not inner:
                self.fail(f"\\{name} has nothing to act on")
            text, at = inner[0]
            return [(text[0] + ACCENTS[name] + text[1:], at), *inner[1:]]
        if name in WRAPPERS:
            while self.at < len(self.source) and self.source[self.at] == " ":
                self.at += 1
            return self.group(level)
        self.fail(f"unknown command \\{name}")
