"""Heavy libraries for the tests, imported when a test first uses them.

Collecting the suite imports every test module; a top-level ``import sympy`` or
``from scipy.integrate import solve_ivp`` there costs every run (even ``-k one_test``
or ``--collect-only``) the second or so these libraries take to import. A test module
writes instead::

    sp = deferred("sympy")
    solve_ivp = deferred("scipy.integrate", "solve_ivp")

and uses ``sp.Symbol(...)`` and ``solve_ivp(...)`` as before, inside its tests: the
import happens on the first attribute access or call, through the ordinary import
system (so it is thread-safe and imports each module once). Nothing at module level
may touch a deferred name, or the import happens at collection again; and only public
names are forwarded (``sp.Symbol``, never ``sp._private``).
"""

from __future__ import annotations

import importlib


class deferred:
    """The module ``module`` (or its attribute ``name``), imported on first use."""

    __slots__ = ("_module", "_name")

    def __init__(self, module: str, name: str | None = None):
        self._module = module
        self._name = name

    def _target(self):
        loaded = importlib.import_module(self._module)
        return loaded if self._name is None else getattr(loaded, self._name)

    def __getattr__(self, attribute: str):
        if attribute.startswith("_"):
            # pytest looks for its markers on every module-level object it collects;
            # private and special names are not forwarded, so that look does not import.
            raise AttributeError(f"{self!r} does not forward {attribute!r}")
        return getattr(self._target(), attribute)

    def __call__(self, *args, **kwargs):
        return self._target()(*args, **kwargs)

    def __instancecheck__(self, instance) -> bool:
        return isinstance(instance, self._target())

    def __repr__(self) -> str:
        where = self._module if self._name is None else f"{self._module}.{self._name}"
        return f"deferred({where})"
