"""The server's routes, one router per audience (docs/serve.md lists them all).

- :mod:`.health`: ``GET /healthz``, for monitoring; no token.
- :mod:`.assets`: ``GET /static/{name}``, the pages' stylesheets and scripts; no token.
- :mod:`.student`: the student's page ``/s/{token}`` and its forms.
- :mod:`.staff`: the staff page ``/i/{token}`` and its downloads.
- :mod:`.staff_students`: the staff's page of one student ``/i/{token}/students/{id}``
  and its forms (points set by hand).
- :mod:`.api`: the JSON API under ``/api/v1``, tokens in ``Authorization: Bearer``.
- :mod:`.staff_links`: staff links listed, made and revoked (page and API).
- :mod:`.audit`: the audit log (page, CSV and API).
- :mod:`.exceptions`: exceptions to the policy per student, the staff page
  ``/i/{token}/exceptions`` and ``/api/v1/exceptions``.
- :mod:`.regrade`: the staff's regrade page ``/i/{token}/regrade`` and ``/api/v1/regrades``.
- :mod:`.lti`: LTI 1.3 login initiation, launch and the tool's public keys, ``/lti/…``
  (no token: the platform's signed id_token decides).
- :mod:`.lti_staff`: the staff's page of the course platform ``/i/{token}/lti`` (the
  scores sent to its gradebook, the members imported).
- :mod:`.lti_place`: the teacher's page of a deep-linking request
  ``/i/{token}/lti/place``.

Each route names who may call it in its signature (:mod:`dynagrade.serve.deps`);
tests/test_serve_routes.py holds every route of every router to that.
"""

from __future__ import annotations

from . import (api, assets, audit, exceptions, health, lti, lti_place, lti_staff, regrade,
               staff, staff_links, staff_students, student)

#: in the order a request's path is matched against them: the API and the student pages,
#: which a class calls most, first (every router before the right one costs a match)
ROUTERS = (api.router, student.router, health.router, assets.router, staff.router,
           staff_students.router, exceptions.page_router, exceptions.api_router,
           staff_links.pages_router, staff_links.api_router, audit.pages_router,
           audit.api_router, *regrade.ROUTERS, lti.router, lti_staff.router, lti_place.router)
