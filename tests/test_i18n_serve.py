"""A German exam is served in German: the grading workers grade in the exam's language,
work handed to threads keeps it, choice words are taken in it, and the student and staff
pages hold no English fixed string (the author's statement, numbers, units and ids aside).
"""

from __future__ import annotations

import asyncio
import dataclasses
import html
import re
from html.parser import HTMLParser

import pytest

from serve_support import exam_copy, reference_answers, serve
from test_i18n import SOURCE, marked_messages

from dynagrade import i18n

EXAM_TOML = """\
id = "german-test"
title = "Deutsch"
date = 2025-04-14
language = "de"

[[exercise]]
id = "block-sliding-down-incline"
points = 5

[[exercise]]
id = "projectile-range"
points = 4
"""

ROSTER = "student_id,name,email\ns1,Ada Eins,ada@example.org\ns2,Bo Zwei,bo@example.org\n"


@pytest.fixture(scope="module")
def german_exam(tmp_path_factory):
    from dynagrade.generation.generate import generate_exam

    root = tmp_path_factory.mktemp("german")
    (root / "exam.toml").write_text(EXAM_TOML, encoding="utf-8")
    (root / "roster.csv").write_text(ROSTER, encoding="utf-8")
    generate_exam(root / "exam.toml", root / "roster.csv", root / "out", pdf=False, jobs=1,
                  secret="7a" * 32)
    return root / "out"


@pytest.fixture(scope="module")
def served(german_exam, tmp_path_factory):
    """A German homework showing verdicts at once, with attempts and a penalty (every
    policy word on the page), two submits of s1 already made."""
    import datetime as dt

    manifest = exam_copy(german_exam, tmp_path_factory.mktemp("german-hw") / "exam",
                         mode="homework", feedback="immediate", attempts=3, penalty=0.1,
                         closes=dt.datetime(2030, 1, 1, tzinfo=dt.timezone.utc))
    with serve(manifest) as running:
        assert running.server.data.manifest.exam.language == "de"
        first = running.submit("s1", "block-sliding-down-incline",
                               {"a": "3 kg", "N": "-1", "stops": "vielleicht"})
        assert first.status_code == 200, first.text
        second = running.submit("s1", "projectile-range", {
            name: "1" for name in reference_answers(running, "s1", "projectile-range")})
        assert second.status_code == 200, second.text
        yield running


def _parts(response) -> dict:
    return {p["name"]: p for p in response.json()["parts"]}


# -- grading in the exam's language ---------------------------------------------------------


def test_the_grading_workers_grade_in_the_exams_language(served):
    """A wrong unit is unreadable (refused beside the part, nothing spent) and a wrong
    number graded: both answers come back in German, and the stored verdict is German."""
    response = served.submit("s2", "block-sliding-down-incline",
                             {"a": "2 kg", "N": "-1", "stops": "vielleicht"})
    parts = _parts(response)
    assert not parts["a"]["readable"]
    assert parts["a"]["message"].startswith("Problem mit der Einheit: angegeben: eine Masse")
    assert "erwartet: eine Beschleunigung" in parts["a"]["message"]
    assert parts["stops"]["message"].startswith("unbekannte Option 'vielleicht'; die Optionen "
                                                "sind: ja, nein")
    assert parts["N"]["readable"] and parts["N"]["feedback"].startswith("Nicht richtig")
    stored = [a for a in _stored(served, "s2") if a.part == "N"]
    assert stored and stored[-1].feedback.startswith("Nicht richtig")
    assert not [a for a in _stored(served, "s2") if a.part == "a"]


def test_the_preview_reads_in_the_exams_language(served):
    headers = {"Authorization": f"Bearer {served.tokens['s1']}"}
    read = served.client.post("/api/v1/preview", headers=headers, json={
        "exercise": "block-sliding-down-incline", "part": "a", "answer": "36 km/h^2"}).json()
    assert read["readable"] and read["message"].startswith("gelesen als 36 km/h^2 = ")
    bad = served.client.post("/api/v1/preview", headers=headers, json={
        "exercise": "block-sliding-down-incline", "part": "a", "answer": "3 +* 4"}).json()
    assert not bad["readable"] and bad["message"].startswith("zwei Operatoren hintereinander")


def test_refusals_are_in_the_exams_language(served):
    response = served.submit("s2", "block-sliding-down-incline", {"a": "   "})
    assert response.status_code == 422
    assert "keine Antwort angegeben" in response.text


def test_work_handed_to_threads_keeps_the_language():
    from starlette.concurrency import run_in_threadpool

    async def in_thread() -> str:
        with i18n.language("de"):
            return await run_in_threadpool(lambda: i18n._("not answered"))

    assert asyncio.run(in_thread()) == "nicht beantwortet"
    assert i18n.active() == "en"


def _stored(served, student):
    from dynagrade.serve import db

    return db.student_answers(served.server.engine, served.server.data.exam_id, student)


# -- choice words ----------------------------------------------------------------------------


def test_choice_words_are_taken_in_the_exams_language(served):
    entry = served.variant("s2", "block-sliding-down-incline")
    right = {"yes": "ja", "no": "nein"}[entry.answers["stops"]]
    wrong = {"ja": "nein", "nein": "ja"}[right]
    parts = _parts(served.submit("s2", "block-sliding-down-incline", {"stops": right}))
    assert parts["stops"]["correct"]
    # the unreadable "vielleicht" before spent no attempt: this is the first, at full points
    assert parts["stops"]["feedback"] == "Richtig."
    assert parts["stops"]["message"] == f"gelesen als {right}"
    parts = _parts(served.submit("s2", "block-sliding-down-incline", {"stops": wrong}))
    assert parts["stops"]["readable"] and not parts["stops"]["correct"]
    assert parts["stops"]["feedback"].endswith("(Versuch 2: 90 % der Punkte)")


def test_english_exams_take_english_choice_words_only():
    from dynagrade.grading import grade
    from dynagrade.grading.spec import ChoiceSpec

    spec = ChoiceSpec(("yes", "no"))
    assert not grade(spec, "no", "nein").correct
    assert grade(spec, "no", "nein").error.startswith("unknown option 'nein'")
    with i18n.language("de"):
        assert grade(spec, "no", "nein").correct and grade(spec, "no", "no").correct
        assert not grade(spec, "no", "ja").correct
        # a label the author wrote wins over a translated word
        assert grade(ChoiceSpec(("ja", "yes", "no")), "ja", "ja").correct


# -- no English on a German page -------------------------------------------------------------


class _Text(HTMLParser):
    """The text a person reads or hears on a page: text nodes (not scripts or styles) and
    the attributes read aloud."""

    SPOKEN = ("title", "aria-label", "placeholder", "alt")

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.chunks: list[str] = []
        self._skip = 0

    def handle_starttag(self, tag, attrs):
        if tag in ("script", "style", "code"):  # code: commands and answers as typed
            self._skip += 1
        self.chunks.extend(value for name, value in attrs if name in self.SPOKEN and value)

    def handle_endtag(self, tag):
        if tag in ("script", "style", "code"):
            self._skip -= 1

    def handle_data(self, data):
        if not self._skip:
            self.chunks.append(data)


def _english_words() -> set[str]:
    """The words of the interface's English messages that German text never uses (a word
    the German catalog uses as well, like "Name" or "sin", cannot tell the two apart)."""
    from babel.messages.pofile import read_po

    def words(text: str) -> set[str]:
        text = re.sub(r"\{[^}]*\}", " ", text)
        return {w.lower() for w in re.findall(r"[A-Za-z]{3,}", text)}

    english: set[str] = set()
    for message in marked_messages():
        english |= words(message)
    with (SOURCE / "locale" / "de" / "LC_MESSAGES" / f"{i18n.DOMAIN}.po").open("rb") as handle:
        german = set()
        for message in read_po(handle):
            for text in (message.string if isinstance(message.string, tuple)
                         else (message.string,)):
                german |= words(text or "")
    return english - german


def _authors_words(served) -> list[str]:
    """What the author and the roster wrote, and the page's ids: removed before the scan."""
    data = served.server.data
    out = [data.title, data.instructions or ""]
    for student in data.students.values():
        out += [student.name, student.student_id]
    for exercise_id in data.exercise_ids:
        out += [exercise_id, data.exercises_meta[exercise_id].title]
        for part in data.parts(exercise_id):
            out += [part.name, part.label]
    return [w for w in out if w]


def _english_left(served, page: str, statements: list[str]) -> list[str]:
    for statement in statements:  # the statement and solution HTML as the page holds them
        page = page.replace(statement, " ")
    reader = _Text()
    reader.feed(page)
    text = " ".join(reader.chunks)
    for written in sorted(_authors_words(served), key=len, reverse=True):
        if len(written) >= 3:  # shorter names fall below the words looked for anyway
            text = re.sub(rf"(?<!\w){re.escape(written)}(?!\w)", " ", text)
    text = re.sub(r"[\w.-]+\.csv|[0-9][\w.:+/-]*", " ", text)  # file names, numbers, times
    words = {w.lower() for w in re.findall(r"[A-Za-z]{3,}", html.unescape(text))}
    left = sorted(words & _english_words())
    if left:  # where each word stands, for the failure message
        print({w: re.findall(rf".{{0,40}}\b{w}\b.{{0,40}}", text, re.I)[:2] for w in left})
    return left


def _statements(served, student: str) -> list[str]:
    data = served.server.data
    out = []
    for exercise_id in data.exercise_ids:
        out.append(data.statement_html(student, exercise_id))
        out.append(data.figure_svg(student, exercise_id) or "")
        out.append(data.solution_html(student, exercise_id) or "")
    return [s for s in out if s]


def test_the_english_word_list_is_built_from_the_messages():
    words = _english_words()
    assert {"attempts", "correct", "submit", "verdict", "unknown"} <= words
    assert "name" not in words  # German too


def test_the_german_student_page_has_no_english_fixed_string(served):
    page = served.client.get(f"/s/{served.tokens['s1']}")
    assert page.status_code == 200 and 'lang="de"' in page.text
    assert "Dein Stand" in page.text and "Nicht richtig" in page.text
    assert _english_left(served, page.text, _statements(served, "s1")) == []


def test_the_german_staff_page_has_no_english_fixed_string(served):
    page = served.client.get(f"/i/{served.staff}")
    assert page.status_code == 200 and 'lang="de"' in page.text
    assert "Fortschritt" in page.text
    assert _english_left(served, page.text, []) == []


def test_the_german_regrade_page_has_no_english_fixed_string(served):
    page = served.client.get(f"/i/{served.staff}/regrade")
    assert "Kein Plan ist offen" in page.text
    assert _english_left(served, page.text, []) == []
    made = served.client.post("/api/v1/regrades",
                              headers={"Authorization": f"Bearer {served.staff}"})
    assert made.status_code == 200, made.text
    page = served.client.get(f"/i/{served.staff}/regrade")
    assert f"Plan {made.json()['id']} anwenden" in page.text
    # who previewed it is data: the staff link's name (here its default, the hash's start)
    assert _english_left(served, page.text, [made.json()["actor"]]) == []


def test_the_scan_finds_english(served):
    """The scan is not blind: the same page in English is full of interface words."""
    english = dataclasses.replace(served.server.data.manifest.exam, language="en")
    from dynagrade.serve import pages

    with i18n.language(english.language):
        page = pages.student_html(served.server, served.tokens["s1"], "s1", None,
                                  _now(), "")
    found = _english_left(served, page, _statements(served, "s1"))
    assert {"attempts", "feedback", "points"} <= set(found)


def _now():
    import datetime as dt

    return dt.datetime(2025, 4, 14, 10, 0, tzinfo=dt.timezone.utc)


def test_a_german_exams_error_page_gives_its_reason_in_german(served):
    page = served.client.get("/s/not-a-token", headers={"Accept": "text/html"})
    assert page.status_code == 401 and 'lang="de"' in page.text
    assert "unbekannter Link" in page.text and "unknown link" not in page.text
