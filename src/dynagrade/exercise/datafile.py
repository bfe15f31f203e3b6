"""Reading a file that someone handed in as data: a regular file, size checked first.

A fill-in file, a responses CSV or a roster may be anything a student or a download put
in a folder: a symbolic link to ``/etc/passwd``, ``/dev/zero``, a FIFO that never ends.
:func:`read_data_file` opens without blocking, looks at what it opened (``fstat``), and
reads only a regular file no larger than the limit, so no path is followed into a device
and no read is unbounded.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from ..errors import DynagradeError


class DataFileError(DynagradeError, ValueError):
    """The file cannot be read as data; the message says why (never the file's content)."""


def file_kind(mode: int) -> str:
    """What a file of ``mode`` is, in words ("a FIFO", "a device", ...)."""
    if stat.S_ISLNK(mode):
        return "a symbolic link"
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "a regular file" if stat.S_ISREG(mode) else "not a regular file"


def read_data_file(path: str | os.PathLike, limit: int) -> bytes:
    """The bytes of the regular file ``path``; :class:`DataFileError` when it is not a
    regular file, cannot be opened, or holds more than ``limit`` bytes."""
    path = Path(path)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        descriptor = os.open(path, flags)
    except OSError as error:
        raise DataFileError(f"cannot read the file ({error.strerror})") from None
    with os.fdopen(descriptor, "rb") as handle:
        mode = os.fstat(descriptor).st_mode
        if not stat.S_ISREG(mode):
            raise DataFileError(f"it is {file_kind(mode)}, not a regular file")
        size = os.fstat(descriptor).st_size
        if size > limit:
            raise DataFileError(f"{size} bytes is too large (the limit is {limit})")
        data = handle.read(limit + 1)
    if len(data) > limit:
        raise DataFileError(f"more than {limit} bytes is too large")
    return data
