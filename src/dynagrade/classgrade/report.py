"""Feedback for each student and the class report, from a graded class.

Plots are drawn with matplotlib into inline SVG (fixed hash salt, no date), so the
report is one self-contained HTML file that shows the same on every run. Each plot is an
image with a title and a description that states its data (the histogram's bin counts
also stand in a table), drawn in colours of at least 3:1 contrast against white.
"""

from __future__ import annotations

import io
import statistics
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..exam.points import Rounding
from ..i18n import _
from ..exercise.numbers import answer_text, format_number, percent_text
from ..exercise.units import with_unit
from ..render.accessible_svg import accessible_svg, sentence_list
from ..render.figures import SVG_SETTINGS, inline_svg
from ..render.sheets import render_template
from .copies import NEAR_KEYS, NEVER_A_GRADE, THRESHOLD
from .discover import CHANCE_FACTOR, MIN_SUPPORT, MIN_VARIANTS, PROPOSALS_ONLY
from .stats import MIN_STUDENTS, PartStats

if TYPE_CHECKING:
    from ..exam.manifest import ExamEntry, ExerciseEntry
    from .outcome import StudentFeedback


NO_ANSWER = "— (no answer)"
NOT_DEFINED = "— (not defined)"
#: bar colours, both at least 3:1 against white (WCAG 1.4.11): blue 4.8:1, dark orange 5.0:1
BAR_COLOURS = ("#1f77b4", "#b45309")
BINS = tuple(range(0, 101, 10))


def _shown(value, unit) -> str:
    return with_unit(answer_text(value), unit)


def _feedback_context(exam: ExamEntry, exercises: dict[str, ExerciseEntry],
                      data: StudentFeedback) -> dict:
    rule = Rounding(exam.rounding)
    sections = []
    for entry in data.student.variants:
        exercise_id = entry.exercise
        result = data.results[exercise_id]
        described = exercises[exercise_id]
        parts = [{"name": part.name, "status": part.status, "score": part.score,
                  "points": part.points, "feedback": part.shown_feedback(rule),
                  "expected_shown": _shown(part.expected, part.unit),
                  "answer_shown": part.answer if part.answer is not None else NO_ANSWER}
                 for part in (result.parts if result is not None else ())]
        sections.append({"id": exercise_id, "title": described.title,
                         "points": described.points, "result": result, "parts": parts,
                         "rejected": data.rejected.get(exercise_id, []),
                         "solution": data.solutions.get(exercise_id)})
    row = data.row
    shown_row = {"total": row.total, "max_total": row.max_total,
                 "percent": percent_text(row.percent), "status": row.status}
    return {"exam": exam, "student": data.student, "row": shown_row, "sections": sections}


def feedback_markdown(exam: ExamEntry, exercises: dict[str, ExerciseEntry],
                      data: StudentFeedback) -> str:
    """One student's feedback as Markdown."""
    return render_template("feedback.md", **_feedback_context(exam, exercises, data))


def feedback_html(exam: ExamEntry, exercises: dict[str, ExerciseEntry],
                  data: StudentFeedback) -> str:
    """One student's feedback as a self-contained HTML page."""
    return render_template("feedback.html", **_feedback_context(exam, exercises, data))


def _svg(figure, title: str, description: str, id_prefix: str) -> str:
    import matplotlib

    buffer = io.StringIO()
    with matplotlib.rc_context(SVG_SETTINGS):
        figure.savefig(buffer, format="svg", metadata={"Date": None, "Creator": "dynagrade"})
    return inline_svg(accessible_svg(buffer.getvalue(), title, description), id_prefix)


@dataclass(frozen=True)
class Histogram:
    """The score histogram: its SVG and its data, ``(band, students)`` per 10 % band."""

    svg: str
    bins: tuple[tuple[str, int], ...]


def score_bins(percents: list[float]) -> tuple[tuple[str, int], ...]:
    """Students per band of 10 %: ``[0, 10)``, ..., ``[80, 90)`` and ``[90, 100]``."""
    counts = [0] * (len(BINS) - 1)
    last = len(counts) - 1
    for percent in percents:
        counts[min(max(int(percent // 10), 0), last)] += 1
    return tuple((f"{low}–{high} %" + (" (100 % included)" if band == last else ""), count)
                 for band, (low, high, count) in enumerate(zip(BINS, BINS[1:], counts)))


def histogram(percents: list[float]) -> Histogram:
    """Histogram of the students' percentages in bins of 10 %, with its data."""
    from matplotlib.figure import Figure
    from matplotlib.ticker import MaxNLocator

    bins = score_bins(percents)
    figure = Figure(figsize=(6.0, 2.8))
    axes = figure.add_axes((0.1, 0.18, 0.86, 0.74))
    axes.bar([low + 5 for low in BINS[:-1]], [count for _, count in bins], width=10,
             color=BAR_COLOURS[0], edgecolor="white")
    axes.set_xlabel("score (%)")
    axes.set_ylabel("students")
    axes.set_xlim(0, 100)
    locator = axes.yaxis.get_major_locator()
    if isinstance(locator, MaxNLocator):  # always: a linear axis's AutoLocator is one
        locator.set_params(integer=True)
    counted = [f"{band}: {count}" for band, count in bins]
    description = (f"Bar chart of the scores of {len(percents)} students in bands of 10 %, "
                   f"students per band: {sentence_list(counted)}.")
    return Histogram(_svg(figure, "Histogram of the students' scores", description,
                          "histogram-"), bins)


def items_svg(stats) -> str:
    """Difficulty (mean score fraction) and point-biserial discrimination per part."""
    from matplotlib.figure import Figure

    labels = [f"{s.exercise_id}\n{s.part}" for s in stats]
    height = 1.2 + 0.32 * len(stats)
    figure = Figure(figsize=(7.0, height))
    axes = figure.add_axes((0.34, 0.6 / height, 0.62, 1 - 1.0 / height))
    positions = list(range(len(stats)))[::-1]
    axes.barh([p + 0.2 for p in positions], [s.difficulty or 0.0 for s in stats], height=0.4,
              color=BAR_COLOURS[0], label="difficulty (mean fraction)")
    axes.barh([p - 0.2 for p in positions], [s.point_biserial or 0.0 for s in stats],
              height=0.4, color=BAR_COLOURS[1], label="discrimination (point-biserial)")
    axes.set_yticks(positions, labels, fontsize=7)
    axes.set_xlim(-0.5, 1.0)
    axes.axvline(0, color="0.3", lw=0.6)
    axes.legend(fontsize=7, loc="lower right", edgecolor="0.4")
    values = [f"{s.exercise_id} {s.part}: difficulty {_stat(s.difficulty)}, "
              f"point-biserial {_stat(s.point_biserial)}" for s in stats]
    description = ("Horizontal bar chart, two bars per part (difficulty, blue; point-"
                   "biserial discrimination, orange) on a scale from −0.5 to 1: "
                   + "; ".join(values) + ".")
    return _svg(figure, "Difficulty and discrimination of every part", description, "items-")


def _stat(value) -> str:
    return NOT_DEFINED if value is None else format_number(value, 3)


def class_summary(rows) -> dict:
    """Roster size, present and absent students, and the mean and median percentage of
    those present (the median of an even count is the mean of the two middle values)."""
    present = [r for r in rows if r.status != "absent"]
    percents = [r.percent for r in present]
    none = "— (no submissions)"
    return {
        "students": len(rows), "present": len(present), "absent": len(rows) - len(present),
        "mean": format_number(statistics.fmean(percents), 4) if percents else none,
        "median": format_number(statistics.median(percents), 4) if percents else none,
    }


def share(part: int, whole: int) -> str:
    """``part`` as a whole percentage of ``whole`` ("67 %"), or not defined for none."""
    return NOT_DEFINED if not whole else f"{100 * part / whole:.0f} %"


def reliability(stats: PartStats) -> str:
    """How many students a part's statistics rest on, and whether that is too few."""
    if not stats.answered:
        return "no students"
    if stats.few_students:
        return f"{stats.answered} students: fewer than {MIN_STUDENTS}, a hint only"
    return f"{stats.answered} students"


def small_class_caution(stats: list[PartStats]) -> str:
    """A sentence when any part's statistics rest on fewer than :data:`MIN_STUDENTS`
    students ("" when none does)."""
    few = [s for s in stats if s.answered and s.few_students]
    if not few:
        return ""
    fewest = min(s.answered for s in few)
    which = "every part" if len(few) == len([s for s in stats if s.answered]) \
        else f"{len(few)} of the {len(stats)} parts"
    return (f"the statistics of {which} rest on fewer than {MIN_STUDENTS} students (the "
            f"fewest: {fewest}). With so few, one student more or less moves a difficulty, "
            "a point-biserial correlation or an upper–lower index by a tenth or more: read "
            "them, and the shares of wrong answers, as hints, not measurements.")


def findings_settings() -> dict:
    """The settings the report's sections on discovered mistakes and copied answers
    state, and their notes in the active language."""
    return {"discovery": {"min_support": MIN_SUPPORT, "min_variants": MIN_VARIANTS,
                          "chance_factor": format_number(CHANCE_FACTOR),
                          "note": _(PROPOSALS_ONLY)},
            "copying": {"threshold": format_number(THRESHOLD),
                        "near_keys": format_number(NEAR_KEYS), "note": _(NEVER_A_GRADE)}}


def report_html(exam: ExamEntry, outcome) -> str:
    """The class report: summary, histogram, item statistics (with a caution where they
    rest on few students), the wrong answers grouped by what explains them and, where
    the outcome has them, the mistakes nobody declared and the copied answers."""
    percents = [r.percent for r in outcome.rows if r.status != "absent"]
    return render_template(
        "report.html", exam=exam, outcome=outcome, summary=class_summary(outcome.rows),
        histogram=histogram(percents) if percents else None,
        items=items_svg(outcome.stats) if percents else "", fmt=_stat,
        caution=small_class_caution(outcome.stats), reliability=reliability, share=share,
        min_students=MIN_STUDENTS, wrong_parts=[s for s in outcome.stats if s.wrong],
        findings=outcome.findings, shown=_shown, **findings_settings())
