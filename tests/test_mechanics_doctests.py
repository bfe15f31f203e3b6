"""The notes' numbers in the mechanics core's docstrings hold (issue 29, as sympy's
``physics/mechanics`` shows its results): every ``>>>`` example of every module of
``dynagrade.mechanics`` runs as a doctest, one test per module.

The modules are found without importing them (collection stays light,
tests/test_collection.py) and imported when their test runs. ``bench/mutation.py`` runs a
mutated module's test here by its id (``vibrations``, ``examples.projectile``)."""
import doctest
import importlib
import importlib.util
import pkgutil

import pytest

PACKAGE = "dynagrade.mechanics"


def _module_names(package: str = PACKAGE, prefix: str = "") -> list[str]:
    """The modules of ``package`` and its subpackages (``examples.projectile``), found by
    their files (pkgutil.walk_packages would import the subpackages to look inside)."""
    spec = importlib.util.find_spec(package)
    assert spec is not None and spec.submodule_search_locations
    names = []
    for info in pkgutil.iter_modules(spec.submodule_search_locations):
        if info.ispkg:
            names += _module_names(f"{package}.{info.name}", f"{prefix}{info.name}.")
        else:
            names.append(prefix + info.name)
    return sorted(names)


MODULES = _module_names()


def _examples(name: str) -> list[doctest.DocTest]:
    module = importlib.import_module(f"{PACKAGE}.{name}")
    return [t for t in doctest.DocTestFinder().find(module) if t.examples]


@pytest.mark.parametrize("name", MODULES)
def test_the_notes_numbers_in_docstrings_hold(name):
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for test in _examples(name):
        runner.run(test)
    assert runner.failures == 0, f"{runner.failures} docstring example(s) of {name} fail (output above)"


def test_the_docstrings_hold_the_notes_examples():
    with_examples = {name for name in MODULES if _examples(name)}
    assert {"kinematics", "energy", "impact", "angular_momentum", "vibrations",
            "examples.projectile", "examples.looping", "examples.incline"} <= with_examples
    assert sum(len(t.examples) for name in MODULES for t in _examples(name)) >= 20
