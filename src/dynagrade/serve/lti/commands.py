"""``dynagrade lti``: register a platform, print what its registration form asks for,
rotate the tool's key. Only click is imported here; the rest loads when a command runs.
"""

from __future__ import annotations

import json
from pathlib import Path

import click

_DB_HELP = ("Database URL: sqlite:///path or postgresql://user@host/db "
            "(default: OUT.serve.sqlite3 beside the exam folder OUT).")


def _engine(manifest: str, db_url: str | None):
    from .. import db

    try:
        return db.connect(db_url or db.sqlite_url_beside(Path(manifest)))
    except Exception as error:  # a database that cannot be reached or opened
        if type(error).__module__.startswith(("sqlalchemy", "psycopg", "sqlite3", "alembic")):
            raise click.ClickException(f"cannot open the database: {error}") from None
        raise


@click.group()
def lti():
    """LTI 1.3: launch `dynagrade serve` from Moodle or Canvas (docs/lti.md)."""


_manifest = click.argument("manifest", type=click.Path(exists=True, dir_okay=False))
_db = click.option("--db", "db_url", help=_DB_HELP)


@lti.command()
@_manifest
@_db
@click.option("--issuer", required=True, help="The platform's issuer ('Platform ID' in "
              "Moodle; https://canvas.instructure.com for Canvas cloud).")
@click.option("--client-id", required=True, help="The client id the platform gave the tool.")
@click.option("--deployment-id", "deployment_ids", required=True, multiple=True,
              help="A deployment id the platform gave the tool (repeat for several).")
@click.option("--auth-url", required=True, help="The platform's authentication request "
              "URL (Moodle: .../mod/lti/auth.php).")
@click.option("--token-url", required=True, help="The platform's access token URL "
              "(Moodle: .../mod/lti/token.php).")
@click.option("--jwks-url", required=True, help="The platform's public keyset URL "
              "(Moodle: .../mod/lti/certs.php).")
@click.option("--user-claim", type=click.Choice(["email", "sub", "sourcedid"]),
              default="email", show_default=True, help="How a launching student is found "
              "on the roster: by email, by the platform's user id (= student_id), or by "
              "the LIS person sourcedid, Moodle's ID number (= student_id).")
def register(manifest, db_url, issuer, client_id, deployment_ids, auth_url, token_url,
             jwks_url, user_claim):
    """Register a platform (again: replace its registration)."""
    from . import keys, store

    engine = _engine(manifest, db_url)
    platform = store.register(engine, issuer, client_id, list(deployment_ids), auth_url,
                              token_url, jwks_url, user_claim)
    keys.signing_key(engine)
    click.echo(f"registered {platform.issuer} (client {platform.client_id}, deployments "
               f"{', '.join(platform.deployment_ids)}; students found by {user_claim})")


@lti.command()
@_manifest
@_db
@click.option("--base-url", required=True, help="The address the server is reached at "
              "(as for `dynagrade serve --base-url`).")
def show(manifest, db_url, base_url):
    """Print the values Moodle's and Canvas's registration forms ask for."""
    from . import keys, setup, store

    engine = _engine(manifest, db_url)
    urls = setup.ToolUrls(base_url.rstrip("/"))
    click.echo("Moodle (Manage tools -> configure a tool manually) and Canvas "
               "(Developer Keys -> LTI key):")
    for name, value in urls.fields():
        click.echo(f"  {name}: {value}")
    click.echo(f"  tool key in use: {keys.signing_key(engine).kid}")
    click.echo("Canvas JSON configuration (Method: Paste JSON):")
    click.echo(json.dumps(setup.canvas_json(urls, "Exercises and exams of the Dynamics "
                                            "course"), indent=2))
    for platform in store.all_platforms(engine):
        click.echo(f"registered: {platform.issuer} client {platform.client_id} "
                   f"deployments {', '.join(platform.deployment_ids)} "
                   f"(students by {platform.user_claim})")


@lti.command("rotate-key")
@_manifest
@_db
@click.option("--retire-old", is_flag=True, help="Withdraw every key but the newest "
              "(after the platforms fetched the new key set; a day after rotating).")
def rotate_key(manifest, db_url, retire_old):
    """Make a new tool key that signs from now on; the old ones stay published until
    --retire-old."""
    from . import keys

    engine = _engine(manifest, db_url)
    if retire_old:
        gone = keys.retire(engine)
        click.echo(f"retired {', '.join(gone) or 'nothing'}; signing with "
                   f"{keys.signing_key(engine).kid}")
        return
    click.echo(f"new key {keys.rotate(engine)} signs from now on; the older keys stay "
               "published until `dynagrade lti rotate-key --retire-old`")


@lti.command()
@_manifest
@_db
@click.option("-o", "--output", type=click.Path(dir_okay=False), help="Write the learners "
              "the roster lacks here, as roster rows (student_id,name,email) to add to "
              "roster.csv before the exam is generated again.")
def roster(manifest, db_url, output):
    """Import the course's members from the platform (NRPS) and merge them with the
    roster by the registered claim: link those it holds, list the rest."""
    from ...exam.csvcells import csv_text
    from ...exam.manifest import load
    from ...runs.files import write_atomic
    from .. import db
    from . import roster_import

    engine = _engine(manifest, db_url)
    exam = load(Path(manifest))
    students = {s.student_id: s for s in exam.students}
    try:
        found = roster_import.import_roster(engine, exam.exam.id, students, db.now())
    except roster_import.ImportFailed as error:
        raise click.ClickException(str(error)) from None
    click.echo(f"{len(found.linked)} learners linked to the roster ({found.new_links} new); "
               f"{len(found.unknown)} not on the roster; {len(found.unlisted)} roster "
               "students the platform does not list")
    for learner in found.unknown:
        click.echo(f"  not on the roster: {learner.name} <{learner.email}> "
                   f"(id number {learner.sourcedid or '-'}, platform id {learner.sub})")
    for student_id in found.unlisted:
        click.echo(f"  not listed by the platform: {student_id}")
    if output:
        rows = [("student_id", "name", "email")] + [
            (learner.sourcedid or learner.sub, learner.name, learner.email)
            for learner in found.unknown]
        write_atomic(output, csv_text(rows), private=True)
        click.echo(f"wrote {len(found.unknown)} rows to {output}")
