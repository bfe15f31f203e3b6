"""What a page render costs under a class (issue 28, items 1 and 2): the student page says
how each answer it shows reads (so its script asks for no preview on load), reads each
shown answer once per server process, keeps every variant's statement of the class, and
looks for a missing figure once."""

from __future__ import annotations

import html
import re

from serve_support import exam_copy, exam_dir, serve  # noqa: F401


def _preview_of(page: str, exercise: str, part: str) -> re.Match:
    found = re.search(rf'<output class="([^"]*)" id="{exercise}--{part}--preview"[^>]*>'
                      r'(.*?)</output>', page, re.S)
    assert found is not None, (exercise, part)
    return found


def _box(page: str, exercise: str, part: str) -> str:
    found = re.search(rf'<input id="{exercise}--{part}"[^>]*>', page)
    assert found is not None, (exercise, part)
    return found.group(0)


def test_the_page_says_how_each_answer_it_shows_reads(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework")
    with serve(manifest) as served:
        bearer = {"Authorization": f"Bearer {served.tokens['s1']}"}
        # a counted answer: 45 km is 45,000 m, read as such (wrong, but readable)
        assert served.submit("s1", "projectile-range", {"x_max": "45 km"}).status_code == 200
        # drafts: a formula in the part's names, and one with a name it does not have
        assert served.client.put("/api/v1/drafts", headers=bearer, json={
            "exercise": "projectile-range",
            "answers": {"x_max_formula": "v0^2 sin(2 alpha)/g"}}).status_code == 200
        assert served.client.put("/api/v1/drafts", headers=bearer, json={
            "exercise": "sliding-up-a-slope",
            "answers": {"delta_x": "3 kg"}}).status_code == 200
        page = served.client.get(f"/s/{served.tokens['s1']}").text
        asked = served.client.post("/api/v1/preview", headers=bearer, json={
            "exercise": "sliding-up-a-slope", "part": "delta_x", "answer": "3 kg"}).json()

    counted = _preview_of(page, "projectile-range", "x_max")
    assert html.unescape(counted.group(2)) == "reads as 45 km = 4.5e4 m"
    assert "bad" not in counted.group(1)
    assert "aria-invalid" not in _box(page, "projectile-range", "x_max")
    formula = _preview_of(page, "projectile-range", "x_max_formula").group(2)
    assert "<math" in formula and formula.count("<mfrac") == 1  # v0^2 sin(2 alpha) over g
    # a mass where a length is asked: the same words as the preview API, marked unreadable
    unreadable = _preview_of(page, "sliding-up-a-slope", "delta_x")
    assert asked["readable"] is False and "expected a length" in asked["message"]
    assert html.unescape(unreadable.group(2)) == asked["message"]
    assert "bad" in unreadable.group(1)
    assert 'aria-invalid="true"' in _box(page, "sliding-up-a-slope", "delta_x")
    # an empty box says nothing
    assert _preview_of(page, "sliding-up-a-slope", "a_up").group(2) == ""


def test_a_process_reads_each_answer_a_page_shows_once(exam_dir, tmp_path):
    manifest = exam_copy(exam_dir, tmp_path / "exam", mode="homework")
    with serve(manifest) as served:
        served.submit("s1", "projectile-range", {"x_max": "45 km", "x_max_formula": "v0"})
        data = served.server.data
        before = data._reading.cache_info()
        for _load in range(3):
            assert served.client.get(f"/s/{served.tokens['s1']}").status_code == 200
        after = data._reading.cache_info()
    # two filled boxes: read at the first load, remembered at the two others
    assert after.misses - before.misses == 2
    assert after.hits - before.hits == 4


def test_the_statement_cache_holds_every_variant_of_a_class():
    from dynagrade.serve.exam_data import MAX_CACHED_VARIANTS, cache_size

    assert cache_size(1000, 6) == 6000  # more than the 4,096 it was
    assert cache_size(700, 6) == 4200
    assert cache_size(10**6, 6) == MAX_CACHED_VARIANTS  # bounded
    assert cache_size(3, 2) == 64


def test_a_missing_figure_is_looked_for_once(exam_dir, tmp_path, monkeypatch):
    import shutil
    from pathlib import Path

    from dynagrade.serve.exam_data import ExamData

    folder = tmp_path / "exam"
    shutil.copytree(exam_dir, folder)
    (folder / "students" / "s1" / "sliding-up-a-slope.svg").unlink()
    data = ExamData(folder / "manifest.json")
    looked: list[str] = []
    read_text = Path.read_text

    def counting(path, *args, **kwargs):
        looked.append(path.name)
        return read_text(path, *args, **kwargs)

    monkeypatch.setattr(Path, "read_text", counting)
    for _render in range(3):
        assert data.figure_svg("s1", "sliding-up-a-slope") is None
        assert data.figure_svg("s1", "projectile-range").startswith("<svg")
    # the missing one: its two places tried at the first render only; the present one
    # is read at each
    assert looked.count("sliding-up-a-slope.svg") == 2
    assert looked.count("projectile-range.svg") == 3
