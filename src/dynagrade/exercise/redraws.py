"""How often an exam throws an exercise's draws away, and why.

Two things keep a draw of the parameters from reaching a student, and both skew what the
class gets away from the declared distributions:

- a **constraint** it breaks (``Exercise.draw`` draws again at once; counted by a
  :class:`~dynagrade.exercise.params.DrawTally`);
- a **variant that cannot discriminate** (:func:`dynagrade.exercise.verify.variant_problems`:
  a declared misconception or a near miss gives the right answer), which an exam
  replaces by the variant of the next seed.

``dynagrade verify`` reports both shares per exercise; ``dynagrade exam`` warns when more
than :data:`REDRAW_WARNING` of an exercise's variants were replaced. A misconception that
coincides with the key in part of the parameter space is limited to its regime with
``Misconception(..., applies=...)`` rather than left to make exams redraw.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Iterable

from .params import DrawTally

#: the share of an exercise's variants an exam may replace before it warns
REDRAW_WARNING = 0.10
#: the reason recorded for a seed none of whose draws met the constraints
NO_DRAW = "no draw of the parameters meets the constraints"


@dataclass
class RedrawShare:
    """The draws and variants of one exercise over some seeds, and what was thrown away."""

    tally: DrawTally = field(default_factory=DrawTally)
    variants: int = 0
    redrawn: int = 0
    reasons: Counter = field(default_factory=Counter)

    def record(self, problems: Iterable[str]) -> None:
        """One seed's variant, with the reasons it cannot be handed out (none: it can)."""
        problems = set(problems)
        self.variants += 1
        if problems:
            self.redrawn += 1
            self.reasons.update(problems)

    @property
    def share(self) -> float:
        """The share of variants an exam would replace."""
        return self.redrawn / self.variants if self.variants else 0.0

    @property
    def constraint_share(self) -> float:
        """The share of parameter draws that broke a constraint."""
        return self.tally.rejected / self.tally.draws if self.tally.draws else 0.0

    def describe(self) -> str:
        """One line: both shares, each with its reasons, most frequent first."""
        redraws = f"an exam redraws {percent(self.share)} of variants"
        if self.redrawn:
            redraws += f" ({_ranked(self.reasons, self.variants)})"
        rejects = f"constraints reject {percent(self.constraint_share)} of draws"
        if self.tally.rejected:
            rejects += f" ({_ranked(self.tally.broken, self.tally.draws)})"
        return f"{redraws}; {rejects}"

    @property
    def too_many(self) -> bool:
        """Whether an exam would warn about this exercise (:data:`REDRAW_WARNING`)."""
        return self.share > REDRAW_WARNING


def percent(share: float) -> str:
    """A share as a percentage for people: "0 %", "0.4 %", "12 %"."""
    value = 100 * share
    if 0 < value < 1:
        return f"{value:.1f} %"
    return f"{value:.0f} %"


def _ranked(counts: Counter, total: int, shown: int = 3) -> str:
    """The most frequent reasons with their shares of ``total``."""
    ranked = [f"{reason}: {percent(count / total)}"
              for reason, count in counts.most_common(shown)]
    if len(counts) > shown:
        ranked.append(f"{len(counts) - shown} more")
    return "; ".join(ranked)
