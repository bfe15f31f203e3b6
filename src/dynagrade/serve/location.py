"""Where an exam's data lives, and the mark of a folder being served.

The default database of the exam whose manifest is ``out/manifest.json`` is the SQLite
file ``out.serve.sqlite3`` *beside* the folder (:func:`dynagrade.runs.outputs.database_beside`),
never inside it: ``dynagrade exam -o out`` replaces the folder whole, and refuses to while
that database exists (:func:`dynagrade.runs.outputs.refuse_if_in_use`).

Earlier versions kept ``serve.sqlite3`` inside the folder. Such a database is used where it
is, with a warning (moving a live SQLite file is unsafe while an older server may still
write to it); the folder holding it is then never replaced either.

While ``dynagrade serve`` runs it holds a shared lock on a mark file in the exam folder
(:func:`serving`), which ``dynagrade exam`` checks for liveness: a mark left by a killed
server holds no lock and counts for nothing.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
from pathlib import Path
from typing import Iterator

from ..i18n import _
from ..runs.outputs import SERVING_MARK, database_beside

#: the database's name inside the exam folder, where earlier versions kept it
OLD_NAME = "serve.sqlite3"


def default_database(manifest: Path) -> Path:
    """The SQLite file the exam of ``manifest`` uses when no ``--db`` is given."""
    folder = Path(manifest).resolve().parent
    old, new = folder / OLD_NAME, database_beside(folder)
    return old if old.exists() and not new.exists() else new


def database_notices(manifest: Path) -> list[str]:
    """Warnings about the default database's place, for the command line."""
    folder = Path(manifest).resolve().parent
    old, new = folder / OLD_NAME, database_beside(folder)
    if not old.exists():
        return []
    if new.exists():
        return [_("{old} is not used: the exam's database is {new} (earlier versions kept "
                  "it inside the exam folder); move {old} away once you have checked it "
                  "holds nothing you need").format(old=old, new=new)]
    return [_("the database {old} is inside the exam folder, where earlier versions kept "
              "it; it is used where it is, and `dynagrade exam` will not replace this "
              "folder. To move it to {new}: stop the server, then move {old} (with any "
              "-wal and -shm files beside it)").format(old=old, new=new)]


@contextlib.contextmanager
def serving(folder: Path) -> Iterator[None]:
    """Mark ``folder`` as being served for the duration of the block (a shared lock on
    its mark file, holding this process's id); several servers may hold it at once."""
    mark = Path(folder) / SERVING_MARK
    handle = None
    with contextlib.suppress(OSError):  # a read-only exam folder: no mark, still served
        handle = open(mark, "a+")
        fcntl.flock(handle, fcntl.LOCK_SH)
        handle.seek(0)
        handle.truncate()
        handle.write(str(os.getpid()))
        handle.flush()
    try:
        yield
    finally:
        if handle is not None:
            fcntl.flock(handle, fcntl.LOCK_UN)
            handle.close()
