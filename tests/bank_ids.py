"""The shipped bank's exercise ids that test modules are parametrized over, read once.

Parametrizing over the bank happens at collection, before any test runs: every id the
files declare (their text is read, no file is run), or the ids of the exercises with a
figure, which needs the listing ``dynagrade list`` shows (every file parsed with
:mod:`ast`, the few that compute a listed value loaded). Each module asking its own bank
paid for that again; a listing costs about a fifth of a second. Here each is read once
per process and shared::

    @pytest.mark.parametrize("exercise_id", figured_ids())

The tests themselves still load exercises from a bank of their own (or the ``bank``
fixture), so nothing loaded at collection is shared with them.
"""

from __future__ import annotations

from functools import cache

from dynagrade.exercise import open_bank


@cache
def _bank():
    """One bank for reading ids, so that its index of files is built once."""
    return open_bank()


@cache
def bank_ids() -> tuple[str, ...]:
    """Every id the bank's files declare, sorted; no exercise file is run."""
    return tuple(_bank().ids())


@cache
def figured_ids() -> tuple[str, ...]:
    """The ids of the bank's exercises that draw a figure, sorted."""
    return tuple(sorted(listing.id for listing in _bank().listing() if listing.figured))
