"""Write sample submissions for a generated exam, to try class grading end to end.

Usage (after ``dynagrade exam examples/exam.toml --roster examples/roster.csv -o out/``)::

    python examples/make_submissions.py out/

It fills in the students' own fill-in files from ``out/students/`` and writes them to
``out/submissions/``:

- the first 5 roster students answer everything correctly;
- the next 5 answer every other part correctly (the first, third, ...) and the rest wrong;
- the next 2 hand in their sheets unanswered;
- one hands in a corrupt file for the first exercise (and correct answers for the rest);
- one hands in the first exercise twice: a wrong file, then (modified a minute later) a
  correct one; the later counts;
- two answer in a CSV of responses (student_id,exercise_id,part,answer), correctly;
- a sheet from a student who is not on the roster (in a folder of no roster student);
  in the first student's folder, a sheet whose VARIANT token was changed (a sheet of
  another exam); in the second student's folder, the first student's sheet answered correctly
  (impersonating: credited to nobody);
- everyone else is absent.

Each student's files go in a folder named by their id: that, not the file's STUDENT
line, says whose a file is.
"""

from __future__ import annotations

import csv
import json
import os
import re
import sys
from pathlib import Path

WRONG_FACTOR = 1.37

PLAN = (("correct", 5), ("half", 5), ("empty", 2), ("corrupt", 1), ("duplicate", 1),
        ("csv", 2))


def plan(student_ids: list[str]) -> dict[str, str]:
    """Which kind of submission each student hands in (absent ones are left out)."""
    kinds, position = {}, 0
    for kind, count in PLAN:
        for student_id in student_ids[position:position + count]:
            kinds[student_id] = kind
        position += count
    return kinds


def _number(value: float) -> str:
    return f"{value:.10g}"


def answer(part: dict, value, correct: bool) -> str:
    """The text a student writes for ``part`` whose reference is ``value``."""
    kind = part["kind"]
    if kind == "numeric":
        return _number(value if correct else value * WRONG_FACTOR + 0.5)
    if kind == "vector":
        factor = 1.0 if correct else WRONG_FACTOR
        return "[" + ", ".join(_number(v * factor + (0 if correct else 0.5)) for v in value) + "]"
    if kind == "symbolic":
        return value if correct else f"{WRONG_FACTOR}*({value})"
    if kind == "choice":
        chosen = value if isinstance(value, list) else [value]
        if correct:
            return ", ".join(chosen)
        others = [o for o in part["options"] if o not in chosen]
        return others[0] if others else "?"
    raise ValueError(kind)


def answers_for(described: dict, variant: dict, kind: str) -> dict[str, str | None]:
    """The answers a student of ``kind`` gives to each part of one exercise."""
    answers = {}
    for index, part in enumerate(described["parts"]):
        value = variant["answers"][part["name"]]
        if kind == "empty":
            answers[part["name"]] = None
        elif kind == "half":
            answers[part["name"]] = answer(part, value, index % 2 == 0)
        elif kind == "wrong":
            answers[part["name"]] = answer(part, value, False)
        else:
            answers[part["name"]] = answer(part, value, True)
    return answers


def fill(sheet_text: str, answers: dict[str, str | None]) -> str:
    """The fill-in file with ``name = None`` replaced by each answer (a quoted string)."""
    for name, text in answers.items():
        if text is not None:
            sheet_text = re.sub(rf"^{re.escape(name)} = None$", f"{name} = {json.dumps(text)}",
                                sheet_text, count=1, flags=re.M)
    return sheet_text


def main(out_dir: str) -> None:
    out = Path(out_dir)
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    exercises = {e["id"]: e for e in manifest["exercises"]}
    students = manifest["students"]
    kinds = plan([s["student_id"] for s in students])
    target = out / "submissions"
    target.mkdir(parents=True, exist_ok=True)
    rows = []
    for student in students:
        kind = kinds.get(student["student_id"])
        if kind is None:
            continue
        folder = target / student["student_id"]
        for number, variant in enumerate(student["variants"]):
            described = exercises[variant["exercise"]]
            sheet = (out / "students" / student["student_id"]
                     / f"{variant['exercise']}.py").read_text(encoding="utf-8")
            if kind == "csv":
                for name, text in answers_for(described, variant, "correct").items():
                    rows.append([student["student_id"], variant["exercise"], name, text])
                continue
            if kind == "corrupt" and number == 0:
                text = fill(sheet, answers_for(described, variant, "correct"))
                (folder / f"{variant['exercise']}.py").parent.mkdir(parents=True, exist_ok=True)
                (folder / f"{variant['exercise']}.py").write_text(
                    text.replace("EXERCISE = ", "EXERCISE = = ", 1), encoding="utf-8")
                continue
            if kind == "duplicate" and number == 0:
                folder.mkdir(parents=True, exist_ok=True)
                (folder / f"1-{variant['exercise']}.py").write_text(
                    fill(sheet, answers_for(described, variant, "wrong")), encoding="utf-8")
                (folder / f"2-{variant['exercise']}.py").write_text(
                    fill(sheet, answers_for(described, variant, "correct")), encoding="utf-8")
                _modified_after(folder / f"2-{variant['exercise']}.py",
                                folder / f"1-{variant['exercise']}.py")
                continue
            folder.mkdir(parents=True, exist_ok=True)
            kind_here = kind if kind in ("half", "empty") else "correct"
            (folder / f"{variant['exercise']}.py").write_text(
                fill(sheet, answers_for(described, variant, kind_here)), encoding="utf-8")
    with open(target / "responses.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(["student_id", "exercise_id", "part", "answer"])
        writer.writerows(rows)
    first = students[0]
    sheet = (out / "students" / first["student_id"]
             / f"{first['variants'][0]['exercise']}.py").read_text(encoding="utf-8")
    strangers = target / "strangers"
    strangers.mkdir(exist_ok=True)
    (strangers / "not-on-roster.py").write_text(
        sheet.replace(f"STUDENT = {first['student_id']!r}", "STUDENT = 'x00-000'"),
        encoding="utf-8")
    elsewhere = target / first["student_id"] / "old"
    elsewhere.mkdir(parents=True, exist_ok=True)
    forged = 'VARIANT = "' + "0" * 24 + '"'
    (elsewhere / "other-exam.py").write_text(
        re.sub(r"^VARIANT = ['\"][0-9a-z]+['\"]$", forged, sheet, flags=re.M),
        encoding="utf-8")
    if len(students) > 1:
        _impersonate(out, target, first, students[1], exercises)
    print(f"wrote sample submissions to {target}")


def _modified_after(later: Path, earlier: Path) -> None:
    """Give ``later`` a modification time a minute after ``earlier``'s."""
    stamp = earlier.stat().st_mtime + 60
    os.utime(later, (stamp, stamp))


def _impersonate(out: Path, target: Path, victim: dict, student: dict,
                 exercises: dict) -> None:
    """Put ``victim``'s first sheet, answered correctly, in ``student``'s folder."""
    variant = victim["variants"][0]
    sheet = (out / "students" / victim["student_id"]
             / f"{variant['exercise']}.py").read_text(encoding="utf-8")
    folder = target / student["student_id"] / "for-a-friend"
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"{variant['exercise']}.py").write_text(
        fill(sheet, answers_for(exercises[variant["exercise"]], variant, "correct")),
        encoding="utf-8")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out")
