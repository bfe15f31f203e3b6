"""``dynagrade serve``: students answer their exam or homework in a browser.

The reference answers stay on the server; the exam's policy (exam/policy.py) decides what
a student sees. Modules: ``exam_data`` (the manifest, variants and grading), ``db`` (every
SQL statement), ``grading_pool`` (bounded grading with the grader's time budget),
``limits`` (size and rate limits, CSRF), ``submit`` (the rules of one submit),
``state`` (a worker's settings and resources), ``deps`` (what routes depend on: state
and who is calling), ``models`` (the JSON bodies), ``routes`` (one router each for
health, student pages, staff pages and ``/api/v1``), ``pages`` (their HTML),
``practice`` (signed practice draws), ``downloads`` (CSV files), ``app`` (the routers
on one ASGI app), ``links`` (secret links), ``gradebook`` (staff views and downloads).
"""
