"""Answer parts of an exercise: what is asked, in which unit, for how many points.

A part kind (:class:`Numeric`, :class:`Vector`, :class:`Symbolic`, :class:`Options`) owns
everything that differs between kinds. Its class is the kind, registered by defining it
(:mod:`.kinds`): it names its grading kind (``grading``: spec, grade, accepts, read and
compare builder, :mod:`dynagrade.grading.kinds`) and its Moodle form (``moodle``), and
implements the small contract of :class:`Part`:

- ``reference`` / ``in_part_unit``: the solver's SI answer in the part's own unit;
- ``spec``: the grader's specification (:mod:`dynagrade.grading.spec`);
- ``describe(points)``: the part's line in a fill-in file, with the points as the exam
  scales them; ``input_hint`` / ``input_options``: what an answer box shows;
- ``answer_text`` / ``shown_answer``: a reference answer as a student would type it
  and as a person reads it (the one answer formatter, :func:`.numbers.answer_text`);
- ``near_misses`` / ``misconception_answer`` / ``cross_check``: what ``dynagrade
  verify`` tries against a variant; ``own_checks_key``: what the first two depend on,
  where that is less than the whole variant (an exam remembers their outcome under it);
- ``manifest_fields``: the settings the exam manifest stores; ``follows_through``;
- ``check_names``: refuses, when the exercise is built, names an answer could not use
  (an alias of a formula's variable that is another name, a number naming two options).

No other module asks which kind a part is; code that needs a new behaviour per kind adds
a method here. Reference answers arrive from the solver in SI; a part converts them into
its own unit, which is also the unit a bare number is read in.
"""

from __future__ import annotations

from ..i18n import _
import textwrap
from abc import ABC, abstractmethod
from dataclasses import dataclass, field, replace
from typing import Any, Callable, ClassVar, Mapping, Sequence

from ..grading.kinds import GRADING_KINDS
from ..grading.spec import (
    ChoiceSpec,
    KnownWrong,
    NumericSpec,
    SymbolicSpec,
    Variable,
    VectorSpec,
)
from ..errors import DefinitionError
from ..grading.names import printed_form
from ..grading.tolerance import DEFAULT_RTOL, is_close, round_sig
from .kinds import PART_KINDS, MoodleForm, NotExported, register_part_kind
from .numbers import answer_text, format_number, points_phrase
from .params import ParamValues
from .units import conversion_factor, from_si, to_si, with_unit

#: how far off a near miss is: an answer 5 % too large must fail its part
PERTURBATION = 0.05
#: how closely a formula must reproduce the mechanics core's number (``Symbolic.equals``)
CROSS_CHECK_RTOL = 1e-6

__all__ = ["Misconception", "Numeric", "Vector", "Symbolic", "Options", "Variable", "Part",
           "PART_KINDS"]


@dataclass(frozen=True)
class Misconception:
    """A known wrong answer and the feedback it earns.

    ``value`` is a function of the parameters (in SI) returning the wrong answer in SI for
    numeric and vector parts, or an expression string for symbolic parts. ``applies``, a
    predicate of the parameters (in SI), limits the misconception to the regime where it
    is a mistake at all (e.g. "the block slides" only while ``mu < tan(alpha)``):
    elsewhere it is neither tried on an answer nor able to make a variant be redrawn.
    """

    name: str
    value: Callable[[ParamValues], Any] | str
    feedback: str
    score: float = 0.0
    applies: Callable[[ParamValues], bool] | None = None

    def applies_to(self, params: ParamValues) -> bool:
        """Whether this misconception is tried in the variant with ``params``."""
        return self.applies is None or bool(self.applies(params))

    def wrong_value(self, params: ParamValues) -> Any:
        """The wrong answer (SI) in the variant with ``params``: a numeric or vector
        part's misconception is a function of the parameters."""
        if isinstance(self.value, str):
            raise DefinitionError(f"misconception {self.name!r}: a number's or vector's "
                                  "misconception is a function of the parameters, not "
                                  f"the formula {self.value!r}")
        return self.value(params)

    @property
    def formula(self) -> str:
        """The wrong formula: a symbolic part's misconception is an expression."""
        if not isinstance(self.value, str):
            raise DefinitionError(f"misconception {self.name!r}: a formula's misconception "
                                  "is an expression string, not a function")
        return self.value


@dataclass(frozen=True)
class Part(ABC):
    """What every part has: a name (the variable on the student's sheet), a label, points,
    and the number of the statement's question it answers (``question=2``; None only when
    the statement numbers no questions).

    ``constant_answer`` is the reason, in a sentence, why the answer is the same in every
    variant where that is the physics taught ("beta_1 L = 1.8751 is the first root of
    cos(x) cosh(x) = -1 for every clamped-free beam"); ``dynagrade verify`` then does not
    ask it to vary
    (:mod:`.variety`). Without it, an answer that scores in almost every variant fails."""

    name: str
    label: str = ""
    points: float = 1.0
    misconceptions: tuple[Misconception, ...] = ()
    question: int | None = None
    constant_answer: str | None = None

    kind = "part"
    #: the settings the exam manifest stores for parts of this kind (attribute names)
    manifest_fields: ClassVar[tuple[str, ...]] = ()
    #: whether the reference answer follows the parameters (a formula is one for all)
    answer_varies: ClassVar[bool] = True
    #: the grader's half of the kind (every concrete kind sets its own, :mod:`.kinds`)
    grading: ClassVar[object] = None
    #: how the kind goes into Moodle (a :class:`MoodleForm`, or :class:`NotExported`)
    moodle: ClassVar[MoodleForm | NotExported | None] = None
    #: whether answers of this kind are numbers that a class's answers can be compared by
    #: (:mod:`dynagrade.classgrade.answer_values`: copies, discovered misconceptions)
    compares_numbers: ClassVar[bool] = False

    def __init_subclass__(cls, **kwargs):
        """A class that declares its own ``kind`` is a part kind: checked and registered
        now (:func:`.kinds.register_part_kind`), so a kind without a grading kind or a
        Moodle form cannot exist."""
        super().__init_subclass__(**kwargs)
        if "kind" in cls.__dict__:
            register_part_kind(cls)

    @classmethod
    def answer_number(cls, entry: Any, text: str) -> float | tuple[float, ...] | None:
        """The number (or components) an answer gives in the part's unit, read by the
        grader (never evaluated); ``entry`` is the manifest's part entry (its ``unit``,
        ``rtol``, ``atol``, ``size``). None: unreadable, or not a kind of numbers."""
        return None

    @classmethod
    def key_number(cls, key: Any) -> float | tuple[float, ...] | None:
        """The manifest's reference answer as a number (or components); None: not one."""
        return None

    def __post_init__(self):
        if not self.name.isidentifier():
            raise ValueError(f"part name {self.name!r} is not an identifier")
        if self.points < 0:
            raise ValueError(f"part {self.name!r}: points must not be negative")
        if self.question is not None and (isinstance(self.question, bool) or
                                          not isinstance(self.question, int) or
                                          self.question < 1):
            raise DefinitionError(f"part {self.name!r}: question must be a whole number "
                                  f"from 1, got {self.question!r}")
        if self.constant_answer is not None and (not isinstance(self.constant_answer, str)
                                                 or not self.constant_answer.strip()):
            raise DefinitionError(f"part {self.name!r}: constant_answer= gives the reason "
                                  "the answer is the same in every variant, as a sentence")

    def reference(self, solved: Mapping[str, Any]) -> Any:
        """This part's reference answer, in the part's unit, from the solver's SI output."""
        try:
            return self.in_part_unit(solved[self.name])
        except KeyError:
            raise DefinitionError(f"the solver returned no answer for part {self.name!r}; "
                                  f"it returned {sorted(solved)}") from None

    def spec(self, params: ParamValues):
        """The grader's specification for this part in the variant with ``params``."""
        raise TypeError(f"{type(self).__name__} has no grading specification")

    def in_part_unit(self, value):
        """A value the solver gives in SI, as this part states and grades it."""
        return value

    def misconceptions_for(self, params: ParamValues) -> tuple[Misconception, ...]:
        """The declared misconceptions that apply in the variant with ``params``."""
        return tuple(m for m in self.misconceptions if m.applies_to(params))

    def _known_wrong(self, params: ParamValues) -> tuple[KnownWrong, ...]:
        return tuple(
            KnownWrong(m.name, self.in_part_unit(m.wrong_value(params)), m.feedback, m.score)
            for m in self.misconceptions_for(params)
        )

    @property
    def unit(self) -> str | None:
        return None

    @property
    def follows_through(self) -> bool:
        """Whether a wrong answer may be graded again against the student's own earlier
        answers (:mod:`.scoring`)."""
        return False

    def spellings(self) -> Mapping[str, str]:
        """Each spelling an answer may use for a variable of the part's formula, to the
        variable's name (none: the answer is no formula)."""
        return {}

    def variable_names(self) -> tuple[str, ...]:
        """The variables of the part's formula (none: the answer is no formula)."""
        return ()

    def with_variables(self, variables: Mapping[str, Variable]) -> Part:
        """The part with its formula's ``variables`` completed (:mod:`.model`); only a
        part whose answer is a formula has them."""
        raise TypeError(f"{type(self).__name__} {self.name!r} has no variables")

    def follow_through_uses(self) -> tuple[str, ...]:
        """The earlier parts a follow-through reference is computed from (none here)."""
        return ()

    def followed_reference(self, params: ParamValues, earlier: Mapping[str, float]) -> Any:
        """The reference recomputed, in the part's unit, from the student's ``earlier``
        answers (SI, by the names of :meth:`follow_through_uses`); only a part that
        :attr:`follows_through` has one."""
        raise TypeError(f"{type(self).__name__} {self.name!r} does not follow through")

    @abstractmethod
    def asks(self) -> str:
        """What the answer is, in words (``a number in m/s``); every kind says its own."""

    def describe(self, points: float) -> str:
        """The part's line in a fill-in file; ``points`` as the exam scales them (the
        part's own points outside an exam)."""
        asked = f"question {self.question}, " if self.question is not None else ""
        return shortened(f"{asked}{self.label or self.name}: {self.asks()} "
                         f"({points_phrase(points)})", 240)

    def input_hint(self) -> str:
        """What the answer looks like, for a sheet's part line or an input's placeholder."""
        return ""

    def check_names(self) -> None:
        """Raise ``ValueError`` when the names an answer may use clash (an alias that is
        another variable, a function or a unit; a number naming two options)."""

    def input_options(self) -> tuple[str, ...]:
        """The values an answer box offers to pick from (none: free text)."""
        return ()

    def answer_text(self, value, digits: int = 12) -> str:
        """A reference answer written as a student would write it."""
        return answer_text(value, digits)

    def shown_answer(self, value, digits: int = 6) -> str:
        """A reference answer with its unit, as a person reads it."""
        return with_unit(answer_text(value, digits), self.unit)

    def near_misses(self, expected) -> list[tuple[str, str]]:
        """Answers close to ``expected`` that must be wrong, each with what it is."""
        return []

    def misconception_answer(self, misconception: Misconception, params: ParamValues) -> str:
        """The answer a declared misconception gives in the variant with ``params``."""
        return self.answer_text(self.in_part_unit(misconception.wrong_value(params)))

    def cross_check(self, params: ParamValues, answers: Mapping[str, Any],
                    part: Callable[[str], Part]) -> list[str]:
        """Disagreements with the variant's other answers (``part(name)`` looks one up)."""
        return []

    def own_checks_key(self, params: ParamValues, expected) -> tuple | None:
        """Everything the part's own checks in the variant with ``params`` and reference
        ``expected`` depend on besides the part itself: the reference graded against its
        own spec, its near misses and its misconceptions
        (:func:`dynagrade.exercise.verify.part_own_problems`). Their outcome may be
        remembered under this key (with the exercise's identity and the part's name).
        None, as here, when they depend on the whole variant: nothing is remembered."""
        return None

    def scores(self, answer, expected) -> bool:
        """Whether ``answer``, a reference of this part (in its unit), scores against the
        reference ``expected``: the part's tolerance applied to numbers, not to text
        (:mod:`.variety` asks it for many pairs). Here: the two are equal."""
        return answer == expected

    def one_answer(self, references: Sequence) -> tuple[Any, int]:
        """The reference among ``references`` (one per variant) that scores against the
        most of them, and against how many: what one student's answer would earn across
        a class (:mod:`.variety`)."""
        distinct: list = []
        for reference in references:
            if reference not in distinct:
                distinct.append(reference)
        counts = [sum(self.scores(c, r) for r in references) for c in distinct]
        best = max(range(len(distinct)), key=counts.__getitem__)
        return distinct[best], counts[best]

    def typed_as(self, value: float, unit: str | None) -> float | None:
        """The number this part reads when a student types ``value``, a quantity worked
        out in ``unit``, with that unit: converted where the units are of one dimension
        (both pure numbers included), None where they are not or the part takes no
        number (:func:`.variety.coincidences`)."""
        return None

    def typed_bare(self, value: float) -> float | None:
        """The number this part reads when a student types ``value`` bare: ``value``
        where the part reads a bare number in its unit, None where it does not."""
        return None


@dataclass(frozen=True)
class Numeric(Part):
    """A number with a unit, correct within ``max(atol, rtol*|expected|)``.

    ``follow_through(p, answers)`` recomputes the reference (in SI) from the student's
    earlier answers (``answers[name]`` in SI), so a part is not lost for an error made
    before it. ``require_unit`` makes a bare number wrong; ``unit_credit`` (0..1) is the
    share of the points that the unit alone earns (docs/grading.md).
    """

    unit: str | None = None
    rtol: float = DEFAULT_RTOL
    atol: float | None = None
    sigfigs: int | None = None
    follow_through: Callable[[ParamValues, Mapping[str, float]], float] | None = None
    uses: tuple[str, ...] = ()
    require_unit: bool = False
    unit_credit: float | None = None

    kind = "numeric"
    grading = GRADING_KINDS["numeric"]
    moodle = MoodleForm.NUMBER
    manifest_fields = ("rtol", "atol")
    compares_numbers = True

    @classmethod
    def answer_number(cls, entry, text):
        from ..grading.errors import AnswerError
        from ..grading.reading import read_number

        try:
            return read_number(text, entry.unit)
        except (AnswerError, ValueError):
            return None

    @classmethod
    def key_number(cls, key):
        try:
            return float(key)
        except (TypeError, ValueError):
            return None

    def in_part_unit(self, value):
        return from_si(float(value), self.unit)

    @property
    def follows_through(self) -> bool:
        return self.follow_through is not None

    def follow_through_uses(self) -> tuple[str, ...]:
        return self.uses

    def followed_reference(self, params: ParamValues, earlier: Mapping[str, float]) -> Any:
        if self.follow_through is None:
            return super().followed_reference(params, earlier)
        return from_si(self.follow_through(params, earlier), self.unit)

    def asks(self) -> str:
        return f"a number in {self.unit}" if self.unit else "a number"

    def near_misses(self, expected):
        if expected == 0:
            return []
        return [(self.answer_text(expected * (1 + PERTURBATION)), "an answer 5 % too large")]

    def scores(self, answer, expected) -> bool:
        if self.sigfigs is not None:
            return round_sig(float(answer), self.sigfigs) == round_sig(float(expected),
                                                                       self.sigfigs)
        return bool(is_close(float(answer), float(expected), self.rtol, self.atol))

    def one_answer(self, references):
        """:meth:`Part.one_answer` for numbers, all pairs at once (numpy)."""
        if self.sigfigs is not None:
            return super().one_answer(references)
        import numpy as np

        values = np.asarray(references, dtype=np.float64)
        counts = is_close(values[:, None], values[None, :], self.rtol, self.atol).sum(axis=1)
        best = int(np.argmax(counts))
        return float(values[best]), int(counts[best])

    def typed_as(self, value, unit):
        factor = conversion_factor(unit, self.unit)
        return None if factor is None else value * factor

    def typed_bare(self, value):
        return None if self.require_unit else value

    def spec(self, params):
        return NumericSpec(unit=self.unit, rtol=self.rtol, atol=self.atol,
                           sigfigs=self.sigfigs, misconceptions=self._known_wrong(params),
                           require_unit=self.require_unit, unit_credit=self.unit_credit)


@dataclass(frozen=True)
class Vector(Part):
    """A vector of ``size`` components in one unit, graded component by component.

    ``basis`` names the components' basis vectors when they are not the Cartesian e1,
    e2, e3 (``("e_r", "e_phi")``, ``("e_t", "e_n")``): the answer may then be written
    ``3 e_r + 2 e_φ`` (:class:`~dynagrade.grading.spec.VectorSpec`)."""

    unit: str | None = None
    size: int = 2
    rtol: float = DEFAULT_RTOL
    atol: float | None = None
    basis: tuple[str, ...] = ()

    kind = "vector"
    grading = GRADING_KINDS["vector"]
    moodle = MoodleForm.COMPONENTS
    manifest_fields = ("rtol", "atol", "size")
    compares_numbers = True

    @classmethod
    def answer_number(cls, entry, text):
        from ..grading.vector import answer_components

        spec = VectorSpec(size=entry.size or 2, unit=entry.unit,
                          rtol=DEFAULT_RTOL if entry.rtol is None else entry.rtol,
                          atol=entry.atol)
        values = answer_components(spec, text)
        return None if values is None else tuple(float(v) for v in values)

    @classmethod
    def key_number(cls, key):
        try:
            return tuple(float(v) for v in key)
        except (TypeError, ValueError):
            return None

    def in_part_unit(self, value):
        values = tuple(from_si(float(v), self.unit) for v in value)
        if len(values) != self.size:
            raise ValueError(f"part {self.name!r} expects {self.size} components, "
                             f"the solver gave {len(values)}")
        return values

    def asks(self) -> str:
        return f"a vector of {self.size} components" + (f" in {self.unit}" if self.unit else "")

    def input_hint(self) -> str:
        return _("{n} components").format(n=self.size)

    def near_misses(self, expected):
        if not any(expected):
            return []
        return [(self.answer_text(tuple(v * (1 + PERTURBATION) for v in expected)),
                 "a vector 5 % too long")]

    def scores(self, answer, expected) -> bool:
        import numpy as np

        return bool(self._close(np.asarray([answer], dtype=np.float64),
                                np.asarray([expected], dtype=np.float64))[0, 0])

    def one_answer(self, references):
        """:meth:`Part.one_answer` for vectors, all pairs at once, each component with the
        grader's scale (:func:`~dynagrade.grading.vector.component_scale`)."""
        import numpy as np

        values = np.asarray(references, dtype=np.float64)
        counts = self._close(values, values).sum(axis=1)
        best = int(np.argmax(counts))
        return tuple(float(v) for v in values[best]), int(counts[best])

    def _close(self, answers, expected):
        """Whether each row of ``answers`` scores against each row of ``expected``: a
        matrix (answers × references)."""
        import numpy as np

        scale = np.maximum(np.abs(expected),
                           0.01 * np.linalg.norm(expected, axis=1)[:, None])
        close = is_close(answers[:, None, :], expected[None, :, :], self.rtol, self.atol,
                         scale[None, :, :])
        return close.all(axis=2)

    def spec(self, params):
        return VectorSpec(size=self.size, unit=self.unit, rtol=self.rtol, atol=self.atol,
                          misconceptions=self._known_wrong(params), basis=self.basis)


@dataclass(frozen=True)
class Symbolic(Part):
    """An expression in declared variables, judged by evaluation over their domains.

    ``expected`` is the reference expression (the exercise's own text); ``equals`` names a
    numeric part that this expression must reproduce at the variant's parameters, which
    ``dynagrade verify`` checks against the mechanics core. ``form`` lists form tests
    (``"no_decimals"``, ``"simplified"``, ``"no_functions"``) graded apart from
    equivalence: an equivalent answer that fails one earns ``form_credit``.

    A variable is accepted under its name and every spelling of its printed symbol and
    aliases (``Variable(symbol=..., aliases=...)``; a parameter's ``symbol`` by default).
    ``up_to_constant`` declares that an additive constant does not matter: it names the
    variables the constant is constant in (``("theta",)`` for a potential V(θ) whose zero
    level is a convention; ``True`` for all). The answer is then compared by its changes
    in those variables, and the feedback says the constant was ignored.
    """

    expected: str = ""
    variables: Mapping[str, Variable] = field(default_factory=dict)
    equals: str | None = None
    form: tuple[str, ...] = ()
    form_credit: float = 0.5
    up_to_constant: bool | tuple[str, ...] = ()

    kind = "symbolic"
    grading = GRADING_KINDS["symbolic"]
    moodle = NotExported("a formula")
    answer_varies = False

    def reference(self, solved):
        return self.expected

    def with_variables(self, variables: Mapping[str, Variable]) -> Part:
        return replace(self, variables=variables)

    def asks(self) -> str:
        """``a formula in h, lat (λ)``: each variable's name, and the symbol the
        statement prints for it where that reads otherwise."""
        return "a formula in " + ", ".join(_with_printed_symbol(name, variable)
                                             for name, variable in self.variables.items())

    def input_hint(self) -> str:
        return _("in {names}").format(names=", ".join(self.variables))

    def near_misses(self, expected):
        return [(f"{1 + PERTURBATION}*({expected})", "the formula times 1.05")]

    def misconception_answer(self, misconception, params):
        return misconception.formula

    def own_checks_key(self, params, expected):
        """The reference, and which misconceptions apply: a formula's spec, its near miss
        and its misconceptions' answers are text fixed by the exercise, so only the
        ``applies`` predicates let its own checks differ between variants."""
        return (expected, tuple(index for index, misconception in enumerate(self.misconceptions)
                                if misconception.applies_to(params)))

    def check_names(self) -> None:
        self._spec(self.misconceptions)

    def spellings(self) -> Mapping[str, str]:
        return self._spec(()).spellings

    def variable_names(self) -> tuple[str, ...]:
        return tuple(self.variables)

    def cross_check(self, params, answers, part):
        """The formula, evaluated at the variant's parameters, against the numeric part it
        ``equals`` (the mechanics core's number)."""
        if not self.equals:
            return []
        from ..grading import evaluate_expression

        target = part(self.equals)
        value = to_si(answers[target.name], target.unit)
        formula = evaluate_expression(self.expected, dict(params))
        if abs(formula - value) > CROSS_CHECK_RTOL * max(abs(value), 1e-300):
            return [f"part {self.name}: the formula gives {format_number(formula)} in SI but "
                    f"the core gives {format_number(value)} for part {target.name}"]
        return []

    def spec(self, params):
        return self._spec(self.misconceptions_for(params))

    def _spec(self, misconceptions: tuple[Misconception, ...]) -> SymbolicSpec:
        """The spec with ``misconceptions`` (when the part is built, every one: no
        variant's parameters say which apply)."""
        known = tuple(KnownWrong(m.name, m.formula, m.feedback, m.score)
                      for m in misconceptions)
        return SymbolicSpec(variables=dict(self.variables), misconceptions=known,
                            form=tuple(self.form), form_credit=self.form_credit,
                            up_to_constant=self.up_to_constant)


def _with_printed_symbol(name: str, variable: Variable | None) -> str:
    symbol = getattr(variable, "symbol", None)
    printed = printed_form(symbol) if symbol else name
    return name if printed in (name, printed_form(name)) else f"{name} ({printed})"


@dataclass(frozen=True)
class Options(Part):
    """A choice among labelled options; ``multiple=True`` allows several correct ones.

    ``numbered=True`` says the statement numbers the options' cases in order: option k
    is then also accepted as the number k and as the k-th letter (``2``, ``b``).
    ``aliases`` maps further spellings to options (``{"G": "on the ground"}``).
    """

    options: tuple[str, ...] = ()
    multiple: bool = False
    numbered: bool = False
    aliases: Mapping[str, str] = field(default_factory=dict)

    kind = "choice"
    grading = GRADING_KINDS["choice"]
    moodle = MoodleForm.OPTIONS
    manifest_fields = ("options", "multiple")

    def in_part_unit(self, value):
        chosen = (value,) if isinstance(value, str) else tuple(value)
        unknown = [c for c in chosen if c not in self.options]
        if unknown:
            raise ValueError(f"part {self.name!r}: the solver chose {unknown}, "
                             f"not among the options {list(self.options)}")
        return chosen if self.multiple else chosen[0]

    def asks(self) -> str:
        return self.input_hint()

    def input_hint(self) -> str:
        from ..grading.choice import shown_option

        options = ", ".join(shown_option(o) for o in self.options)
        numbers = " " + _("(or 1–{n})").format(n=len(self.options)) if self.numbered else ""
        return (_("one or more of {options}") if self.multiple else _("one of {options}")).format(
            options=options) + numbers

    def input_options(self) -> tuple[str, ...]:
        return tuple(self.options)

    def near_misses(self, expected):
        if not self.multiple:
            return [(option, f"option {option!r}") for option in self.options
                    if option != expected]
        others = [o for o in self.options if o not in expected]
        if not others and len(expected) <= 1:
            return []
        wrong = expected[:-1] if len(expected) > 1 else expected + tuple(others[:1])
        return [(", ".join(wrong), "a different set of options")]

    def check_names(self) -> None:
        self.spec(None)

    def option_aliases(self) -> tuple[tuple[str, str], ...]:
        """Every (spelling, option) besides the labels: the numbers and letters of a
        numbered part, then the declared ``aliases``."""
        pairs = []
        if self.numbered:
            pairs += [(str(k), o) for k, o in enumerate(self.options, start=1)]
            pairs += [(chr(ord("a") + k), o) for k, o in enumerate(self.options[:26])]
        return tuple(pairs) + tuple(dict(self.aliases).items())

    def spec(self, params):
        return ChoiceSpec(options=tuple(self.options), multiple=self.multiple,
                          aliases=self.option_aliases())


def shortened(text: str, width: int) -> str:
    """``textwrap.shorten(text, width)``: the words of ``text`` one space apart, cut with
    " [...]" to fit ``width``; a line that fits as it is (most) skips the wrapper."""
    words = " ".join(text.split())
    return words if len(words) <= width else textwrap.shorten(words, width)


def part_class(class_name: str) -> type[Part] | None:
    """The part kind whose class is named ``class_name`` (``"Numeric"``) as an exercise
    file calls it; None for any other name (:mod:`.listing` reads calls unrun)."""
    cls = globals().get(class_name)
    if isinstance(cls, type) and issubclass(cls, Part) and cls in PART_KINDS.values():
        return cls
    return None
