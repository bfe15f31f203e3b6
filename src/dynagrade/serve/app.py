"""The ASGI application: student and staff pages and the JSON API (docs/serve.md).

``create_app(manifest, db_url)`` builds it; every worker process builds its own, and
they share nothing but the database. A token in the path (pages) or in
``Authorization: Bearer`` (API) decides who is asking; nothing else does.

Routes::

    GET  /healthz                     200 when the database answers
    GET  /s/{token}                   the student's sheet, answer boxes, attempts
    POST /s/{token}/submit            the sheet's form (CSRF field, idempotency key)
    POST /s/{token}/practice          practice mode: a fresh variant of one exercise
    GET  /i/{token}                   staff: gradebook, progress, downloads
    GET  /i/{token}/grades.csv | submissions.csv | report.html
    POST /api/v1/answers              submit (student token)
    POST /api/v1/preview              how an answer reads (student token)
    GET  /api/v1/grades.csv           the gradebook (staff token)
    GET  /api/v1/submissions.csv      the counted answers as `dynagrade grade` reads them
"""

from __future__ import annotations

import datetime as dt
import os
import uuid
from collections import Counter
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Callable

import jinja2
from fastapi import FastAPI, HTTPException, Request
from fastapi.responses import HTMLResponse, JSONResponse, PlainTextResponse, RedirectResponse
from markupsafe import Markup
from pydantic import BaseModel, Field
from starlette.concurrency import run_in_threadpool

from ..exam.solution_policy import solution_visible
from . import db, gradebook, limits
from .exam_data import MAX_ANSWER_CHARS, ExamData
from .grading_pool import Busy, GradingPool
from .submit import Refused, describe, submit

_TEMPLATES = jinja2.Environment(
    loader=jinja2.FileSystemLoader(Path(__file__).resolve().parent / "templates"),
    autoescape=True, trim_blocks=True, lstrip_blocks=True)


class AnswersBody(BaseModel):
    """``POST /api/v1/answers``: one exercise's answers, part name → text."""

    exercise: str = Field(max_length=200)
    answers: dict[str, str]


class PreviewBody(BaseModel):
    """``POST /api/v1/preview``: how one answer reads."""

    exercise: str = Field(max_length=200)
    part: str = Field(max_length=200)
    answer: str = Field(max_length=MAX_ANSWER_CHARS)
    practice: str | None = Field(default=None, max_length=200)


def create_app(manifest: str | os.PathLike, db_url: str | None = None,
               folders: tuple[str, ...] = (), base_url: str = "",
               grading_workers: int = 2,
               clock: Callable[[], dt.datetime] | None = None) -> FastAPI:
    """The server of the exam in ``manifest`` (database: ``db_url`` or SQLite beside it)."""
    from ..exercise.loader import open_bank

    manifest = Path(manifest)
    data = ExamData(manifest, open_bank(folders))
    engine = db.connect(db_url or db.sqlite_url_beside(manifest))
    secret = db.server_secret(engine)
    base = _path_of(base_url)

    @asynccontextmanager
    async def lifespan(app: FastAPI):
        app.state.pool = GradingPool(str(manifest), folders, grading_workers)
        await run_in_threadpool(app.state.pool.warm_up)
        try:
            yield
        finally:
            app.state.pool.close()
            engine.dispose()

    app = FastAPI(title=f"dynagrade serve: {data.title}", lifespan=lifespan,
                  root_path=base, docs_url="/api/docs", redoc_url=None,
                  openapi_url="/api/openapi.json")
    app.add_middleware(limits.BodySizeLimit)
    app.add_middleware(limits.PrivateHeaders)
    app.state.data, app.state.engine, app.state.secret = data, engine, secret
    app.state.limiter = limits.RateLimiter()
    app.state.identities = limits.RecentlySeen()
    app.state.folders = tuple(folders)
    app.state.clock = clock or db.now
    _routes(app, base)
    return app


def _path_of(base_url: str) -> str:
    from urllib.parse import urlparse

    return urlparse(base_url).path.rstrip("/") if base_url else ""


# -- who is asking ------------------------------------------------------------------------


def _holder(request: Request, token: str, role: str) -> db.Identity:
    state = request.app.state
    if not state.limiter.allow(token):
        raise HTTPException(429, "too many requests; slow down", headers={"Retry-After": "1"})
    identity = state.identities.get(token)
    if identity is None:
        identity = db.identify(state.engine, state.data.exam_id, token)
        state.identities.put(token, identity)
    if identity is None or identity.role != role:
        raise HTTPException(401 if identity is None else 403,
                            "unknown link" if identity is None else "not a link for this page")
    return identity


def _bearer(request: Request, role: str) -> db.Identity:
    header = request.headers.get("authorization", "")
    scheme, _, token = header.partition(" ")
    if scheme.lower() != "bearer" or not token.strip():
        raise HTTPException(401, "send the token as 'Authorization: Bearer <token>'",
                            headers={"WWW-Authenticate": "Bearer"})
    return _holder(request, token.strip(), role)


def _practice_seed(state, student_id: str, exercise_id: str, value: str | None) -> int | None:
    """The seed of a signed practice draw ``"<seed>.<signature>"`` (``None`` without)."""
    if not value:
        return None
    seed, _, signature = value.partition(".")
    if not seed.isdigit() or not limits.signed_ok(
            state.secret, f"{student_id}:{exercise_id}:{seed}", signature):
        raise Refused(422, "not a practice variant of this page")
    return int(seed)


def _practice_value(state, student_id: str, exercise_id: str, seed: int) -> str:
    return f"{seed}.{limits.sign(state.secret, f'{student_id}:{exercise_id}:{seed}')}"


# -- routes -------------------------------------------------------------------------------


def _routes(app: FastAPI, base: str) -> None:
    @app.exception_handler(Refused)
    async def refused(request: Request, error: Refused):
        return JSONResponse({"detail": error.message}, status_code=error.status)

    @app.exception_handler(Busy)
    async def busy(request: Request, error: Busy):
        return JSONResponse({"detail": "the server is busy grading; try again shortly"},
                            status_code=503, headers={"Retry-After": "2"})

    @app.get("/healthz", response_class=PlainTextResponse)
    def healthz(request: Request):
        try:
            db.ping(request.app.state.engine)
        except Exception as error:  # any failure of the database is "not healthy"
            return PlainTextResponse(f"database: {type(error).__name__}", status_code=503)
        return "ok"

    @app.post("/api/v1/answers")
    async def api_answers(request: Request, body: AnswersBody):
        identity = await run_in_threadpool(_bearer, request, "student")
        state = request.app.state
        key = request.headers.get("idempotency-key")
        return await submit(state, identity.student_id, body.exercise, body.answers, key,
                            None, state.clock())

    @app.post("/api/v1/preview")
    async def api_preview(request: Request, body: PreviewBody):
        identity = await run_in_threadpool(_bearer, request, "student")
        state = request.app.state
        if body.exercise not in state.data.exercises_meta or \
                body.part not in {p.name for p in state.data.parts(body.exercise)}:
            raise Refused(422, "no such exercise or part in this exam")
        seed = _practice_seed(state, identity.student_id, body.exercise, body.practice)
        read = await state.pool.read(identity.student_id, body.exercise, body.part,
                                     body.answer, seed)
        return read or {"readable": False, "message": "could not be read in time",
                        "formula": None}

    @app.get("/api/v1/grades.csv")
    def api_grades(request: Request):
        _bearer(request, "staff")
        return _csv(request, gradebook.grades_csv, "grades.csv")

    @app.get("/api/v1/submissions.csv")
    def api_submissions(request: Request):
        _bearer(request, "staff")
        return _csv(request, gradebook.responses_csv, "submissions.csv")

    @app.get("/s/{token}", response_class=HTMLResponse)
    def student_page(request: Request, token: str, practice: str | None = None):
        identity = _holder(request, token, "student")
        return HTMLResponse(_student_html(request, token, identity.student_id, practice))

    @app.post("/s/{token}/submit")
    async def student_submit(request: Request, token: str):
        identity, form, exercise_id = await _posted_form(request, token)
        state = request.app.state
        answers = {k[len("answer."):]: str(v) for k, v in form.items()
                   if k.startswith("answer.")}
        practice = form.get("practice") or None
        try:
            seed = _practice_seed(state, identity.student_id, exercise_id, practice)
            await submit(state, identity.student_id, exercise_id, answers,
                         str(form.get("key") or "") or None, seed, state.clock())
        except Refused as error:
            page = await run_in_threadpool(_student_html, request, token,
                                           identity.student_id, None, error.message)
            return HTMLResponse(page, status_code=error.status)
        query = f"?practice={exercise_id}:{practice}" if practice else ""
        return RedirectResponse(f"{base}/s/{token}{query}#{exercise_id}", status_code=303)

    @app.post("/s/{token}/practice")
    async def student_practice(request: Request, token: str):
        identity, _, exercise_id = await _posted_form(request, token)
        state = request.app.state
        if state.data.policy.mode != "practice" or exercise_id not in state.data.exercises_meta:
            raise HTTPException(422, "new variants are offered in practice mode only")
        seed = await run_in_threadpool(state.data.new_practice_seed, exercise_id)
        value = _practice_value(state, identity.student_id, exercise_id, seed)
        return RedirectResponse(f"{base}/s/{token}?practice={exercise_id}:{value}#{exercise_id}",
                                status_code=303)

    @app.get("/i/{token}", response_class=HTMLResponse)
    def staff_page(request: Request, token: str):
        _holder(request, token, "staff")
        return HTMLResponse(_staff_html(request, token))

    @app.get("/i/{token}/grades.csv")
    def staff_grades(request: Request, token: str):
        _holder(request, token, "staff")
        return _csv(request, gradebook.grades_csv, "grades.csv")

    @app.get("/i/{token}/submissions.csv")
    def staff_submissions(request: Request, token: str):
        _holder(request, token, "staff")
        return _csv(request, gradebook.responses_csv, "submissions.csv")

    @app.get("/i/{token}/report.html", response_class=HTMLResponse)
    def staff_report(request: Request, token: str):
        _holder(request, token, "staff")
        state = request.app.state
        stored = db.all_answers(state.engine, state.data.exam_id)
        return HTMLResponse(gradebook.class_report_html(state.data, stored))


async def _posted_form(request: Request, token: str):
    """The student, the form and its exercise of a form posted from a student page,
    after the CSRF check."""
    identity = await run_in_threadpool(_holder, request, token, "student")
    form = await request.form()
    if not limits.csrf_ok(request.app.state.secret, token, form.get("csrf")):
        raise HTTPException(403, "the form is stale or not from this page; reload it")
    return identity, form, str(form.get("exercise", ""))


def _csv(request: Request, render, filename: str) -> PlainTextResponse:
    state = request.app.state
    text = render(state.data, db.all_answers(state.engine, state.data.exam_id))
    return PlainTextResponse(text, media_type="text/csv; charset=utf-8", headers={
        "Content-Disposition": f'attachment; filename="{filename}"',
        "Cache-Control": "no-store"})


# -- pages --------------------------------------------------------------------------------


def _policy_text(policy, now: dt.datetime) -> str:
    words = [policy.mode]
    if policy.closes:
        words.append(f"closes {policy.closes.isoformat()}")
    if policy.attempts:
        words.append(f"{policy.attempts} attempts per part")
    if policy.penalty:
        words.append(f"{round(100 * policy.penalty)} % less per extra attempt")
    words.append("verdicts shown" if policy.shows_verdicts(now) else
                 "answers are checked for readability only; verdicts after the close")
    return " · ".join(words)


def _student_html(request: Request, token: str, student_id: str, practice: str | None,
                  error: str | None = None) -> str:
    from ..render.markup import markdown_to_html

    state = request.app.state
    data: ExamData = state.data
    now = state.clock()
    verdicts = data.policy.shows_verdicts(now)
    stored = db.student_answers(state.engine, data.exam_id, student_id)
    practice_of, _, practice_value = (practice or "").partition(":")
    exercises = []
    for exercise_id in data.exercise_ids:
        meta = data.exercises_meta[exercise_id]
        seed = None
        if practice_of == exercise_id:
            try:
                seed = _practice_seed(state, student_id, exercise_id, practice_value)
            except Refused:
                seed = None
        mine = [a for a in stored if a.exercise_id == exercise_id and
                (a.counted if seed is None else a.seed == seed and not a.counted)]
        last = {a.part: a.raw for a in mine}
        solution = (_solution(data, student_id, exercise_id, mine, now)
                    if seed is None else None)
        exercises.append({
            "id": exercise_id, "title": meta.title, "points": meta.points,
            "statement": Markup(data.statement_html(student_id, exercise_id, seed)),
            "figure": Markup(data.figure_svg(student_id, exercise_id) or "")
            if seed is None else "",
            "parts": data.parts(exercise_id), "key": uuid.uuid4().hex, "last": last,
            "practice": practice_value if seed is not None else None,
            "history": [{"attempt": a.attempt, "counted": a.counted,
                         "time": a.created_at.strftime("%Y-%m-%d %H:%M:%S"),
                         "part": a.part, "raw": a.raw, "message": a.message,
                         "status": a.status, "correct": a.correct,
                         "score": round(a.score, 3), "max_score": round(a.max_score, 3),
                         "feedback": a.feedback} for a in reversed(mine)],
            "solution": Markup(solution) if solution else None})
    is_open = data.policy.is_open(now)
    closed_text = ("The exam is not open yet." if data.policy.opens and now < data.policy.opens
                   else "The exam is closed; answers are no longer accepted.")
    return _TEMPLATES.get_template("student.html").render(
        title=data.title, student=data.students[student_id], token=token, base=_base(request),
        language=data.manifest.exam.language,
        csrf=limits.csrf_field(state.secret, token), exercises=exercises, verdicts=verdicts,
        mode=data.policy.mode, policy_text=_policy_text(data.policy, now), is_open=is_open,
        closed_text=closed_text, error=error, max_chars=MAX_ANSWER_CHARS,
        instructions=Markup(markdown_to_html(data.instructions)) if data.instructions else "",
        submit_label="Save answers" if not verdicts else "Submit")


def _solution(data: ExamData, student_id: str, exercise_id: str, mine: list,
              now: dt.datetime) -> str | None:
    """The worked solution of the student's variant as HTML, once the policy lets them
    see it: after the close, or after the last attempt of every part (``mine``: the
    student's counted answers to the exercise)."""
    policy = data.policy
    closed = policy.closes is not None and now >= policy.closes
    used = Counter(a.part for a in mine)
    out_of_attempts = bool(policy.attempts) and all(
        used[part.name] >= policy.attempts for part in data.manifest_parts[exercise_id])
    if not solution_visible(policy.solutions, closed, policy.shows_verdicts(now),
                            out_of_attempts):
        return None
    return data.solution_html(student_id, exercise_id)


def _staff_html(request: Request, token: str) -> str:
    state = request.app.state
    data: ExamData = state.data
    stored = db.all_answers(state.engine, data.exam_id)
    columns, rows = gradebook.staff_table(data, stored)
    return _TEMPLATES.get_template("staff.html").render(
        title=data.title, token=token, base=_base(request), rows=rows, columns=columns,
        language=data.manifest.exam.language,
        progress=gradebook.progress(data, stored), exercise_ids=data.exercise_ids,
        counts=db.counts(state.engine, data.exam_id), refresh=60,
        policy_text=_policy_text(data.policy, state.clock()))


def _base(request: Request) -> str:
    return request.scope.get("root_path", "")


__all__ = ["create_app", "app_from_environment", "describe"]


def app_from_environment() -> FastAPI:
    """The app ``dynagrade serve`` describes in ``$DYNAGRADE_SERVE`` (one per worker)."""
    import json

    settings = json.loads(os.environ["DYNAGRADE_SERVE"])
    return create_app(settings["manifest"], settings["db"], tuple(settings["folders"]),
                      settings["base_url"], settings["grading_workers"])
