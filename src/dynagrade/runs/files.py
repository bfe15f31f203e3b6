"""Writing output files: atomically, only over what is a file, private where it must be.

Every file dynagrade writes goes through :func:`write_atomic`. It writes a temporary file
in the target's own folder and renames it over the target with :func:`os.replace`, which
is atomic on one file system: a reader sees the old file or the new one, never a part of
either.

A rename replaces whatever has the target's name, so the target is looked at first
(without following a link): it must be a regular file or nothing. A device, FIFO,
socket, folder or symbolic link there is refused with :class:`OutputFileError` and
nothing is written. ``dynagrade links -o /dev/null`` run as root would otherwise replace
the device by a file of secret links, and every later writer to ``/dev/null`` would
fill that file.

``private=True`` is for what only its owner may read (secrets, answer keys, manifests,
students' links): the file is created 0600 and a folder made for it 0700. Other files
get the usual 0666 less the umask.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from ..errors import DynagradeError

#: the mode of a private file, and of a folder made for one
PRIVATE_FILE = 0o600
PRIVATE_FOLDER = 0o700

#: what a file type is called in a refusal
_KINDS = ((stat.S_ISLNK, "a symbolic link"), (stat.S_ISDIR, "a folder"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISFIFO, "a FIFO (named pipe)"), (stat.S_ISSOCK, "a socket"))


class OutputFileError(DynagradeError, OSError):
    """An output file cannot be written there; the message names the path and why."""


def refuse_unless_replaceable(path: str | os.PathLike) -> None:
    """Raise :class:`OutputFileError` unless ``path`` is a regular file or nothing (a
    link is refused, not followed)."""
    try:
        mode = os.lstat(path).st_mode
    except FileNotFoundError:
        return
    except OSError as error:
        raise OutputFileError(f"{path}: cannot write here ({error.strerror})") from None
    if stat.S_ISREG(mode):
        return
    kind = next((name for test, name in _KINDS if test(mode)), "not a regular file")
    raise OutputFileError(f"{path}: is {kind}, not a regular file; dynagrade writes only "
                          "a new file or over a regular one (give another path)")


def write_atomic(path: str | os.PathLike, data: bytes | str, private: bool = False) -> Path:
    """Write ``data`` (text is encoded as UTF-8) to ``path`` atomically; returns the path.
    ``private`` files are 0600 (and a folder made for them 0700)."""
    path = Path(path)
    refuse_unless_replaceable(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    created = False
    try:
        descriptor = _create(temporary, private)
        created = True
        with os.fdopen(descriptor, "wb") as handle:
            handle.write(payload)
        refuse_unless_replaceable(path)  # made a device or link while we wrote
        os.replace(temporary, path)
    except BaseException as error:
        if created:
            temporary.unlink(missing_ok=True)
        if isinstance(error, OSError) and not isinstance(error, DynagradeError):
            raise OutputFileError(f"{path}: cannot write the file "
                                  f"({error.strerror or error})") from None
        raise
    return path


def _create(temporary: Path, private: bool) -> int:
    """Open ``temporary`` as a new file (never through a link). Its folder is made, and a
    file of that name left by a killed run of this process id removed, only when the
    first attempt finds them needed: an exam writes thousands of files, and each check
    done in advance is a system call per file."""
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW
    mode = PRIVATE_FILE if private else 0o666
    try:
        return os.open(temporary, flags, mode)
    except FileNotFoundError:
        make_folder(temporary.parent, private)
    except FileExistsError:
        temporary.unlink()
    return os.open(temporary, flags, mode)


def make_folder(folder: str | os.PathLike, private: bool = False) -> Path:
    """Make ``folder`` (and its parents) unless it exists; a private one is 0700."""
    folder = Path(folder)
    if not folder.is_dir():
        try:
            folder.mkdir(PRIVATE_FOLDER if private else 0o777, parents=True, exist_ok=True)
        except OSError as error:
            raise OutputFileError(f"{folder}: cannot make the folder "
                                  f"({error.strerror or error})") from None
    return folder


def create_private(path: str | os.PathLike) -> None:
    """Create ``path`` as an empty 0600 file unless it exists (a regular file), so that
    a program that then opens it (SQLite) keeps that mode; its folder is made 0700."""
    path = Path(path)
    refuse_unless_replaceable(path)
    make_folder(path.parent, private=True)
    try:
        os.close(os.open(path, os.O_WRONLY | os.O_CREAT | os.O_NOFOLLOW, PRIVATE_FILE))
    except OSError as error:
        raise OutputFileError(f"{path}: cannot create the file "
                              f"({error.strerror or error})") from None
