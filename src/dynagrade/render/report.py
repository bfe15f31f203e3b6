"""Feedback for each student and the class report, from a graded class.

Plots are drawn with matplotlib into inline SVG (fixed hash salt, no date), so the
report is one self-contained HTML file that shows the same on every run.
"""

from __future__ import annotations

import io
from typing import TYPE_CHECKING

from .figures import SVG_SETTINGS, inline_svg
from ..exercise.numbers import answer_text, format_number
from ..exercise.units import with_unit
from .sheets import render_template

if TYPE_CHECKING:
    from ..exam.manifest import ExamEntry, ExerciseEntry


def _shown(value, unit) -> str:
    return with_unit(answer_text(value), unit)


def _feedback_context(exam, exercises, data) -> dict:
    sections = []
    for entry in data["student"].variants:
        exercise_id = entry.exercise
        result = data["results"][exercise_id]
        described = exercises[exercise_id]
        parts = []
        if result is not None:
            for part in result["parts"]:
                parts.append({**part, "expected_shown": _shown(part["expected"], part["unit"]),
                              "answer_shown": part["answer"] if part["answer"] is not None
                              else "—"})
        sections.append({"id": exercise_id, "title": described.title,
                         "points": described.points, "result": result, "parts": parts,
                         "solution": data.get("solutions", {}).get(exercise_id)})
    return {"exam": exam, "student": data["student"], "row": data["row"],
            "sections": sections}


def feedback_markdown(exam: ExamEntry, exercises: dict[str, ExerciseEntry], data: dict) -> str:
    """One student's feedback as Markdown."""
    return render_template("feedback.md", **_feedback_context(exam, exercises, data))


def feedback_html(exam: ExamEntry, exercises: dict[str, ExerciseEntry], data: dict) -> str:
    """One student's feedback as a self-contained HTML page."""
    return render_template("feedback.html", **_feedback_context(exam, exercises, data))


def _svg(figure) -> str:
    import matplotlib

    buffer = io.StringIO()
    with matplotlib.rc_context(SVG_SETTINGS):
        figure.savefig(buffer, format="svg", metadata={"Date": None, "Creator": "dynagrade"})
    return inline_svg(buffer.getvalue())


def histogram_svg(percents: list[float]) -> str:
    """Histogram of the students' percentages in bins of 10 %."""
    from matplotlib.figure import Figure

    figure = Figure(figsize=(6.0, 2.8))
    axes = figure.add_axes((0.1, 0.18, 0.86, 0.74))
    axes.hist(percents, bins=[10 * i for i in range(11)], color="C0", edgecolor="white")
    axes.set_xlabel("score (%)")
    axes.set_ylabel("students")
    axes.set_xlim(0, 100)
    axes.yaxis.get_major_locator().set_params(integer=True)
    return _svg(figure)


def items_svg(stats) -> str:
    """Difficulty (mean score fraction) and point-biserial discrimination per part."""
    from matplotlib.figure import Figure

    labels = [f"{s.exercise_id}\n{s.part}" for s in stats]
    height = 1.2 + 0.32 * len(stats)
    figure = Figure(figsize=(7.0, height))
    axes = figure.add_axes((0.34, 0.6 / height, 0.62, 1 - 1.0 / height))
    positions = list(range(len(stats)))[::-1]
    axes.barh([p + 0.2 for p in positions], [s.difficulty or 0.0 for s in stats], height=0.4,
              color="C0", label="difficulty (mean fraction)")
    axes.barh([p - 0.2 for p in positions], [s.point_biserial or 0.0 for s in stats],
              height=0.4, color="C1", label="discrimination (point-biserial)")
    axes.set_yticks(positions, labels, fontsize=7)
    axes.set_xlim(-0.5, 1.0)
    axes.axvline(0, color="0.3", lw=0.6)
    axes.legend(fontsize=7, loc="lower right")
    return _svg(figure)


def report_html(exam: ExamEntry, outcome) -> str:
    """The class report: summary, histogram, item statistics and common wrong answers."""
    present = [r for r in outcome.rows if r["status"] != "absent"]
    percents = [r["percent"] for r in present]
    summary = {
        "students": len(outcome.rows), "present": len(present),
        "absent": len(outcome.rows) - len(present),
        "mean": format_number(sum(percents) / len(percents), 4) if percents else "—",
        "median": format_number(sorted(percents)[len(percents) // 2], 4) if percents else "—",
    }
    return render_template(
        "report.html", exam=exam, outcome=outcome, summary=summary,
        histogram=histogram_svg(percents) if percents else "",
        items=items_svg(outcome.stats) if present else "",
        fmt=lambda v: "—" if v is None else format_number(v, 3))
