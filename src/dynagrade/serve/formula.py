"""A formula answer typeset back, so a student sees how ``sqrt(2 g h)`` was read.

The answer is parsed by the grader's safe parser (never evaluated here), printed as TeX
(fractions, roots, powers, Greek letters, indices: ``v0`` → v₀) and laid out as MathML by
:mod:`dynagrade.render.mathtex`, as the sheets' statements are.
"""

from __future__ import annotations

import re

from ..grading.nodes import BinOp, Call, Const, Name, Neg, Num, Unit, format_number

_GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota",
          "kappa", "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi",
          "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma",
          "Phi", "Psi", "Omega"}
_FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan", "sinh",
              "cosh", "tanh", "exp", "ln", "log"}


def formula_mathml(text: str, variables: tuple[str, ...], spellings=None) -> str | None:
    """The formula ``text`` in ``variables`` as a MathML element, or None when it cannot
    be read. ``spellings`` maps the further spellings the grader accepts (``λ``,
    ``v_2(0)``) to variable names, so they typeset as the variable they stand for."""
    from ..grading.errors import AnswerError
    from ..grading.parser import parse_expression
    from ..render.mathtex import to_mathml

    try:
        return to_mathml(to_tex(parse_expression(text, variables, spellings)))
    except (AnswerError, RecursionError, ValueError):
        return None


def to_tex(node) -> str:
    """TeX of an expression tree."""
    if isinstance(node, Num):
        return format_number(node.value)
    if isinstance(node, (Name, Const, Unit)):
        return _name(node.id)
    if isinstance(node, Neg):
        inner = to_tex(node.operand)
        return f"-\\left({inner}\\right)" if isinstance(node.operand, BinOp) and \
            node.operand.op in "+-" else f"-{inner}"
    if isinstance(node, Call):
        args = ", ".join(to_tex(a) for a in node.args)
        if node.func == "sqrt":
            return f"\\sqrt{{{args}}}"
        if node.func == "abs":
            return f"\\left|{args}\\right|"
        name = f"\\{node.func}" if node.func in _FUNCTIONS else f"\\mathrm{{{node.func}}}"
        return f"{name}\\left({args}\\right)"
    if node.op == "/":
        return f"\\frac{{{to_tex(node.left)}}}{{{to_tex(node.right)}}}"
    if node.op == "^":
        base = to_tex(node.left)
        if isinstance(node.left, (BinOp, Neg)):
            base = f"\\left({base}\\right)"
        return f"{{{base}}}^{{{to_tex(node.right)}}}"
    left, right = to_tex(node.left), to_tex(node.right)
    if node.op == "*":
        left = _grouped(node.left, left)
        right = _grouped(node.right, right)
        return f"{left} \\cdot {right}"
    if node.op == "-" and isinstance(node.right, BinOp) and node.right.op in "+-":
        right = f"\\left({right}\\right)"
    return f"{left} {node.op} {right}"


def _grouped(node, tex: str) -> str:
    return f"\\left({tex}\\right)" if isinstance(node, BinOp) and node.op in "+-" else tex


def _name(name: str) -> str:
    match = re.fullmatch(r"([A-Za-z]+)_?([0-9A-Za-z]*)", name)
    if not match:
        return f"\\mathrm{{{name}}}"
    stem, index = match.groups()
    base = f"\\{stem}" if stem in _GREEK else (stem if len(stem) == 1 else f"\\mathrm{{{stem}}}")
    return f"{base}_{{{index}}}" if index else base
