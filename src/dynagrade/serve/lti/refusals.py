"""Why a login or launch is refused: one error, its HTTP status, and a page for it."""

from __future__ import annotations

from ...errors import DynagradeError


class LaunchRefused(DynagradeError):
    """A login initiation or launch this tool does not accept; ``message`` (translated)
    says why in words for the person in front of the page, ``status`` is the answer's."""

    def __init__(self, message: str, status: int = 401, title: str | None = None):
        super().__init__(message)
        self.message, self.status, self.title = message, status, title
