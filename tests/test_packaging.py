"""The wheel ships every module: each folder of Python files under src/dynagrade is a
package that pyproject.toml lists (an editable install finds unlisted subpackages, so
only this check catches one that a built wheel would leave out)."""

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_every_folder_of_python_files_under_src_is_a_listed_package():
    listed = set(tomllib.loads((ROOT / "pyproject.toml").read_text())
                 ["tool"]["setuptools"]["packages"])
    src = ROOT / "src"
    folders = {".".join(path.parent.relative_to(src).parts)
               for path in src.rglob("*.py") if "__pycache__" not in path.parts}
    assert folders - listed == set()
