"""The interface's languages: every fixed string a person reads comes from a gettext
message catalog (``locale/<language>/LC_MESSAGES/dynagrade.po``, read with Babel).

Usage, in any layer (like :mod:`dynagrade.errors`, this module imports nothing of
dynagrade)::

    from dynagrade.i18n import _, language

    message = _("not answered")                      # in the active language
    with language("de"):
        message = _("{n} of {total} components are right").format(n=2, total=3)

The active language is a context variable, so each request of the server (and each
task of its event loop) has its own; outside any ``language(...)`` block it is English,
the language the messages are written in, and no catalog is read at all (so ``grade
exercise.py`` imports no Babel). A message missing from a catalog is shown in English.
Exercise statements and worked solutions are the author's and are never translated.

Catalogs are kept as ``.po`` text (the translators' format) and read once per process;
``tests/test_i18n.py`` extracts every marked message from the sources and templates and
requires each catalog to translate all of them.
"""

from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from functools import lru_cache
from importlib import resources
from typing import Iterator, Protocol

#: the language messages are written in
SOURCE_LANGUAGE = "en"
#: the languages the interface speaks (a catalog each, but the source language)
LANGUAGES = ("en", "de")
#: the catalogs' domain: ``locale/<language>/LC_MESSAGES/<DOMAIN>.po``
DOMAIN = "dynagrade"

_active: ContextVar[str] = ContextVar("dynagrade_language", default=SOURCE_LANGUAGE)


class Catalog(Protocol):
    """What a loaded catalog answers (Babel's ``Translations``)."""

    def gettext(self, message: str) -> str: ...

    def ngettext(self, singular: str, plural: str, n: int) -> str: ...


def supported(code: str | None) -> str:
    """``code`` if the interface speaks it (``de-CH`` is ``de``), else English."""
    base = (code or "").replace("_", "-").split("-")[0].lower()
    return base if base in LANGUAGES else SOURCE_LANGUAGE


def active() -> str:
    """The language messages are shown in now."""
    return _active.get()


@contextmanager
def language(code: str | None) -> Iterator[str]:
    """Show messages in ``code`` (a language the interface speaks, else English) within
    the block; yields the language chosen."""
    chosen = supported(code)
    token = _active.set(chosen)
    try:
        yield chosen
    finally:
        _active.reset(token)


def _(message: str) -> str:
    """``message`` in the active language."""
    code = _active.get()
    return message if code == SOURCE_LANGUAGE else catalog(code).gettext(message)


def ngettext(singular: str, plural: str, n: int) -> str:
    """``singular`` or ``plural`` for ``n``, in the active language."""
    code = _active.get()
    if code == SOURCE_LANGUAGE:
        return singular if n == 1 else plural
    return catalog(code).ngettext(singular, plural, n)


def N_(message: str) -> str:
    """Mark ``message`` for the catalogs without translating it here (a table of words
    translated where it is shown)."""
    return message


@lru_cache(maxsize=None)
def catalog(code: str) -> Catalog:
    """The catalog of ``code``, read once from its ``.po`` file."""
    from babel.messages.mofile import write_mo
    from babel.messages.pofile import read_po
    from babel.support import Translations
    import io

    source = resources.files("dynagrade") / "locale" / code / "LC_MESSAGES" / f"{DOMAIN}.po"
    with source.open("rb") as handle:
        messages = read_po(handle, locale=code, domain=DOMAIN)
    compiled = io.BytesIO()
    write_mo(compiled, messages, use_fuzzy=False)
    compiled.seek(0)
    return Translations(compiled, domain=DOMAIN)
