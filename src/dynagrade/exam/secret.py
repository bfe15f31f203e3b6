"""An exam's secret: where it comes from when it is not drawn fresh.

Every ``dynagrade exam`` run draws a new random secret unless ``--secret-file FILE``
names one: an existing file's secret is used (so a re-run, or a test, gives the same
variants and byte-identical files), a missing file is created holding a new secret
(readable by its owner only). The secret is also stored in the manifest, which the
staff keep as they keep the key.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import DynagradeError
from ..exercise.datafile import DataFileError, read_data_file
from ..exercise.seeds import new_secret
from ..runs.files import write_atomic

MIN_SECRET_CHARACTERS = 32
MAX_SECRET_BYTES = 4096


class SecretError(DynagradeError, ValueError):
    """The secret file cannot be used; the message names it and why."""


def load_secret(path: str | os.PathLike) -> str:
    """The secret in ``path``, written there first (a new random one) when missing."""
    path = Path(path)
    if not path.exists() and not path.is_symlink():
        secret = new_secret()
        write_atomic(path, secret + "\n", private=True)
        return secret
    try:
        secret = read_data_file(path, MAX_SECRET_BYTES).decode("ascii").strip()
    except (DataFileError, UnicodeDecodeError) as error:
        raise SecretError(f"{path}: not an exam secret ({error})") from None
    if len(secret) < MIN_SECRET_CHARACTERS or not secret.isprintable() or " " in secret:
        raise SecretError(f"{path}: an exam secret is one word of at least "
                          f"{MIN_SECRET_CHARACTERS} characters (a missing file gets a "
                          "random one)")
    return secret
