"""dynagrade: randomized Dynamics exercises and exams, and a grader for them."""

__version__ = "0.1.0"
