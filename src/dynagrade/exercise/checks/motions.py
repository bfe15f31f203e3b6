"""Equations of motion that integrated checks (:class:`~.integrated.Integrated`) share,
each written from the notes and none calling the mechanics core: the state ``y`` is
positions then velocities."""

from __future__ import annotations

import math
from typing import Any, Sequence

from ..params import ParamValues


def thrown(t: float, y: Any, p: ParamValues) -> Sequence[float]:
    """A particle under its weight alone in the plane, eq. (1.11): ``y = (x1, x2, v1, v2)``,
    ``x1'' = 0``, ``x2'' = -g`` (``p.g``)."""
    return (y[2], y[3], 0.0, -p.g)


def launched(speed: float, angle: float) -> tuple[float, float, float, float]:
    """The state of a particle launched from the origin at ``speed`` and ``angle`` above
    the horizontal, eq. (1.75)."""
    return (0.0, 0.0, speed * math.cos(angle), speed * math.sin(angle))


def falling(t: float, y: Any, p: ParamValues) -> Sequence[float]:
    """A particle falling along one vertical line ``y = (x2, v2)``: ``x2'' = -g``,
    eq. (1.11)."""
    return (y[1], -p.g)


def rising(t: float, y: Any, p: ParamValues) -> float:
    """The vertical speed, for the event "the particle stops rising" (downward crossing)."""
    return y[-1] if len(y) == 2 else y[3]


def height(t: float, y: Any, p: ParamValues) -> float:
    """The height, for the event "the particle lands" (downward crossing)."""
    return y[0] if len(y) == 2 else y[1]
