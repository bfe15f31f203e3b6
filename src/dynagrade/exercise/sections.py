"""The notes' lowest-level sections, and which of them an exercise's ``source`` names.

A course needs several exercises for every section of the notes (weekly homework, a
practice pool, exams); ``dynagrade list --by-section`` counts them. The 41 sections are
the leaves of the notes' table of contents (the summaries of key relations and the brief
summary 1.1.5 are left out: nothing is taught there first). An exercise counts under the
section of its ``source``:

- ``"Section 3.2.3"`` under 3.2.3; a source more precise than a leaf counts under the
  leaf that holds it (``"Section 3.1.1"`` under 3.1, whose subsections are no leaves);
- ``"Example 1.9"`` under the section whose text holds the example (:data:`EXAMPLES`).
  Only chapter 1's examples are in our copy of the notes, so exercises of chapters 2–5
  cite sections.

Usage::

    section_of("Example 1.13")          # "1.2.2"
    coverage(bank.listing())            # [SectionCount("1.1.1", "Kinematics in ...", (...)), ...]
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable

#: the fewest exercises a section should have (issue 31: homework, practice, two exams)
ENOUGH = 3

#: the leaves of the notes' table of contents, with their titles as it gives them
SECTIONS: tuple[tuple[str, str], ...] = (
    ("1.1.1", "Kinematics in a Cartesian reference frame"),
    ("1.1.2", "Constrained motion"),
    ("1.1.3", "Kinematics in polar coordinates"),
    ("1.1.4", "Kinematics of space curves"),
    ("1.2.1", "Newton's axioms and balance of linear momentum"),
    ("1.2.2", "Work-energy balance"),
    ("1.2.3", "Balance of angular momentum"),
    ("1.2.4", "Particle impact"),
    ("2.1", "Kinematics"),
    ("2.2.1", "Balance of linear momentum"),
    ("2.2.2", "Work-energy balance"),
    ("2.2.3", "Balance of angular momentum"),
    ("2.3.1", "Collision of two particles"),
    ("2.3.2", "Particles of variable mass: mass accretion and mass loss"),
    ("3.1", "Kinematics"),
    ("3.2.1", "Balance of linear momentum"),
    ("3.2.2", "Balance of angular momentum"),
    ("3.2.3", "Moment of inertia tensor"),
    ("3.2.4", "Angular momentum transfer formula"),
    ("3.2.5", "Work-energy balance"),
    ("3.3", "Collisions of rigid bodies"),
    ("3.4.1", "Active and passive rotations"),
    ("3.4.2", "Rotating frames of reference"),
    ("3.4.3", "Balance of linear momentum"),
    ("3.4.4", "Balance of angular momentum, Euler equations"),
    ("3.5.1", "General description"),
    ("3.5.2", "Axisymmetric bodies"),
    ("4.1", "Lagrange equations"),
    ("4.2", "Mechanical equilibrium"),
    ("4.3.1", "Definitions and equation of motion"),
    ("4.3.2", "Free vibrations"),
    ("4.3.3", "Forced vibrations"),
    ("4.4.1", "Equations of motion for multi-DOF vibrations"),
    ("4.4.2", "Free, undamped vibrations"),
    ("4.4.3", "Damped and forced vibrations"),
    ("4.4.4", "Modal decomposition"),
    ("5.1", "Dynamics of systems with massless deformable bodies"),
    ("5.2", "Dynamics of deformable bodies with non-negligible mass"),
    ("5.3.1", "Longitudinal wave motion and vibrations"),
    ("5.3.2", "Torsional wave motion and vibrations"),
    ("5.3.3", "Flexural wave motion and vibrations"),
)

#: chapter 1's examples by the section whose text holds them: in the notes, Examples
#: 1.1-1.3 stand between the headings 1.1.1 and 1.1.2, 1.4 under 1.1.2, 1.5 under 1.1.3,
#: 1.6 under 1.1.4, 1.7-1.10 under 1.2.1, 1.11-1.15 under 1.2.2, 1.16-1.19 under 1.2.3
EXAMPLES: dict[str, str] = {
    **dict.fromkeys(("1.1", "1.2", "1.3"), "1.1.1"),
    "1.4": "1.1.2",
    "1.5": "1.1.3",
    "1.6": "1.1.4",
    **dict.fromkeys(("1.7", "1.8", "1.9", "1.10"), "1.2.1"),
    **dict.fromkeys(("1.11", "1.12", "1.13", "1.14", "1.15"), "1.2.2"),
    **dict.fromkeys(("1.16", "1.17", "1.18", "1.19"), "1.2.3"),
}

_LEAVES = dict(SECTIONS)
_SOURCE = re.compile(r"^(Example|Section)\s+(\d+(?:\.\d+)*)")


def section_of(source: str) -> str | None:
    """The leaf section (of :data:`SECTIONS`) an exercise's ``source`` names; None when it
    names none (an example outside :data:`EXAMPLES`, a section that is no leaf's)."""
    match = _SOURCE.match(source.strip())
    if match is None:
        return None
    kind, number = match.groups()
    if kind == "Example":
        return EXAMPLES.get(number)
    parts = number.split(".")
    for end in range(len(parts), 0, -1):  # the section itself, or the leaf that holds it
        if ".".join(parts[:end]) in _LEAVES:
            return ".".join(parts[:end])
    return None


@dataclass(frozen=True)
class SectionCount:
    """One section of the notes and the exercises that count under it."""

    section: str
    title: str
    exercises: tuple[str, ...]

    @property
    def enough(self) -> bool:
        return len(self.exercises) >= ENOUGH

    def to_json(self) -> dict:
        return {"section": self.section, "title": self.title, "count": len(self.exercises),
                "enough": self.enough, "exercises": list(self.exercises)}


def coverage(exercises: Iterable) -> tuple[list[SectionCount], list[str]]:
    """Every section of :data:`SECTIONS` with the ids of the ``exercises`` (anything with
    ``id`` and ``source``: a listing or loaded exercises) that count under it, in the
    notes' order; and the ids whose source names no section."""
    under: dict[str, list[str]] = {number: [] for number, _ in SECTIONS}
    unplaced = []
    for exercise in exercises:
        section = section_of(exercise.source)
        if section is None:
            unplaced.append(exercise.id)
        else:
            under[section].append(exercise.id)
    return ([SectionCount(number, title, tuple(under[number])) for number, title in SECTIONS],
            unplaced)
