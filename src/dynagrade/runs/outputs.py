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
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

from ..errors import DynagradeError


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
        staging.mkdir()
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
