"""``dynagrade serve`` and ``dynagrade links``: the command-line side of the server.

Only click is imported here; the server's dependencies load when a command runs.
"""

from __future__ import annotations

import os
from pathlib import Path

import click

_DB_HELP = ("Database URL: sqlite:///path or postgresql://user@host/db "
            "(default: serve.sqlite3 beside the manifest).")


def _open(manifest: str, db_url: str | None, folders):
    from ..classgrade.grade import ManifestError
    from ..exercise.loader import open_bank
    from . import db
    from .exam_data import ExamData

    try:
        data = ExamData(manifest, open_bank(folders))
        engine = db.connect(db_url or db.sqlite_url_beside(Path(manifest)))
    except ManifestError as error:
        raise click.ClickException(str(error)) from None
    except Exception as error:  # a database that cannot be reached or opened
        if type(error).__module__.startswith(("sqlalchemy", "psycopg", "sqlite3", "alembic")):
            raise click.ClickException(f"cannot open the database: {error}") from None
        raise
    return data, engine


@click.command()
@click.argument("manifest", type=click.Path(exists=True, dir_okay=False))
@click.option("--db", "db_url", help=_DB_HELP)
@click.option("-o", "--output", type=click.Path(dir_okay=False), default="links.csv",
              show_default=True, help="Where to write student_id,name,email,url.")
@click.option("--base-url", default="http://127.0.0.1:8000", show_default=True,
              help="The address students open (the reverse proxy's, in production).")
@click.option("--rotate", is_flag=True, help="Revoke every student link and make new ones.")
@click.option("--instructor", is_flag=True, help="Also make and print a staff link.")
@click.pass_obj
def links(context, manifest, db_url, output, base_url, rotate, instructor):
    """Write one secret link per roster student (tokens are stored hashed)."""
    from . import db
    from .links import staff_url, write_links

    data, engine = _open(manifest, db_url, context.folders)
    notices = write_links(data, engine, Path(output), base_url, rotate=rotate)
    for notice in notices:
        click.echo(f"warning: {notice}", err=True)
    click.echo(f"wrote {output}: {len(data.students)} student links")
    if instructor:
        click.echo(f"staff link: {staff_url(base_url, db.issue_staff_token(engine, data.exam_id))}")


@click.command()
@click.argument("manifest", type=click.Path(exists=True, dir_okay=False))
@click.option("--db", "db_url", help=_DB_HELP)
@click.option("--host", default="127.0.0.1", show_default=True)
@click.option("--port", type=click.IntRange(1, 65535), default=8000, show_default=True)
@click.option("--base-url", default="", help="The public address, when behind a reverse "
              "proxy under a path (e.g. https://exams.example.org/dynamics).")
@click.option("--workers", type=click.IntRange(1, 64), default=1, show_default=True,
              help="Server processes (each with its own grading pool).")
@click.option("--grading-workers", type=click.IntRange(1, 64), default=2, show_default=True,
              help="Grading processes per server process.")
@click.pass_obj
def serve(context, manifest, db_url, host, port, base_url, workers, grading_workers):
    """Serve the exam or homework that `dynagrade exam` generated."""
    import uvicorn

    from .state import ENVIRONMENT, Settings

    data, engine = _open(manifest, db_url, context.folders)  # migrate once, fail early
    engine.dispose()
    os.environ[ENVIRONMENT] = Settings(Path(manifest), db_url, tuple(context.folders),
                                       base_url, grading_workers).to_json()
    click.echo(f"serving {data.title!r} ({data.policy.mode}) on http://{host}:{port}")
    uvicorn.run("dynagrade.serve.app:app_from_environment", factory=True, host=host,
                port=port, workers=workers, proxy_headers=True, log_level="info")
