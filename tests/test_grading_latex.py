r"""LaTeX answers (grading/latex.py): the subset students paste reads as the same tree as
the plain syntax a reader would type for it, anything else is refused at its command,
and the plain syntax's limits hold.

Each LaTeX answer is compared with the plain formula written by hand for it, so the
test checks the reading, not the translator's own output.
"""

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dynagrade.grading import AnswerError, grade
from dynagrade.grading.latex import translate
from dynagrade.grading.lexer import MAX_LENGTH
from dynagrade.grading.nodes import BinOp, Call, Const, Name, Neg, Num, format_number
from dynagrade.grading.parser import MAX_DEPTH, parse_expression, parse_quantity, parse_vector
from dynagrade.grading.quantity import read_quantity
from dynagrade.grading.readability import readability
from dynagrade.grading.spec import NumericSpec, SymbolicSpec, Variable

VARS = ("v0", "g", "alpha", "k", "m", "omega_n", "zeta", "t", "x", "h", "L", "phidot",
        "F_max", "Deltax", "omega", "phi")


def tree(text, variables=VARS):
    return parse_expression(text, variables)


@pytest.mark.parametrize("latex, plain", [
    # the examples
    (r"\frac{v_0^2}{g}\sin(2\alpha)", "v0^2/g*sin(2*alpha)"),
    (r"\sqrt{\frac{k}{m}}", "sqrt(k/m)"),
    (r"\omega_n\sqrt{1-\zeta^2}", "omega_n*sqrt(1-zeta^2)"),
    (r"e^{-\zeta\omega_n t}", "e^(-zeta*omega_n*t)"),
    (r"\dot{\varphi}", "phidot"),
    # fractions, roots and products
    (r"\frac12 m v_0^2", "(1/2)*m*v0^2"),
    (r"\dfrac{1}{2}k x^2", "(1/2)*k*x^2"),
    (r"\frac{2}{mg}", "2/(m*g)"),
    (r"\frac{v_0}{g}\frac{1}{2}", "(v0/g)*(1/2)"),
    (r"2/\frac{k}{m}", "2/(k/m)"),
    (r"\frac{\frac{k}{m}}{g}", "(k/m)/g"),
    (r"\sqrt[3]{x}", "cbrt(x)"),
    (r"\sqrt[4]{x}", "x^(1/4)"),
    (r"\sqrt[2]{k}", "sqrt(k)"),
    (r"2\pi\sqrt{\frac{m}{k}}", "2*pi*sqrt(m/k)"),
    (r"m \cdot g", "m*g"),
    (r"m \times g \div k", "m*g/k"),
    # braces and brackets
    (r"\left(x+1\right)^{2}", "(x+1)^2"),
    (r"\left (x+1\right )^{2}", "(x+1)^2"),  # TeX allows a space before the bracket
    (r"\left[x+1\right]^{2}", "(x+1)^2"),
    (r"\left|x-h\right|", "abs(x-h)"),
    (r"{v_0}^2", "v0^2"),
    (r"x^{k+1}", "x^(k+1)"),
    (r"\omega_{n}t", "omega_n*t"),
    (r"v_{0}t", "v0*t"),  # the subscript's brace ends the name: v_0 times t
    (r"F_{max}", "F_max"),
    (r"F_{max} \cdot t", "F_max*t"),
    # Greek letters, functions, accents, wrappers, spaces
    (r"\varphi", "phi"),
    (r"\omega t", "omega*t"),
    (r"m\omega", "m*omega"),
    (r"\Delta x", "Deltax"),
    (r"\cos^{-1}\left(\frac{h}{L}\right)", "acos(h/L)"),
    (r"\arccos\left(\frac{h}{L}\right)", "acos(h/L)"),
    (r"\sin^2\alpha", "sin(alpha)^2"),
    (r"m g\sin\alpha", "m*g*sin(alpha)"),
    (r"\exp\left(-\zeta t\right)", "exp(-zeta*t)"),
    (r"\ln{x}", "ln(x)"),
    (r"\mathrm{e}^{x}", "e^x"),
    (r"\operatorname{atan2}(h, L)", "atan2(h, L)"),
    (r"m\,g\;h\!\ x\quad t", "m*g*h*x*t"),
    (r"$\frac{k}{m}$", "k/m"),
    (r"\(\frac{k}{m}\)", "k/m"),
    (r"v_0 = \frac{x}{t}", "x/t"),
])
def test_latex_reads_as_the_plain_formula(latex, plain):
    assert tree(latex) == tree(plain)


def test_time_derivatives_reach_the_variable_printed_with_the_accent():
    """A variable printed \\dot\\varphi_0 (rotating_particle_air) is reached by its
    LaTeX, as the typed forms spell it."""
    spec = SymbolicSpec({"omega0": Variable(2, 20, "rad/s", symbol=r"\dot\varphi_0"),
                         "at": Variable(0.5, 3, "m/s^2", symbol=r"\ddot s")})
    assert grade(spec, "omega0^2", r"\dot\varphi_0^2").correct
    assert grade(spec, "omega0^2", r"\dot{\varphi}_0^{2}").correct
    assert grade(spec, "at*omega0", r"\ddot{s}\,\dot\varphi_0").correct


@pytest.mark.parametrize("text, fragment, position", [
    (r"\int x", r"'\int' is not LaTeX the grader reads", 0),
    (r"x \to 1", r"'\to'", 2),
    (r"\alpah", r"did you mean '\alpha'?", 0),
    (r"m\vec{v}", r"'\vec'", 1),
    (r"\frac{1}{2", "missing '}'", 8),
    (r"\alpha}", "no matching '{'", 6),
    (r"\dot{a+h}", r"'\dot' takes one name", 0),
    (r"x_{a+h}", "a subscript holds letters and digits only", 1),
    (r"\left< x \right>", r"need a bracket after them", 0),
    (r"\frac{1}", r"'\frac' needs an argument", 0),
    (r"\sqrt[3{x}", "missing ']'", 5),
    ("x\\", "a backslash must start a LaTeX command", 1),
    # errors of the plain reading point into the LaTeX as typed
    (r"\frac{k}{m} + )", "unexpected ')'", 14),
    (r"\sqrt{\frac{k}{q}}", "unknown name 'q'", 15),
    (r"\frac{k}{}", "empty brackets", 9),
    (r"\frac{k+}{m}", "unexpected ')'", 7),  # under the numerator's last character
])
def test_latex_outside_the_subset_is_refused_at_its_command(text, fragment, position):
    with pytest.raises(AnswerError) as info:
        tree(text)
    assert fragment in info.value.message
    assert info.value.position == position


def test_latex_keeps_the_limits_of_the_plain_syntax():
    deep = r"\," + "{" * (MAX_DEPTH + 10) + "x" + "}" * (MAX_DEPTH + 10)
    with pytest.raises(AnswerError, match="nested too deeply"):
        tree(deep)
    with pytest.raises(AnswerError, match="too long"):
        tree(r"\frac{x}{k}+" * (MAX_LENGTH // 12 + 1))
    nested = r"\sqrt{" * 400 + "x" + "}" * 400  # 2801 characters
    with pytest.raises(AnswerError, match="too long"):
        tree(nested)


def test_a_formula_in_more_wrappers_than_the_limit_is_refused_and_at_the_limit_is_read():
    """Each \\mathrm{...} is a group one level deeper, like a brace: ``x`` inside MAX_DEPTH
    of them is read; inside one more it is refused, at the innermost group's content
    (101 wrappers of 8 characters, ``\\mathrm{``: position 808; of 6, ``\\text{``: 606)."""
    assert MAX_DEPTH == 100  # the positions are worked out for it
    for wrapper, innermost in ((r"\mathrm{", 808), (r"\text{", 606)):
        assert tree(wrapper * MAX_DEPTH + "x" + "}" * MAX_DEPTH) == Name("x")
        with pytest.raises(AnswerError, match="nested too deeply") as info:
            tree(wrapper * (MAX_DEPTH + 1) + "x" + "}" * (MAX_DEPTH + 1))
        assert info.value.position == innermost


def test_a_braced_subscript_keeps_a_declared_printed_spelling():
    """``v_{02}`` and ``v_{2}(0)`` were read as the printed spellings of v02 before the
    LaTeX reader; they still are."""
    spellings = {"v_{02}": "v02", "v_02": "v02", "v_{2}(0)": "v02", "v_2(0)": "v02"}
    for written in ("v_{02}", "v_{2}(0)", "2 v_{2}(0)"):
        assert Name("v02") in _leaves(parse_expression(written, ("v02",), spellings)), written


def _leaves(node):
    if isinstance(node, BinOp):
        return _leaves(node.left) + _leaves(node.right)
    return [node]


def test_units_in_latex_are_read_as_units():
    assert read_quantity(r"3.2\,\mathrm{m/s}").value == pytest.approx(3.2)
    assert read_quantity(r"3.2\text{ m/s}").value == pytest.approx(3.2)
    assert read_quantity(r"45\,\mathrm{km/h}").value == pytest.approx(12.5)  # 45000 m / 3600 s
    assert read_quantity(r"5\,\mu\mathrm{m}").value == pytest.approx(5e-6)
    assert read_quantity(r"\frac{1}{2}\,\mathrm{kg}").value == pytest.approx(0.5)
    assert parse_quantity(r"9.81\ \mathrm{m/s^2}") == parse_quantity("9.81 m/s^2")
    components, unit = parse_vector(r"\left(1, \frac{1}{2}\right)\,\mathrm{m}")
    assert components == [Num(1.0), BinOp("/", Num(1.0), Num(2.0))] and unit == parse_quantity("m")


def test_the_preview_shows_latex_in_the_plain_syntax():
    numeric = readability(NumericSpec(unit="m/s"), r"45\,\mathrm{km/h}")
    assert numeric.readable and numeric.message == "reads as 45 km/h = 12.5 m/s"
    spec = SymbolicSpec({"k": Variable(1, 2, "N/m"), "m": Variable(1, 2, "kg")})
    formula = readability(spec, r"\sqrt{\frac{k}{m}}")
    assert formula.readable and formula.message == "reads as sqrt(k / m)"
    refused = readability(spec, r"\sqrt{\frac{k}{m}}\int")
    assert not refused.readable and "'\\int'" in refused.message and "^" in refused.message


def test_the_translation_remembers_where_each_character_came_from():
    plain, origin, closers = translate(r"\frac{k}{m}+\alpha")
    assert plain == " (k/m)+ α" and origin == [0, 0, 6, 0, 9, 10, 11, 12, 12]
    assert closers == {10}


def test_no_note_on_a_written_product_after_a_printed_fraction():
    """"a/2g is read as (a/2)·g" is for a division written without brackets; a \\frac is
    printed with its own, so \\frac{1}{2}mv^2 gets no such note."""
    assert "a/2g" not in grade(PROJECTILE, "v0^2*sin(2*alpha)/g",
                               r"\frac{v_0^2}{2g}\sin(2\alpha)").feedback
    assert "a/2g" in grade(PROJECTILE, "v0^2*sin(2*alpha)/g", "v0^2/2g sin(2α)").feedback


PROJECTILE = SymbolicSpec({"v0": Variable(1, 50, "m/s"), "alpha": Variable(0.1, 1.4, "rad"),
                           "g": Variable(9, 10, "m/s^2")})


def test_a_latex_formula_is_graded_like_its_plain_form():
    """The range of a projectile, R = v0² sin(2α)/g: the LaTeX is right, and the same
    LaTeX with a physics mistake (half the range, or sin α for sin 2α) is wrong."""
    right = r"\frac{v_0^2}{g}\sin(2\alpha)"
    assert grade(PROJECTILE, "v0^2*sin(2*alpha)/g", right).correct
    assert not grade(PROJECTILE, "v0^2*sin(2*alpha)/g", r"\frac{v_0^2}{2g}\sin(2\alpha)").correct
    assert not grade(PROJECTILE, "v0^2*sin(2*alpha)/g", r"\frac{v_0^2}{g}\sin\alpha").correct


_PIECES = [r"\frac", r"\sqrt", "[", "]", "{", "}", r"\left", r"\right", "(", ")", "|",
           r"\alpha", r"\dot", "x", "_", "^", "2", "-", r"\,", "$", r"\mathrm", r"\sin",
           " ", "\\", r"\{", r"\}", r"\Delta", r"\mu", "m", "/", r"\cdot", "²", ","]


@settings(max_examples=500, deadline=None)
@given(st.lists(st.sampled_from(_PIECES), max_size=14).map("".join))
def test_any_text_of_latex_pieces_is_read_or_refused_with_a_message(text):
    for read in (lambda t: parse_expression(t, ("x", "alpha", "m", "xdot")), parse_quantity,
                 parse_vector):
        try:
            read(text)
        except AnswerError as error:
            assert error.message and (error.position is None or 0 <= error.position <= len(text))


# -- the round trip ------------------------------------------------------------------------
#: How the renderer below writes each declared name in LaTeX.
_NAMES = {"x": ["x"], "alpha": [r"\alpha"], "omega_n": [r"\omega_{n}", r"\omega_n"],
          "v0": ["v_{0}", "v_0"], "phidot": [r"\dot{\varphi}", r"\dot\varphi"], "zeta": [r"\zeta"]}
_FUNCTIONS = {"sin": r"\sin", "cos": r"\cos", "tan": r"\tan", "exp": r"\exp", "ln": r"\ln",
              "sinh": r"\sinh", "asin": r"\arcsin", "atan": r"\arctan"}
_PRECEDENCE = {"+": 1, "-": 1, "*": 2, "/": 2, "^": 4}


def _leaf():
    return st.one_of(
        st.sampled_from([0, 1, 2, 3, 0.5, 2.25, 10, 981]).map(lambda v: Num(float(v))),
        st.sampled_from(sorted(_NAMES)).map(Name),
        st.sampled_from(["pi", "e"]).map(Const))


def _trees():
    def extend(children):
        return st.one_of(
            children.map(Neg),
            st.tuples(st.sampled_from("+-*/^"), children, children).map(lambda t: BinOp(*t)),
            st.tuples(st.sampled_from(sorted(_FUNCTIONS) + ["sqrt", "cbrt", "abs"]),
                      children).map(lambda t: Call(t[0], (t[1],))))
    return st.recursive(_leaf(), extend, max_leaves=12)


def _precedence(node):
    if isinstance(node, BinOp):
        return _PRECEDENCE[node.op]
    return 3 if isinstance(node, Neg) else 5


def _render(node, draw):
    """A LaTeX rendering of a tree, choosing among equivalent spellings with ``draw``."""
    if isinstance(node, Num):
        return format_number(node.value)
    if isinstance(node, Name):
        return draw(st.sampled_from(_NAMES[node.id]))
    if isinstance(node, Const):
        return r"\pi" if node.id == "pi" else draw(st.sampled_from(["e", r"\mathrm{e}"]))
    if isinstance(node, Neg):
        inner = _render(node.operand, draw)
        return "-" + (rf"\left({inner}\right)" if _precedence(node.operand) < 3 else inner)
    if isinstance(node, Call):
        inner = _render(node.args[0], draw)
        if node.func == "sqrt":
            return rf"\sqrt{{{inner}}}"
        if node.func == "cbrt":
            return rf"\sqrt[3]{{{inner}}}"
        if node.func == "abs":
            return rf"\left|{inner}\right|"
        bracket = draw(st.sampled_from([r"\left({}\right)", "({})", "{{{}}}"]))
        return _FUNCTIONS[node.func] + bracket.format(inner)
    left, right = _render(node.left, draw), _render(node.right, draw)
    if node.op == "/":
        return rf"\frac{{{left}}}{{{right}}}"
    if node.op == "^":
        if _precedence(node.left) <= 4:
            left = rf"\left({left}\right)"
        return f"{{{left}}}^{{{right}}}" if draw(st.booleans()) else f"{left}^{{{right}}}"
    p = _PRECEDENCE[node.op]
    if _precedence(node.left) < p:
        left = rf"\left({left}\right)"
    if _precedence(node.right) <= p and not (isinstance(node.right, Neg) and p == 1):
        right = rf"\left({right}\right)"
    if node.op == "*":
        glued = right[0].isalpha() or right.startswith(("\\", "{"))
        operator = draw(st.sampled_from([r"\cdot", r"\times", ""] if glued else [r"\cdot", r"\times"]))
        return f"{left} {operator} {right}"
    return f"{left} {node.op} {right}"


@settings(max_examples=300, deadline=None)
@given(_trees(), st.data())
def test_a_latex_rendering_of_a_random_expression_tree_reads_back_to_the_same_tree(node, data):
    rendered = _render(node, data.draw)
    assert parse_expression(rendered, tuple(_NAMES)) == node, rendered
