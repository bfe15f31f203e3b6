"""A small exercise of our own, an exam of it, and the fixes a regrade follows: the
exercise file is written into a folder of the test's, so a test can change its solver or
a tolerance as an author fixing a mistake would (tests/test_rekey.py,
tests/test_serve_regrade.py, tests/test_serve_regrade_browser.py).

The exercise: one length x (1 to 2 m in steps of 0.25 m) and two answers, y = 2 x and
z = 3 x (metres, the default tolerance of 1 %). The "fixed" file says y = 2 x + 1 m, and
with ``rtol`` the tolerance of z."""

from __future__ import annotations

from pathlib import Path

EXERCISE_ID = "regrade-demo"

EXERCISE = '''\
from dynagrade.exercise import Exercise, Numeric, Uniform

EXERCISE = Exercise(
    id="regrade-demo", title="Regrade demo", source="Example 1.1",
    params=(Uniform("x", {low}, 2, step=0.25, unit="m"),),
    statement="The length is x = {{{{ x }}}}. Find y and z.",
    solve=lambda p: {{"y": {y}, "z": 3 * p.x}},
    parts=(Numeric("y", unit="m"), Numeric("z", unit="m"{z_rtol})),
)
'''

#: the exercise as the exam was generated from it, and as fixed
ORIGINAL = {"y": "2 * p.x"}
FIXED_Y = {"y": "2 * p.x + 1"}

ROSTER = "student_id,name\ns1,Ada One\ns2,Bo Two\ns3,Cy Three\ns4,Di Four\ns5,Ed Five\n"


def write_exercise(folder: Path, y: str = "2 * p.x", rtol: float | None = None,
                   low: float = 1) -> Path:
    """The exercise file in ``folder`` (y's formula in SI, z's tolerance, x's lowest
    value)."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "regrade_demo.py"
    path.write_text(EXERCISE.format(y=y, low=low,
                                    z_rtol="" if rtol is None else f", rtol={rtol}"),
                    encoding="utf-8")
    return path


def demo_exam(root: Path, policy: str = 'mode = "homework"\npenalty = 0.5\n') -> tuple[Path, Path]:
    """An exam of the exercise (4 points: 2 per part) for the five students of
    :data:`ROSTER`, generated with a fixed secret: (the manifest, the exercise folder)."""
    from dynagrade.exercise.loader import open_bank
    from dynagrade.generation.generate import generate_exam

    folder = root / "exercises"
    write_exercise(folder)
    (root / "exam.toml").write_text(
        f'id = "regrade-test"\ntitle = "Regrade test"\ndate = 2025-04-14\n{policy}'
        f'[[exercise]]\nid = "{EXERCISE_ID}"\npoints = 4\n', encoding="utf-8")
    (root / "roster.csv").write_text(ROSTER, encoding="utf-8")
    generate_exam(root / "exam.toml", root / "roster.csv", root / "out",
                  bank=open_bank([folder]), pdf=False, jobs=1, secret="7a" * 32)
    return root / "out" / "manifest.json", folder


def lengths(manifest: Path) -> dict[str, float]:
    """Each student's x (metres), as the manifest stores their variant."""
    from dynagrade.exam.manifest import load

    return {s.student_id: float(s.variants[0].params["x"]) for s in load(manifest).students}
