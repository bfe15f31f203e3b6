"""The tool's requests to a platform's services (token, line items, scores, members):
plain HTTPS with the standard library, a timeout, and the answer as status and text,
whatever the status (a service's refusal is an answer to record, not an exception).
"""

from __future__ import annotations

import json
import urllib.error
import urllib.request
from dataclasses import dataclass
from urllib.parse import urlencode

TIMEOUT_SECONDS = 15
#: the most of an answer read (bytes)
MAX_ANSWER = 1 << 20


@dataclass(frozen=True)
class Answer:
    """A platform's answer: its status (0: no answer at all) and its text."""

    status: int
    text: str
    headers: dict[str, str]

    @property
    def ok(self) -> bool:
        return 200 <= self.status < 300

    def json(self):
        return json.loads(self.text)


def request(method: str, url: str, headers: dict[str, str],
            body: bytes | None = None) -> Answer:
    """``method url`` with ``headers`` and ``body``; a failure to connect is status 0."""
    call = urllib.request.Request(url, data=body, method=method, headers=headers)
    try:
        with urllib.request.urlopen(call, timeout=TIMEOUT_SECONDS) as answer:
            return Answer(answer.status, answer.read(MAX_ANSWER).decode("utf-8", "replace"),
                          dict(answer.headers))
    except urllib.error.HTTPError as error:
        return Answer(error.code, error.read(MAX_ANSWER).decode("utf-8", "replace"),
                      dict(error.headers))
    except (urllib.error.URLError, OSError, ValueError) as error:
        return Answer(0, f"{type(error).__name__}: {error}", {})


def post_form(url: str, fields: dict[str, str]) -> Answer:
    return request("POST", url, {"Content-Type": "application/x-www-form-urlencoded",
                                 "Accept": "application/json"},
                   urlencode(fields).encode())


def with_query(url: str, query: dict[str, str]) -> str:
    """``url`` with ``query`` added to the query it may already have."""
    return f"{url}{'&' if '?' in url else '?'}{urlencode(query)}"
