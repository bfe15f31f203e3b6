"""LTI 1.3: ``dynagrade serve`` launched from a course's LMS (Moodle, Canvas).

The protocol (1EdTech LTI 1.3 Core and Security Framework), one job per module:

- :mod:`.store`: the tables (platforms, the tool's keys, pending logins, sessions) and
  every statement on them.
- :mod:`.claims`: the id_token's claim names and what the roles mean here.
- :mod:`.keys`: the tool's own RSA key pair, its rotation and its public JWKS.
- :mod:`.login`: OIDC third-party login initiation (state and nonce).
- :mod:`.verify`: the platform's id_token checked (signature, issuer, audience,
  deployment, times, nonce, message type, version).
- :mod:`.launch`: a verified launch turned into a session of a roster student or staff.
- :mod:`.sessions`: the session cookie and what the pages accept in place of a link.
- :mod:`.framing`: the platforms' origins, which alone may frame launched pages.
- :mod:`.grades_store`: the tables of the grade and roster services.
- :mod:`.http`, :mod:`.access`: requests to a platform's services, and their access
  tokens (client credentials, a client assertion signed by the tool's key).
- :mod:`.line_items`, :mod:`.scores`, :mod:`.grade_sync`: Assignment and Grade
  Services: the exam's gradebook column, the score a student's platform should hold,
  and the task that queues, sends and retries scores.
- :mod:`.roster_import`: Names and Role Provisioning Services: the course's learners
  merged with the roster.
- :mod:`.deep_linking`: Deep Linking: a teacher's request kept, the signed answer
  placing the exam or a practice exercise.
- :mod:`.setup`: the values a platform's registration form asks for.
- :mod:`.commands`: ``dynagrade lti``.

docs/lti.md is the administrator's guide.
"""
