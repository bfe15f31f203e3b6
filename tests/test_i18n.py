"""The interface's languages: every marked message of the sources and templates has a
translation in every catalog, and the active language is the one asked for."""

from __future__ import annotations

from pathlib import Path

import pytest

import dynagrade
from dynagrade import i18n

SOURCE = Path(dynagrade.__file__).parent
#: where messages are marked: the Python sources (but the mechanics core and the bank,
#: which speak to no one) and the templates of the server
METHODS = [("mechanics/**.py", "ignore"), ("**.py", "python"),
           ("serve/templates/**.html", "jinja2")]
KEYWORDS = {"_": None, "N_": None, "ngettext": (1, 2)}


def marked_messages() -> dict[str, str]:
    """Every marked message (the singular of a plural pair) and where it is first marked."""
    from babel.messages.extract import extract_from_dir

    found: dict[str, str] = {}
    for filename, line, message, _comments, _context in extract_from_dir(
            str(SOURCE), METHODS, keywords=KEYWORDS, comment_tags=()):
        key = message[0] if isinstance(message, tuple) else message
        found.setdefault(key, f"{filename}:{line}")
    return found


@pytest.mark.parametrize("code", [c for c in i18n.LANGUAGES if c != i18n.SOURCE_LANGUAGE])
def test_every_marked_message_has_a_translation_in_every_catalog(code):
    from babel.messages.pofile import read_po

    path = SOURCE / "locale" / code / "LC_MESSAGES" / f"{i18n.DOMAIN}.po"
    with path.open("rb") as handle:
        translated = {m.id if isinstance(m.id, str) else m.id[0]
                      for m in read_po(handle) if m.id and m.string and
                      (m.string if isinstance(m.string, str) else all(m.string))}
    missing = {m: where for m, where in marked_messages().items() if m not in translated}
    assert not missing, f"{len(missing)} message(s) without a {code} translation: " + \
        "; ".join(f"{where}: {m!r}" for m, where in sorted(missing.items(),
                                                             key=lambda kv: kv[1])[:20])


def test_the_extraction_finds_the_marked_messages():
    assert i18n.N_("not answered") == "not answered"
    assert "not answered" in marked_messages()


def test_english_reads_no_catalog_and_other_languages_their_own():
    i18n.catalog.cache_clear()
    assert i18n._("not answered") == "not answered"
    assert i18n.catalog.cache_info().currsize == 0
    with i18n.language("de-CH") as chosen:
        assert chosen == "de" and i18n.active() == "de"
        assert i18n._("not answered") == "nicht beantwortet"
    with i18n.language("xx"):
        assert i18n.active() == "en"
    assert i18n.active() == "en"
