"""Output folders that hold exactly one complete run.

``dynagrade exam`` and ``dynagrade grade -o DIR`` build their files in a staging folder
beside the target (``.DIR.partial``, on the same file system) and only when everything
is written swap it in: the run that was in ``DIR`` moves to ``DIR.previous`` (replacing
an older one there) and the staging folder becomes ``DIR``. So:

- ``DIR`` never mixes files of two runs (no feedback of 600 students beside a 20-row
  gradebook; no PDFs of an earlier run beside a ``--no-pdf`` one);
- a run killed at any moment leaves ``DIR`` as the previous complete run (or, for the
  instant between the two renames, absent with that run at ``DIR.previous``), and a
  staging folder that the next run removes before it starts;
- the previous run is kept, once, as ``DIR.previous``: a re-grade by mistake can be
  undone by hand, and nothing older piles up.

An exam folder that students answer in is never replaced (:func:`refuse_if_in_use`):
not while ``dynagrade serve`` serves it (it holds a lock on :data:`SERVING_MARK` in the
folder), not when the folder holds a database (where earlier versions kept it), and not
once the exam has its database beside the folder (:func:`database_beside`): a new run
would give every student new numbers under the answers already stored.
"""

from __future__ import annotations

import fcntl
import os
import shutil
from pathlib import Path

from ..errors import DynagradeError
from ..i18n import _


class OutputFolderError(DynagradeError, OSError):
    """The output folder cannot be written; the message names it and why."""


def staging_folder(target: str | os.PathLike) -> Path:
    """A fresh, empty staging folder beside ``target`` (a stale one from a killed run is
    removed first)."""
    target = Path(target)
    if not target.name or target.name == ".." or target.resolve() == Path.cwd().resolve():
        raise OutputFolderError(f"{target}: give a folder of its own to write into (the run "
                                "replaces it whole), not the current or a parent folder")
    staging = target.with_name(f".{target.name}.partial")
    try:
        if target.exists() and not target.is_dir():
            raise OutputFolderError(f"{target}: exists and is not a folder")
        target.parent.mkdir(parents=True, exist_ok=True)
        if staging.exists():
            shutil.rmtree(staging)
        staging.mkdir(0o700)  # the run's key, manifest and grades are for staff only
    except OutputFolderError:
        raise
    except OSError as error:
        raise OutputFolderError(f"{target}: cannot write the output folder here "
                                f"({error.strerror or error})") from None
    return staging


def previous_folder(target: str | os.PathLike) -> Path:
    """Where the run that was in ``target`` is kept after a new one is swapped in."""
    target = Path(target)
    return target.with_name(f"{target.name}.previous")


def swap_in(staging: Path, target: str | os.PathLike) -> Path:
    """Make the complete ``staging`` folder the ``target``; the old target becomes
    ``target.previous``."""
    target = Path(target)
    previous = previous_folder(target)
    try:
        if target.exists():
            if previous.exists():
                shutil.rmtree(previous)
            os.replace(target, previous)
        os.replace(staging, target)
    except OSError as error:
        raise OutputFolderError(f"{target}: cannot put the new run in place "
                                f"({error.strerror or error}); it is complete in "
                                f"{staging}") from None
    return target


# -- exam folders in use ------------------------------------------------------------------

#: the file ``dynagrade serve`` keeps in the exam folder it serves, locked (shared) for as
#: long as it runs and holding its process id; a lock, not the file, says it runs
SERVING_MARK = ".dynagrade-serving"

#: database files (SQLite and its companions) that mark a folder as holding answers
_DATABASE_PATTERNS = ("*.sqlite3", "*.sqlite3-wal", "*.sqlite", "*.db")


def database_beside(folder: str | os.PathLike) -> Path:
    """The default database of the exam in ``folder``: ``<folder>.serve.sqlite3`` beside
    the folder (never inside it, so that no run replaces it)."""
    folder = Path(folder).resolve()
    return folder.with_name(f"{folder.name}.serve.sqlite3")


def serving_pid(folder: str | os.PathLike) -> int | None:
    """The process id of the ``dynagrade serve`` serving ``folder``, or ``None`` when no
    server holds the folder's lock (a mark left by a killed server is not a server)."""
    mark = Path(folder) / SERVING_MARK
    try:
        handle = open(mark, "r+")
    except OSError:
        return None
    with handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            text = handle.read().strip()
            return int(text) if text.isdigit() else 0
        fcntl.flock(handle, fcntl.LOCK_UN)
        return None


def refuse_if_in_use(target: str | os.PathLike) -> None:
    """Raise :class:`OutputFolderError` when replacing ``target`` would lose or orphan
    students' answers: it is being served, holds a database, or has one beside it."""
    target = Path(target)
    if not target.is_dir():
        return
    pid = serving_pid(target)
    if pid is not None:
        raise OutputFolderError(_(
            "{folder}: `dynagrade serve` is serving this exam (process {pid}); a new run "
            "would replace the folder under it. Change opens, closes, attempts or feedback "
            "with `dynagrade policy` (no new run needed); to generate anyway, stop the "
            "server and write to another folder").format(folder=target, pid=pid))
    held = sorted(p.name for pattern in _DATABASE_PATTERNS for p in target.glob(pattern))
    if held:
        raise OutputFolderError(_(
            "{folder}: holds a database ({files}) with the students' links and answers; a "
            "new run would move it away. Change the policy with `dynagrade policy`, or move "
            "the database out of the folder first").format(folder=target,
                                                           files=", ".join(held)))
    beside = database_beside(target)
    if beside.exists():
        raise OutputFolderError(_(
            "{folder}: this exam has a database ({database}) with its links and answers; "
            "a new run would give every student new numbers. Change opens, closes, "
            "attempts or feedback with `dynagrade policy`; to start a new exam, write to "
            "another folder (or move the database away first)").format(folder=target,
                                                                        database=beside))
