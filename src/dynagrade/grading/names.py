"""Vocabulary of expressions: spellings of functions, constants, and Unicode letters.

The functions themselves (arguments, values, units) are the table in :mod:`functions`.
"""

from __future__ import annotations

from ..i18n import N_
import difflib
import re
import math

from .errors import SpecError
from .functions import FUNCTIONS

#: Spellings students use -> canonical function name. ``log`` is the natural logarithm.
FUNCTION_ALIASES: dict[str, str] = {
    "arcsin": "asin", "arccos": "acos", "arctan": "atan", "arctan2": "atan2",
    "log": "ln", "sinus": "sin", "cosinus": "cos", "tg": "tan", "cotan": "cot",
    "cosec": "csc", "lg": "log10",
}

#: Mathematical constants: a declared variable of the same name wins over these.
CONSTANTS: dict[str, float] = {"pi": math.pi, "e": math.e}

#: Functions we recognise but do not offer, with the reason shown to the student (marked for
#: the catalogs, translated where shown).
REFUSED_FUNCTIONS: dict[str, str] = {
    "factorial": N_("factorials are not supported"),
    "gamma": N_("the gamma function is not supported"),
    "eval": N_("that name is not allowed"),
    "exec": N_("that name is not allowed"),
    "lambda": N_("that name is not allowed"),
    "int": N_("that name is not allowed"),
    "float": N_("that name is not allowed"),
    "pow": N_("write powers with ^ or **"),
    "max": N_("max is not supported"),
    "min": N_("min is not supported"),
    "diff": N_("derivatives are not supported; give the result"),
    "integrate": N_("integrals are not supported; give the result"),
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


# -- the names a formula's variables may be typed under ---------------------------------

#: Unicode subscript digits -> ASCII digits: ``x₁`` is typed for ``x_1``.
SUBSCRIPTS: dict[str, str] = {chr(0x2080 + k): str(k) for k in range(10)}

#: LaTeX spellings of Greek letters that the course prints but students type plainly.
LATEX_VARIANTS = {"varphi": "phi", "vartheta": "theta", "varepsilon": "epsilon",
                  "varrho": "rho", "varsigma": "sigma", "varpi": "pi"}
#: LaTeX accents, each typed as a word after the letter: ``\dot\varphi`` is ``phidot``.
ACCENTS = ("ddot", "dot", "hat", "bar", "tilde")
_ACCENT = re.compile(r"\\(" + "|".join(ACCENTS) + r")\s*(\{[^{}]*\}|\\[A-Za-z]+|[A-Za-z])")
_WRAPPERS = re.compile(r"\\(?:mathrm|text|mathit|operatorname|boldsymbol|mathbf)\s*\{([^{}]*)\}")
_COMMAND = re.compile(r"\\([A-Za-z]+)")
_SPACING = re.compile(r"\\[,;!: ]|\s+")
_PLAIN = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_SPELLED_GREEK = {spelled: letter for letter, spelled in GREEK.items()
                  if letter not in "ϵϑςϕµ"}
_SUBSCRIPT_RUN = re.compile(r"_(\d+)")
#: combining marks for the accents: ``\dot x`` prints as ẋ
_COMBINING = {"ddot": "\u0308", "dot": "\u0307", "hat": "\u0302", "bar": "\u0304", "tilde": "\u0303"}


class NameClash(SpecError):
    """Two variables, or a variable and a function or unit, share a spelling (an
    authoring error, found when the part's specification is built)."""


def _greek_command(match: re.Match) -> str:
    word = match.group(1)
    return LATEX_VARIANTS.get(word, word)


def typed_forms(symbol: str) -> list[str]:
    """The spellings a student may type for a printed (LaTeX) symbol, most literal first.

    ``\\lambda`` -> ``lambda``; ``\\Omega_E`` -> ``Omega_E``, ``OmegaE``; ``v_{02}`` ->
    ``v_{02}``, ``v_02``, ``v02``; ``v_{2}(0)`` -> ``v_{2}(0)``, ``v_2(0)``, ``v2(0)``,
    ``v₂(0)``; ``\\dot\\varphi`` -> ``phidot``; ``\\Delta x`` -> ``Deltax``. Greek letters
    and subscript digits typed in Unicode (``λ``, ``ω₀``) reach the parser spelled out
    (``lambda``, ``omega_0``), so plain spellings need no Unicode form; the others get
    theirs here (``v₂(0)``).
    """
    text = _WRAPPERS.sub(r"\1", symbol.strip())
    text = _ACCENT.sub(lambda m: _COMMAND.sub(_greek_command, m.group(2).strip("{}"))
                       + m.group(1), text)
    text = _COMMAND.sub(_greek_command, text)
    text = _SPACING.sub("", text)
    forms = [symbol.strip()] if "\\" not in symbol and " " not in symbol.strip() else []
    flat = text.replace("{", "").replace("}", "")
    forms += [text, flat, flat.replace("_", "")]
    if not _PLAIN.fullmatch(flat):
        forms.append(_unicode_form(flat))
    unique = []
    for form in forms:
        if form and form not in unique:
            unique.append(form)
    return unique


def _unicode_form(text: str) -> str:
    """``v_2(0)`` -> ``v₂(0)``, ``omega(0)`` -> ``ω(0)``: a spelling as pasted from print."""
    text = _subscript_digits(text)
    for spelled in sorted(_SPELLED_GREEK, key=len, reverse=True):
        text = re.sub(rf"(?<![A-Za-z]){spelled}(?![a-z])", _SPELLED_GREEK[spelled], text)
    return text


def printed_form(symbol: str) -> str:
    """A printed (LaTeX) symbol as plain text with Greek letters, accents and subscript
    digits: ``\\lambda`` -> ``λ``, ``I_0`` -> ``I₀``, ``v_{2}(0)`` -> ``v₂(0)``,
    ``\\Delta x`` -> ``Δx``, ``\\dot\\varphi_0`` -> ``φ̇₀``."""
    text = _WRAPPERS.sub(r"\1", symbol.strip())
    text = _ACCENT.sub(lambda m: m.group(2).strip("{}") + _COMBINING[m.group(1)], text)
    text = _COMMAND.sub(lambda m: _SPELLED_GREEK.get(_greek_command(m), m.group(1)), text)
    text = _SPACING.sub("", text).replace("{", "").replace("}", "")
    return _subscript_digits(text)


def _subscript_digits(text: str) -> str:
    """``x_12`` -> ``x₁₂``: every ``_`` followed by digits, as subscript digits."""
    return _SUBSCRIPT_RUN.sub(lambda m: "".join(chr(0x2080 + int(d)) for d in m.group(1)), text)


def is_plain(spelling: str) -> bool:
    """Whether a spelling is one name token (the parser's lookup resolves it) rather than
    a run of characters the tokenizer must recognise whole (``v_{02}``, ``v_2(0)``)."""
    return _PLAIN.fullmatch(spelling) is not None


def spellings_of(name: str, symbol: str | None, aliases=()) -> dict[str, bool]:
    """Every spelling of a variable other than its name, each with whether the author
    declared it (an alias and its typed forms) or it was derived from the printed symbol
    (:func:`typed_forms`)."""
    forms: dict[str, bool] = {}
    for alias in aliases:
        for form in typed_forms(alias):
            forms.setdefault(form, True)
    for form in typed_forms(symbol) if symbol else []:
        forms.setdefault(form, False)
    forms.pop(name, None)
    return forms


def alias_table(variables, units=()) -> dict[str, str]:
    """Spelling -> variable name for every variable of a formula part.

    ``variables`` maps names to objects with ``symbol`` and ``aliases``. A declared alias
    that is another variable's name or spelling, a function's name or one of ``units``
    raises :class:`NameClash`; a spelling derived from a printed symbol that would clash
    with a variable or a function is left out (the variable or the function keeps it),
    and one two variables' symbols share is left out for both.
    """
    table: dict[str, str] = {}
    shared: set[str] = set()
    declared_by_author: set[str] = set()
    for name, variable in variables.items():
        for spelling, declared in spellings_of(name, getattr(variable, "symbol", None),
                                               getattr(variable, "aliases", ())).items():
            lookup = spelling.replace("{", "").replace("}", "")
            clash = _clash(spelling, lookup, name, variables, table, units if declared else ())
            if clash and declared:
                raise NameClash(f"the alias {spelling!r} of {name!r} {clash}")
            if clash:
                if table.get(spelling, name) != name and spelling not in declared_by_author:
                    shared.add(spelling)
                continue
            table[spelling] = name
            if declared:
                declared_by_author.add(spelling)
    return {spelling: name for spelling, name in table.items() if spelling not in shared}


def _clash(spelling: str, lookup: str, name: str, variables, table: dict, units) -> str:
    """What ``spelling`` of ``name`` collides with, in words; empty when nothing."""
    if spelling in variables or lookup in variables:
        return f"is the variable {(lookup if lookup in variables else spelling)!r}"
    if table.get(spelling, name) != name:
        return f"is also a spelling of {table[spelling]!r}"
    if canonical_function(lookup):
        return f"is the function {lookup!r}"
    if lookup in units:
        return f"is the unit {lookup!r}"
    return ""
