"""Mutation check of the mechanics core and the grader: how many physics-typical mistakes
the tests (and `dynagrade verify`) would catch.

    python bench/mutation.py                       # CI size: a small seeded sample, with floors
    python bench/mutation.py --sample 160 --group mechanics --verify
    python bench/mutation.py --sample 0            # every mutant there is (long)
    python bench/mutation.py --list-tests          # the module -> test files map, and stop

A mutant is one mistake a student (or an author) makes in a formula, made with Python's
``ast`` at one place of one module: a sign flipped (``+``/``-``, a unary minus dropped),
``sin``/``cos`` (and ``sinh``/``cosh``) exchanged, a constant changed (``2`` -> ``1``,
``0.5`` -> ``1``, any other c -> 2c), a term of a sum dropped, a square made a first power
(and a first power a square), ``*`` and ``/`` exchanged, and the two operands of ``-``
or ``/`` or the first two arguments of a call swapped. Mutants are drawn with ``--seed``
from the modules of each group (``--sample N`` per group, 0 for all), each is written
into a temporary copy of the project (the tree is never edited), and the tests that
cover its module run there (``-x``, hypothesis seeded): a failing run kills it. A mutant
whose module parses to the same tree is *equivalent* and not run; those listed in
``bench/mutation_equivalent.txt`` (reviewed by hand, with the reason) are equivalent
too. A run longer than ``--timeout-factor`` times the unmutated run counts as killed
(``timeout``), as a hang would in CI.

The tests of a module are data, read from the test files' imports: a test file covers
module M when it imports M (``import``, ``from ... import``, ``deferred("...")`` or a
dotted name in a string, and the dotted names of the notes' results in ``reference/``
for the tests that read them), or, for the tests of M's own layer (``test_grading_*``
for a module of ``grading/``, tests/README.md), imports a module of M's package that
imports M (transitively). A mechanics module is also covered by its docstring examples
(tests/test_mechanics_doctests.py). The tests marked slow (tests/conftest.py) are left
out unless ``--slow``: they take most of a surviving mutant's time.

With ``--verify``, every mechanics mutant that changes a reference answer (any part of
any exercise of the bank at seeds 0-2, beyond 1e-9 relative) is also run through
``dynagrade verify`` on the exercises whose keys it changes: the catch rate printed is
the share of those mutants that ``verify`` fails on.

Exit status 1 when a group's kill score is below its ``--floor`` (CI).
"""

from __future__ import annotations

import argparse
import ast
import dataclasses
import json
import os
import hashlib
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GROUPS = {"mechanics": "src/dynagrade/mechanics", "grading": "src/dynagrade/grading"}
#: CI's size: mutants per group, and the kill score each group must reach on it.
CI_SAMPLE = 6
CI_FLOORS = {"mechanics": 0.9, "grading": 0.75}
#: Tests that time themselves on the wall clock: under the load of a mutation run they
#: fail unmutated (a grader answer slower than 1 s), so mutants run without them.
WALL_CLOCK_TESTS = [
    "tests/test_grading_parser.py::test_hostile_answers_get_a_wrong_verdict_within_a_second",
    "tests/test_grading_precise.py::test_a_real_difference_is_found_without_high_precision",
    "tests/test_grading_precise.py::test_values_beyond_any_float_give_up_quietly_and_quickly",
    "tests/test_grading_robustness.py::test_after_prepare_no_verdict_spends_its_budget_loading_pint",
]
#: Without --check-baseline (CI, right after the whole suite passed) the unmutated tests
#: are not run first; a mutant's timeout is then reckoned from this many seconds.
UNCHECKED_BASELINE_SECONDS = 100.0
EQUIVALENT_FILE = Path(__file__).resolve().parent / "mutation_equivalent.txt"
DOCTESTS = "tests/test_mechanics_doctests.py"
COPY_IGNORE = shutil.ignore_patterns(".git", ".venv", "__pycache__", ".hypothesis", "out",
                                     ".pytest_cache", "*.egg-info", ".mypy_cache")


# --- mutants ------------------------------------------------------------------------------

@dataclass(frozen=True)
class Mutant:
    """One change at one place: ``module`` (a path relative to the root), the enclosing
    function, what kind of mistake, the text before and after, and the source it gives."""

    module: str
    function: str
    line: int
    kind: str
    before: str
    after: str
    source: str
    occurrence: int = 1

    @property
    def key(self) -> str:
        """Stable across edits elsewhere in the module: the place's function and text (and
        which occurrence of that text in the function, from the second on)."""
        key = f"{self.module}:{self.function}:{self.kind}:{self.before} -> {self.after}"
        return key if self.occurrence == 1 else f"{key} #{self.occurrence}"


#: Calls whose two first arguments are no physics' operands (a swap is a type error or
#: a message's wording, not a mistake in a formula).
_NO_SWAP = {"isinstance", "issubclass", "getattr", "hasattr", "setattr", "format", "join",
            "get", "setdefault", "replace", "append", "insert", "startswith", "endswith",
            "print", "_", "ngettext", "Verdict", "Readability", "SpecError", "AnswerError",
            "ValueError", "TypeError", "field", "register", "split", "partition"}
_SWAP_FUNCS = {"sin": "cos", "cos": "sin", "sinh": "cosh", "cosh": "sinh"}


def _changed_constant(value):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    if value == 2:
        return type(value)(1)
    if value == 0.5:
        return 1.0
    if value == 0:
        return type(value)(1)
    return value * 2


def _replacements(node: ast.AST):
    """(kind, replacement node) for every physics-typical mistake at ``node``."""
    out = []
    if isinstance(node, ast.BinOp):
        swap_op = {ast.Add: ast.Sub, ast.Sub: ast.Add, ast.Mult: ast.Div, ast.Div: ast.Mult}
        if type(node.op) in swap_op:
            kind = "sign" if isinstance(node.op, (ast.Add, ast.Sub)) else "mult/div"
            out.append((kind, ast.BinOp(node.left, swap_op[type(node.op)](), node.right)))
        if isinstance(node.op, (ast.Add, ast.Sub)):
            out.append(("dropped term", node.left))
            out.append(("dropped term", node.right))
        if isinstance(node.op, (ast.Sub, ast.Div)):
            out.append(("swapped operands", ast.BinOp(node.right, node.op, node.left)))
        if isinstance(node.op, ast.Pow) and isinstance(node.right, ast.Constant):
            if node.right.value == 2:
                out.append(("square", node.left))
    elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        out.append(("sign", node.operand))
    elif isinstance(node, ast.Constant):
        changed = _changed_constant(node.value)
        if changed is not None:
            out.append(("constant", ast.Constant(changed)))
    elif isinstance(node, ast.Call):
        func = node.func
        name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", None)
        if name in _SWAP_FUNCS:
            if isinstance(func, ast.Attribute):
                new_func: ast.expr = ast.Attribute(func.value, _SWAP_FUNCS[name], ast.Load())
            else:
                new_func = ast.Name(_SWAP_FUNCS[name], ast.Load())
            out.append(("sin/cos", ast.Call(new_func, node.args, node.keywords)))
        if name == "sqrt" and len(node.args) == 1:
            out.append(("square", node.args[0]))
        args = node.args
        if name not in _NO_SWAP and len(args) >= 2 and not any(isinstance(a, ast.Starred) for a in args[:2]) \
                and ast.dump(args[0]) != ast.dump(args[1]):
            out.append(("swapped arguments", ast.Call(node.func, [args[1], args[0], *args[2:]],
                                                      node.keywords)))
    elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Load):
        pass
    return out


def _skipped(node: ast.AST, parents: dict) -> bool:
    """Docstrings, messages, annotations and decorators are no formulas."""
    parent = parents.get(node)
    while parent is not None:
        if isinstance(parent, (ast.Raise, ast.JoinedStr, ast.arg)) or \
                (isinstance(parent, ast.FunctionDef) and node in parent.decorator_list):
            return True
        if isinstance(parent, ast.FunctionDef) and getattr(parent, "returns", None) is node:
            return True
        node, parent = parent, parents.get(parent)
    return False


def mutants_of(path: Path, root: Path) -> list[Mutant]:
    """Every mutant of the module at ``path``, inside its functions."""
    text = path.read_text(encoding="utf-8")
    data = text.encode("utf-8")
    line_starts = [0]
    for line in data.splitlines(keepends=True):
        line_starts.append(line_starts[-1] + len(line))
    tree = ast.parse(text)
    parents = {child: parent for parent in ast.walk(tree) for child in ast.iter_child_nodes(parent)}
    original_dump = ast.dump(tree)
    module = path.relative_to(root).as_posix()
    found = []
    for func in ast.walk(tree):
        if not isinstance(func, (ast.FunctionDef, ast.AsyncFunctionDef)):
            continue
        for node in ast.walk(func):
            if not isinstance(node, ast.expr) or _skipped(node, parents) or \
                    (isinstance(node, ast.Constant) and isinstance(node.value, str)):
                continue
            if _enclosing_function(node, parents) is not func:
                continue
            start = line_starts[node.lineno - 1] + node.col_offset
            end = line_starts[node.end_lineno - 1] + node.end_col_offset
            before = data[start:end].decode("utf-8")
            for kind, replacement in _replacements(node):
                after = ast.unparse(replacement)
                if isinstance(parents.get(node), (ast.BinOp, ast.UnaryOp, ast.Attribute,
                                                  ast.Subscript, ast.Call)):
                    after = f"({after})"
                source = (data[:start] + after.encode("utf-8") + data[end:]).decode("utf-8")
                try:
                    mutated_dump = ast.dump(ast.parse(source))
                except SyntaxError:
                    continue
                kind_text = kind if mutated_dump != original_dump else "equivalent:" + kind
                found.append(Mutant(module, func.name, node.lineno, kind_text,
                                    " ".join(before.split()), " ".join(after.split()), source))
    seen: dict[str, int] = {}
    for i, mutant in enumerate(found):
        seen[mutant.key] = seen.get(mutant.key, 0) + 1
        if seen[mutant.key] > 1:
            found[i] = dataclasses.replace(mutant, occurrence=seen[mutant.key])
    return found


def _enclosing_function(node, parents):
    parent = parents.get(node)
    while parent is not None and not isinstance(parent, (ast.FunctionDef, ast.AsyncFunctionDef)):
        parent = parents.get(parent)
    return parent


def draw(pool: list[Mutant], size: int, seed: int) -> list[Mutant]:
    """``size`` mutants of ``pool`` (all for 0), chosen by a seeded hash of each one's key:
    whether a mutant is drawn does not depend on the rest of the pool, so a run after an
    edit elsewhere draws the same mutants as the run before it."""
    def rank(m: Mutant) -> str:
        return hashlib.sha256(f"{seed}:{m.key}".encode()).hexdigest()
    chosen = sorted(pool, key=rank)[:size] if size else pool
    return sorted(chosen, key=lambda m: (m.module, m.line))


def known_equivalent(path: Path = EQUIVALENT_FILE) -> dict[str, str]:
    """The mutants reviewed as equivalent: key -> reason (``key  # reason`` per line)."""
    if not path.exists():
        return {}
    out = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            key, _, reason = line.partition("  # ")
            out[key.strip()] = reason.strip()
    return out


# --- which tests cover which module -------------------------------------------------------

_DOTTED = re.compile(r"^dynagrade(\.\w+)+$")
_NAMED_FUNCTION = re.compile(r"^\w+:\w+$")


def _module_names(root: Path) -> dict[str, Path]:
    src = root / "src"
    return {".".join(p.relative_to(src).with_suffix("").parts).removesuffix(".__init__"): p
            for p in src.rglob("*.py")}


def _reexports(names: dict) -> dict[str, str]:
    """``package.name`` -> the module that defines it, for the names a package's
    ``__init__`` imports from its own modules (``dynagrade.grading.grade`` -> ``.dispatch``)."""
    out = {}
    for package, path in names.items():
        if path.name != "__init__.py":
            continue
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
                for alias in node.names:
                    out[f"{package}.{alias.asname or alias.name}"] = f"{package}.{node.module}"
    return out


def _imported_names(tree: ast.AST, here: str | None, names: dict) -> set[str]:
    """Modules of dynagrade that ``tree`` imports, resolved to the defining module where a
    name is imported from a package (``from dynagrade.grading import grade``)."""
    found: set[str] = set()
    reexports = _reexports(names)

    def add(dotted: str):
        dotted = reexports.get(dotted, dotted)
        while dotted and dotted not in names:
            dotted = dotted.rpartition(".")[0]
        if dotted:
            found.add(dotted)

    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                add(alias.name)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level and here:
                package = here.split(".")[:-1]  # a package's own name ends in .__init__
                package = package[:len(package) - node.level + 1]
                base = ".".join(package + ([base] if base else []))
            for alias in node.names:
                add(f"{base}.{alias.name}")
        elif isinstance(node, ast.Constant) and isinstance(node.value, str):
            if _DOTTED.match(node.value):
                add(node.value)
            elif here and _NAMED_FUNCTION.match(node.value):
                # "vector:grade_vector": a sibling module's function, imported on first use
                # (grading/kinds.py)
                sibling = here.split(".")[:-1] + [node.value.partition(":")[0]]
                if ".".join(sibling) in names:
                    add(".".join(sibling))
    return {name for name in found if name.startswith("dynagrade")}


def _package_imports(root: Path) -> dict[str, set[str]]:
    names = _module_names(root)
    graph = {}
    for name, path in names.items():
        here = name + ".__init__" if path.name == "__init__.py" else name
        graph[name] = _imported_names(ast.parse(path.read_text(encoding="utf-8")), here, names)
    return graph


def tests_of_modules(root: Path) -> dict[str, list[str]]:
    """Module (path relative to root) -> the test files that cover it (module docstring)."""
    names = _module_names(root)
    graph = _package_imports(root)
    reference_names: set[str] = set()
    reference_files = {p.name for p in (root / "reference").glob("*.toml")}
    for data in sorted((root / "reference").glob("*.toml")):
        reference_names |= _imported_names(
            ast.parse(repr(re.findall(r'"(dynagrade(?:\.\w+)+)"', data.read_text(encoding="utf-8")))),
            None, names)
    covered: dict[str, set[str]] = {name: set() for name in names}
    direct_of: dict[str, set[str]] = {name: set() for name in names}
    for test in sorted((root / "tests").glob("test_*.py")):
        text = test.read_text(encoding="utf-8")
        direct = _imported_names(ast.parse(text), None, names)
        tree = ast.parse(text)
        strings = {n.value for n in ast.walk(tree) if isinstance(n, ast.Constant)}
        if "reference" in strings and strings & reference_files:
            direct |= reference_names  # the test reads the notes' results in reference/
        rel = test.relative_to(root).as_posix()
        for start in direct:
            direct_of[start].add(rel)
            package = start if names[start].name == "__init__.py" else start.rpartition(".")[0]
            if not test.name.startswith(f"test_{package.split('.')[-1]}_"):
                # another layer's tests (tests/README.md: one layer per prefix) cover what
                # they import, not all it reaches
                covered[start].add(rel)
                continue
            seen, todo = set(), [start]
            while todo:
                name = todo.pop()
                if name in seen:
                    continue
                seen.add(name)
                covered[name].add(rel)
                todo += [n for n in graph.get(name, ()) if n.rpartition(".")[0] == package
                         or n == package]
    # the tests that import the module itself first: they fail first
    return {names[n].relative_to(root).as_posix():
            sorted(files, key=lambda f: (f not in direct_of[n], f)) for n, files in covered.items()}


def exercises_of_modules(root: Path) -> dict[str, list[str]]:
    """Mechanics module (path relative to root) -> the exercise files whose imports reach
    it (directly or through the core's own imports)."""
    names = _module_names(root)
    graph = _package_imports(root)
    reached: dict[str, set[str]] = {}
    for path in sorted((root / "exercises").rglob("*.py")):
        if path.name == "__init__.py":
            continue
        todo = list(_imported_names(ast.parse(path.read_text(encoding="utf-8")), None, names))
        seen: set[str] = set()
        while todo:
            name = todo.pop()
            if name in seen or not name.startswith("dynagrade.mechanics"):
                continue
            seen.add(name)
            reached.setdefault(names[name].relative_to(root).as_posix(), set()).add(
                path.relative_to(root).as_posix())
            todo += graph.get(name, ())
    return {module: sorted(files) for module, files in reached.items()}


# --- running ------------------------------------------------------------------------------

@dataclass
class Outcome:
    mutant: Mutant
    status: str  # killed, survived, timeout, equivalent, no tests
    seconds: float = 0.0
    verify: str = ""  # for core mutants: "no key change", "caught", "missed"


class Workspace:
    """A temporary copy of the project in which one module at a time is mutated."""

    def __init__(self, root: Path):
        self.tmp = Path(tempfile.mkdtemp(prefix="dynagrade-mutation-"))
        self.root = self.tmp / "project"
        shutil.copytree(root, self.root, ignore=COPY_IGNORE, symlinks=True)
        (self.tmp / "mutation_profile.py").write_text(PROFILE_PLUGIN, encoding="utf-8")
        self.env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(self.root / "src"), str(self.tmp)]),
                    "PYTHONDONTWRITEBYTECODE": "1", "HYPOTHESIS_PROFILE": "mutation"}

    def write(self, module: str, source: str) -> None:
        (self.root / module).write_text(source, encoding="utf-8")

    def pytest(self, targets: list[str], timeout: float, slow: bool) -> tuple[str, float]:
        cmd = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider",
               "-p", "mutation_profile", "-o", "timeout=60", *targets]
        if not slow:
            cmd[4:4] = ["-m", "not slow"]
        for test in WALL_CLOCK_TESTS:
            cmd[4:4] = ["--deselect", test]
        start = time.perf_counter()
        try:
            done = subprocess.run(cmd, cwd=self.root, env=self.env, capture_output=True,
                                  text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return "timeout", time.perf_counter() - start
        seconds = time.perf_counter() - start
        if done.returncode == 5:
            return "no tests", seconds
        return ("survived" if done.returncode == 0 else "killed"), seconds

    def keys(self, exercise_files: list[str]) -> dict:
        """These exercises' reference answers at seeds 0-2 (or the error a draw raises),
        by exercise id and seed."""
        done = subprocess.run([sys.executable, "-c", KEYS_SCRIPT, *exercise_files], cwd=self.root,
                              env=self.env, capture_output=True, text=True, timeout=600)
        return json.loads(done.stdout) if done.returncode == 0 else {"": done.stderr[-300:]}

    def verify(self, exercise_ids: list[str], variants: int) -> bool:
        """Whether ``dynagrade verify`` fails on these exercises."""
        cmd = [sys.executable, "-c", "from dynagrade.cli import main; main()", "verify",
               "--variants", str(variants), *exercise_ids]
        done = subprocess.run(cmd, cwd=self.root, env=self.env, capture_output=True, text=True,
                              timeout=900)
        return done.returncode != 0

    def close(self) -> None:
        shutil.rmtree(self.tmp, ignore_errors=True)


#: A hypothesis profile for mutants (a pytest plugin, loaded before tests/conftest.py picks
#: the profile by HYPOTHESIS_PROFILE): derandomized (seeded), fewer examples, and no
#: shrinking, since a mutant needs one failing example, not the smallest.
PROFILE_PLUGIN = """
from hypothesis import HealthCheck, Phase, settings

settings.register_profile("mutation", max_examples=25, deadline=None, derandomize=True,
                          database=None, phases=[Phase.explicit, Phase.reuse, Phase.generate],
                          suppress_health_check=list(HealthCheck))
"""

KEYS_SCRIPT = """
import json, sys
from dynagrade.exercise.loader import load_file
out = {}
for path in sys.argv[1:]:
    exercise = load_file(path)
    for seed in range(3):
        try:
            answers = exercise.variant(seed, with_statement=False).answers
            out[f"{exercise.id}@{seed}"] = {k: (list(v) if isinstance(v, tuple) else v)
                                            for k, v in answers.items()}
        except Exception as error:
            out[f"{exercise.id}@{seed}"] = "error: " + type(error).__name__
print(json.dumps(out, default=str))
"""


def _differs(a, b) -> bool:
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        if not (a == a and b == b):
            return (a == a) != (b == b)
        return abs(a - b) > 1e-9 * max(abs(a), abs(b), 1e-300)
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return any(_differs(x, y) for x, y in zip(a, b))
    return a != b


def changed_exercises(before: dict, after: dict) -> list[str]:
    changed = {key.partition("@")[0] for key in set(before) | set(after)
               if _differs(before.get(key), after.get(key))}
    return sorted(changed)


def run(args) -> int:
    root = Path(args.root).resolve()
    coverage = tests_of_modules(root)
    if args.list_tests:
        for module, files in sorted(coverage.items()):
            if module.startswith(tuple(GROUPS[g] for g in args.group)):
                print(f"{module}: {' '.join(files) or '(none)'}")
        return 0
    equivalent = known_equivalent()
    sample: list[Mutant] = []
    for group in args.group:
        pool = [m for path in sorted((root / GROUPS[group]).rglob("*.py"))
                for m in mutants_of(path, root)]
        sample += draw(pool, args.sample, args.seed)
    previous = json.loads(Path(args.rerun).read_text(encoding="utf-8")) if args.rerun else {}
    exercise_files = exercises_of_modules(root)
    workspace = Workspace(root)
    outcomes: list[Outcome] = []
    baseline: dict[tuple, float] = {}
    base_keys: dict[str, dict] = {}
    verify_passes: dict[str, bool] = {}  # exercise id -> verify passes it unmutated
    try:
        for mutant in sample:
            earlier = previous.get(mutant.key)
            if earlier and earlier["status"] in ("killed", "timeout"):
                # tests were only added since: what killed it still does
                outcomes.append(Outcome(mutant, earlier["status"], 0.0, earlier["verify"]))
                continue
            targets = list(coverage.get(mutant.module, []))
            if mutant.module.startswith(GROUPS["mechanics"]) and (root / DOCTESTS).exists():
                within = Path(mutant.module).relative_to(GROUPS["mechanics"]).with_suffix("")
                targets.append(f"{DOCTESTS}::test_the_notes_numbers_in_docstrings_hold"
                               f"[{'.'.join(within.parts)}]")
            if mutant.kind.startswith("equivalent") or mutant.key in equivalent:
                outcomes.append(Outcome(mutant, "equivalent"))
                continue
            if not targets:
                outcomes.append(Outcome(mutant, "no tests"))
                continue
            if tuple(targets) not in baseline and not args.check_baseline:
                baseline[tuple(targets)] = UNCHECKED_BASELINE_SECONDS
            if tuple(targets) not in baseline:
                status, seconds = workspace.pytest(targets, timeout=1800, slow=args.slow)
                if status != "survived":
                    print(f"the unmutated tests of {mutant.module} do not pass ({status}): "
                          f"{' '.join(targets)}", file=sys.stderr)
                    return 2
                baseline[tuple(targets)] = seconds
            original = (root / mutant.module).read_text(encoding="utf-8")
            workspace.write(mutant.module, mutant.source)
            try:
                status, seconds = workspace.pytest(
                    targets, timeout=args.timeout_factor * baseline[tuple(targets)] + 20,
                    slow=args.slow)
                outcome = Outcome(mutant, status, seconds)
                if args.verify and mutant.module.startswith(GROUPS["mechanics"]):
                    files = exercise_files.get(mutant.module, [])
                    if mutant.module not in base_keys:
                        workspace.write(mutant.module, original)
                        base_keys[mutant.module] = workspace.keys(files) if files else {}
                        workspace.write(mutant.module, mutant.source)
                    changed = changed_exercises(base_keys[mutant.module],
                                                workspace.keys(files) if files else {})
                    if changed:
                        workspace.write(mutant.module, original)
                        for exercise in set(changed) - set(verify_passes):
                            verify_passes[exercise] = not workspace.verify([exercise], args.variants)
                        workspace.write(mutant.module, mutant.source)
                        changed = [e for e in changed if verify_passes[e]]  # verify's own failures aside
                    if not changed:
                        outcome.verify = "no key change"
                    else:
                        caught = workspace.verify(changed, args.variants)
                        outcome.verify = ("caught" if caught else "missed") + f" ({', '.join(changed)})"
            finally:
                workspace.write(mutant.module, original)
            outcomes.append(outcome)
            if args.progress:
                print(f"  {outcome.status:9} {outcome.seconds:5.1f}s {mutant.key}"
                      + (f"  verify: {outcome.verify}" if outcome.verify else ""), file=sys.stderr)
    finally:
        workspace.close()
    if args.json:
        Path(args.json).write_text(json.dumps(
            {o.mutant.key: {"status": o.status, "verify": o.verify, "line": o.mutant.line}
             for o in outcomes}, indent=1), encoding="utf-8")
    return report(outcomes, args)


def report(outcomes: list[Outcome], args) -> int:
    failed = False
    print(f"mutation check: seed {args.seed}, {len(outcomes)} mutants")
    for group in args.group:
        mine = [o for o in outcomes if o.mutant.module.startswith(GROUPS[group])]
        by_module: dict[str, list[Outcome]] = {}
        for o in mine:
            by_module.setdefault(o.mutant.module, []).append(o)
        print(f"\n{group}:")
        for module, rows in sorted(by_module.items()):
            print(f"  {Path(module).name:24} {_score_text(rows)}")
        score = _score(mine)
        print(f"  {'all':24} {_score_text(mine)}")
        floor = args.floor.get(group) if args.floor else None
        if floor is not None and score is not None and score < floor:
            print(f"  FAIL: kill score {score:.1%} is below the floor {floor:.0%}")
            failed = True
    survivors = [o for o in outcomes if o.status in ("survived", "no tests")]
    print(f"\nsurvivors ({len(survivors)}):")
    for o in survivors:
        print(f"  {o.mutant.module}:{o.mutant.line} {o.mutant.function}: {o.mutant.kind}: "
              f"{o.mutant.before} -> {o.mutant.after}" + (" (no tests)" if o.status == "no tests" else ""))
    checked = [o for o in outcomes if o.verify.startswith(("caught", "missed"))]
    if args.verify:
        caught = sum(o.verify.startswith("caught") for o in checked)
        print(f"\nverify: caught {caught} of {len(checked)} core mutants that change an exercise's key"
              + (f" ({caught / len(checked):.0%})" if checked else ""))
        for o in checked:
            print(f"  {o.verify.split(' ')[0]:6} {o.mutant.key}  tests: {o.status}  exercises: "
                  f"{o.verify.partition(' ')[2]}")
    return 1 if failed else 0


def _score(rows: list[Outcome]) -> float | None:
    live = [o for o in rows if o.status != "equivalent"]
    return sum(o.status in ("killed", "timeout") for o in live) / len(live) if live else None


def _score_text(rows: list[Outcome]) -> str:
    killed = sum(o.status == "killed" for o in rows)
    timeout = sum(o.status == "timeout" for o in rows)
    equivalent = sum(o.status == "equivalent" for o in rows)
    live = len(rows) - equivalent
    score = _score(rows)
    shown = f"{score:6.1%}" if score is not None else "     -"
    return (f"{shown} killed {killed + timeout}/{live}"
            + (f" ({timeout} by timeout)" if timeout else "")
            + (f", {equivalent} equivalent" if equivalent else ""))


def _floors(text: str) -> dict[str, float]:
    out = {}
    for item in text.split(","):
        group, _, value = item.partition("=")
        out[group.strip()] = float(value)
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sample", type=int, default=CI_SAMPLE,
                        help="mutants per group (0: all); default: CI's size")
    parser.add_argument("--seed", type=int, default=29)
    parser.add_argument("--group", action="append", choices=sorted(GROUPS),
                        help="mechanics or grading (default: both)")
    parser.add_argument("--floor", type=_floors, default=None,
                        help="minimum kill scores, e.g. mechanics=0.9,grading=0.75 "
                             "(default: CI's floors at CI's size, none otherwise)")
    parser.add_argument("--verify", action="store_true",
                        help="also run core mutants that change a key through dynagrade verify")
    parser.add_argument("--variants", type=int, default=5, help="variants for verify")
    parser.add_argument("--timeout-factor", type=float, default=3.0)
    parser.add_argument("--slow", action="store_true",
                        help="run the tests marked slow too (tests/conftest.py; left out by default)")
    parser.add_argument("--root", default=str(ROOT), help="the project to mutate (a copy is made)")
    parser.add_argument("--check-baseline", action=argparse.BooleanOptionalAction, default=None,
                        help="first run each set of tests unmutated: they must pass, and their time "
                             "sets the timeout (default: on, off at CI's size)")
    parser.add_argument("--list-tests", action="store_true")
    parser.add_argument("--json", help="write every mutant's outcome to this file")
    parser.add_argument("--rerun", metavar="JSON",
                        help="an earlier run's --json: keep its kills, run the rest again")
    parser.add_argument("--progress", action="store_true", help="a line per mutant on stderr")
    args = parser.parse_args(argv)
    args.group = args.group or sorted(GROUPS)
    if args.sample == CI_SAMPLE:
        args.floor = CI_FLOORS if args.floor is None else args.floor
        args.check_baseline = False if args.check_baseline is None else args.check_baseline
    args.check_baseline = True if args.check_baseline is None else args.check_baseline
    return run(args)


if __name__ == "__main__":
    sys.exit(main())
