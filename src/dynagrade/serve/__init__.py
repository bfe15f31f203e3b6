"""``dynagrade serve``: students answer their exam or homework in a browser.

The reference answers stay on the server; the exam's policy (exam/policy.py) decides what
a student sees. Modules: ``exam_data`` (the manifest, variants and grading), ``db`` (every
SQL statement), ``grading_pool`` (bounded grading with the grader's time budget),
``limits`` (size and rate limits, CSRF), ``app`` (routes: pages and the JSON API),
``links`` (secret links), ``gradebook`` (staff views and downloads).
"""
