"""Errors raised while reading an answer or a part's specification."""

from __future__ import annotations

from ..errors import DynagradeError


class AnswerError(DynagradeError, ValueError):
    """An answer that cannot be read: the message says why, and where when known.

    ``position`` is a 0-based index into ``text`` (the answer as typed). ``str()`` of the
    error shows the message and, when the position is known, the text with a caret
    under the offending character::

        unexpected ')'
          2*(a+b))
                 ^
    """

    def __init__(self, message: str, position: int | None = None, text: str | None = None):
        super().__init__(message)
        self.message = message
        self.position = position
        self.text = text

    def __str__(self) -> str:
        if self.position is None or self.text is None:
            return self.message
        text = self.text
        pos = max(0, min(self.position, len(text)))
        # Show at most ~60 characters around the position so long answers stay readable.
        start = max(0, pos - 40)
        end = min(len(text), pos + 20)
        snippet = text[start:end].replace("\n", " ").replace("\t", " ")
        prefix = "…" if start > 0 else ""
        suffix = "…" if end < len(text) else ""
        caret = " " * (len(prefix) + pos - start) + "^"
        return f"{self.message}\n  {prefix}{snippet}{suffix}\n  {caret}"


class SpecError(DynagradeError, ValueError):
    """A part's specification or reference answer is unusable (an authoring error).

    Raised by :func:`dynagrade.grading.grade` independently of the student's answer,
    so that exercise verification can report it; it is never caused by answer text.
    """
