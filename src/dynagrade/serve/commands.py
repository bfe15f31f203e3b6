"""``dynagrade serve`` and ``dynagrade links``: the command-line side of the server.

Only click is imported here; the server's dependencies load when a command runs.
"""

from __future__ import annotations

import os
from pathlib import Path

import click

_DB_HELP = ("Database URL: sqlite:///path or postgresql://user@host/db "
            "(default: OUT.serve.sqlite3 beside the exam folder OUT).")


def _open(manifest: str, db_url: str | None, folders):
    from ..classgrade.grade import ManifestError
    from ..exercise.loader import open_bank
    from . import db
    from .exam_data import ExamData
    from .location import database_notices

    if db_url is None:
        for notice in database_notices(Path(manifest)):
            click.echo(f"warning: {notice}", err=True)
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
@click.option("--name", "label", metavar="NAME", help="The new staff link's name, which "
              "the audit log shows as who made a change (e.g. 'Anna (TA)').")
@click.option("--list-staff", is_flag=True, help="List the staff links (id, name, made, "
              "revoked) and write nothing.")
@click.option("--revoke-staff", "revoke", metavar="ID", multiple=True, help="Revoke the "
              "staff link with this id (from --list-staff; 'all' for every one) and write "
              "nothing else. Refused by every server within 30 s.")
@click.option("--by", "actor", help="Who acts, for the audit log (default: your user name).")
@click.pass_obj
def links(context, manifest, db_url, output, base_url, rotate, instructor, label,
          list_staff, revoke, actor):
    """Write one secret link per roster student (tokens are stored hashed); make, list
    or revoke staff links."""
    import getpass

    from .links import LinkError, add_staff_link, revoke_staff_links, staff_url, write_links

    data, engine = _open(manifest, db_url, context.folders)
    who = actor or f"{getpass.getuser()} (command line)"
    try:
        if revoke:
            ids = None if "all" in revoke else list(revoke)
            done = revoke_staff_links(engine, data.exam_id, ids, who)
            click.echo(f"revoked {len(done)} staff link(s)"
                       + "".join(f"\n  {link.id} {link.label or ''}".rstrip() for link in done))
        if list_staff:
            _list_staff_links(engine, data.exam_id)
        if revoke or list_staff:
            return
        notices = write_links(data, engine, Path(output), base_url, rotate=rotate)
        for notice in notices:
            click.echo(f"warning: {notice}", err=True)
        click.echo(f"wrote {output}: {len(data.students)} student links")
        if instructor:
            token = add_staff_link(engine, data.exam_id, label, who)
            click.echo(f"staff link: {staff_url(base_url, token)}")
    except LinkError as error:
        raise click.ClickException(str(error)) from None
    finally:
        engine.dispose()


def _list_staff_links(engine, exam_id: str) -> None:
    from . import db

    for link in db.staff_links(engine, exam_id):
        made = db.utc(link.created_at).isoformat(timespec="seconds")
        state = f"revoked {db.utc(link.revoked_at).isoformat(timespec='seconds')}" \
            if link.revoked_at else "active"
        click.echo(f"{link.id}  {link.label or '(no name)'}  made {made}  {state}")


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
@click.option("--access-log", is_flag=True, help="Log every request on standard error "
              "(tokens shown as the start of their hash). Off by default: at a class's "
              "rate the log costs CPU that submits need; the proxy's log has the requests.")
@click.pass_obj
def serve(context, manifest, db_url, host, port, base_url, workers, grading_workers,
          access_log):
    """Serve the exam or homework that `dynagrade exam` generated."""
    import uvicorn

    from .location import serving
    from .state import ENVIRONMENT, Settings

    data, engine = _open(manifest, db_url, context.folders)  # migrate once, fail early
    engine.dispose()
    os.environ[ENVIRONMENT] = Settings(Path(manifest), db_url, tuple(context.folders),
                                       base_url, grading_workers).to_json()
    click.echo(f"serving {data.title!r} ({data.policy.mode}) on http://{host}:{port}")
    with serving(Path(manifest).resolve().parent):  # `dynagrade exam` keeps off the folder
        uvicorn.run("dynagrade.serve.app:app_from_environment", factory=True, host=host,
                    port=port, workers=workers, proxy_headers=True, log_level="info",
                    access_log=access_log)


@click.command("policy")
@click.argument("manifest", type=click.Path(exists=True, dir_okay=False))
@click.option("--db", "db_url", help=_DB_HELP)
@click.option("--opens", metavar="TIME", help="Opening time with its offset, e.g. "
              "2025-04-14T08:00:00+02:00 ('' for none).")
@click.option("--closes", metavar="TIME", help="Closing time with its offset ('' for none).")
@click.option("--attempts", metavar="N", help="Answers per part (0: no limit).")
@click.option("--penalty", metavar="X", help="Fraction of the points lost per extra attempt.")
@click.option("--feedback", type=click.Choice(["immediate", "after-close"]))
@click.option("--counts", type=click.Choice(["best", "last"]))
@click.option("--solutions", type=click.Choice(["with-feedback", "after-close",
                                                 "after-last-attempt", "never"]))
@click.option("--time-limit", metavar="MINUTES", help="Minutes each student has from "
              "pressing Start (0: untimed).")
@click.option("--by", "actor", help="Who makes the change, for the audit log "
              "(default: your user name).")
@click.pass_obj
def policy(context, manifest, db_url, actor, **values):
    """Show or change the policy of an exam being served, without generating it again.

    With no option: the policy in force and every recorded change. With options: the
    change is validated as exam.toml's policy is, recorded (who, when, before, after)
    and in force on every server within seconds.
    """
    import getpass

    from ..exam.policy import PolicyError
    from .policy_changes import change_policy, describe_change, in_force

    data, engine = _open(manifest, db_url, context.folders)
    changes = {key: value for key, value in values.items() if value is not None}
    try:
        if changes:
            who = actor or f"{getpass.getuser()} (command line)"
            before, after = change_policy(engine, data.exam_id, data.manifest_policy, who,
                                          changes)
            lines = describe_change(before, after)
            click.echo("\n".join(["changed:", *lines]) if lines else "nothing changed")
        else:
            _show_policy(data, engine, in_force(engine, data.exam_id, data.manifest_policy))
    except PolicyError as error:
        raise click.ClickException(str(error)) from None
    finally:
        engine.dispose()


def _show_policy(data, engine, current) -> None:
    from . import db

    for key, value in current.to_json().items():
        click.echo(f"{key} = {'' if value is None else value}")
    for entry in reversed(db.changes(engine, data.exam_id, db.POLICY_CHANGE)):
        click.echo(f"{entry.at.isoformat(timespec='seconds')} by {entry.actor}: "
                   f"{entry.before} -> {entry.after}")
