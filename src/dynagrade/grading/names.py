"""Vocabulary of expressions: spellings of functions, constants, and Unicode letters.

The functions themselves (arguments, values, units) are the table in :mod:`functions`.
"""

from __future__ import annotations

import difflib
import math

from .functions import FUNCTIONS

#: Spellings students use -> canonical function name. ``log`` is the natural logarithm.
FUNCTION_ALIASES: dict[str, str] = {
    "arcsin": "asin", "arccos": "acos", "arctan": "atan", "arctan2": "atan2",
    "log": "ln", "sinus": "sin", "cosinus": "cos", "tg": "tan", "cotan": "cot",
    "cosec": "csc", "lg": "log10",
}

#: Mathematical constants: a declared variable of the same name wins over these.
CONSTANTS: dict[str, float] = {"pi": math.pi, "e": math.e}

#: Functions we recognise but do not offer, with the reason shown to the student.
REFUSED_FUNCTIONS: dict[str, str] = {
    "factorial": "factorials are not supported",
    "gamma": "the gamma function is not supported",
    "eval": "that name is not allowed",
    "exec": "that name is not allowed",
    "lambda": "that name is not allowed",
    "int": "that name is not allowed",
    "float": "that name is not allowed",
    "pow": "write powers with ^ or **",
    "max": "max is not supported",
    "min": "min is not supported",
    "diff": "derivatives are not supported; give the result",
    "integrate": "integrals are not supported; give the result",
}

#: Greek letters (and common variants) -> ASCII names as used in exercise files.
GREEK: dict[str, str] = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "ϵ": "epsilon",
    "ζ": "zeta", "η": "eta", "θ": "theta", "ϑ": "theta", "ι": "iota", "κ": "kappa",
    "λ": "lambda", "μ": "mu", "µ": "mu", "ν": "nu", "ξ": "xi", "π": "pi", "ρ": "rho",
    "σ": "sigma", "ς": "sigma", "τ": "tau", "υ": "upsilon", "φ": "phi", "ϕ": "phi",
    "χ": "chi", "ψ": "psi", "ω": "omega",
    "Γ": "Gamma", "Δ": "Delta", "Θ": "Theta", "Λ": "Lambda", "Ξ": "Xi", "Π": "Pi",
    "Σ": "Sigma", "Φ": "Phi", "Ψ": "Psi", "Ω": "Omega",
}

#: Superscript characters -> their ASCII meaning inside an exponent.
SUPERSCRIPTS: dict[str, str] = {
    "⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5", "⁶": "6", "⁷": "7",
    "⁸": "8", "⁹": "9", "⁻": "-", "⁺": "+",
}

#: Every character read as a minus sign, in a formula and in a number's exponent alike:
#: ASCII ``-``, the minus sign U+2212, and the dashes and hyphens students paste from
#: calculators, PDFs, word processors and phones.
MINUS_SIGNS = "-\u2212\u2010\u2011\u2012\u2013\u2014\ufe63\uff0d"
#: Every character read as a plus sign.
PLUS_SIGNS = "+\ufe62\uff0b"

#: Characters read as operators.
OPERATOR_CHARS: dict[str, str] = {
    **{c: "-" for c in MINUS_SIGNS[1:]}, **{c: "+" for c in PLUS_SIGNS[1:]},
    "×": "*", "·": "*", "⋅": "*", "∙": "*", "•": "*", "∗": "*", "÷": "/", "∕": "/",
    "（": "(", "）": ")",
}


def canonical_function(name: str) -> str | None:
    """The canonical function for a spelling, or None if ``name`` is no function."""
    if name in FUNCTIONS:
        return name
    alias = FUNCTION_ALIASES.get(name)
    if alias in FUNCTIONS:
        return alias
    return None


def suggest(name: str, candidates) -> str | None:
    """The closest candidate to a misspelt name (difflib), or None."""
    pool = sorted(set(candidates))
    lowered = {c.lower(): c for c in pool}
    if name.lower() in lowered:
        return lowered[name.lower()]
    match = difflib.get_close_matches(name, pool, n=1, cutoff=0.6)
    return match[0] if match else None
