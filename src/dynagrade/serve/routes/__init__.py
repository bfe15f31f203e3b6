"""The server's routes, one router per audience (docs/serve.md lists them all).

- :mod:`.health`: ``GET /healthz``, for monitoring; no token.
- :mod:`.student`: the student's page ``/s/{token}`` and its forms.
- :mod:`.staff`: the staff page ``/i/{token}`` and its downloads.
- :mod:`.staff_students`: the staff's page of one student ``/i/{token}/students/{id}``
  and its forms (points set by hand).
- :mod:`.api`: the JSON API under ``/api/v1``, tokens in ``Authorization: Bearer``.

Each route names who may call it in its signature (:mod:`dynagrade.serve.deps`);
tests/test_serve_routes.py holds every route of every router to that.
"""

from __future__ import annotations

from . import api, health, staff, staff_students, student

ROUTERS = (health.router, student.router, staff.router, staff_students.router, api.router)
