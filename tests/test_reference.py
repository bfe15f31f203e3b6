"""The notes' own chapter-1 results (reference/ch1.toml) against the mechanics core and
against the exercises built on them.

Each entry's expression is parsed with dynagrade's grading parser (never eval) and
evaluated at random points of its variables' domains (hypothesis); the core function
named in the entry must give the same value.  Entries that name an exercise part are
also compared with that part's reference answer for a handful of variants.
"""
import importlib
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dynagrade.grading.evaluate import evaluate
from dynagrade.grading.parser import parse_expression

REFERENCE = Path(__file__).resolve().parents[1] / "reference" / "ch1.toml"
ENTRIES = tomllib.loads(REFERENCE.read_text(encoding="utf-8"))["result"]
IDS = [f"{e['source']}: {e['name']}" for e in ENTRIES]


def _value(text, names, env):
    return float(evaluate(parse_expression(text, names), {k: np.float64(v) for k, v in env.items()}))


def _arguments(entry, env):
    names = tuple(entry["domain"])
    args = {}
    for arg, text in entry["args"].items():
        if isinstance(text, list):
            args[arg] = np.array([_value(t, names, env) for t in text])
        else:
            args[arg] = _value(text, names, env)
    return args


def _core(entry, env):
    module, _, name = entry["function"].rpartition(".")
    result = getattr(importlib.import_module(module), name)(**_arguments(entry, env))
    select = entry.get("select")
    if select is None:
        return float(result)
    if select == "norm":
        return float(np.linalg.norm(result))
    if isinstance(select, int):
        return float(np.asarray(result)[select])
    return float(getattr(result, select))


def test_reference_file_covers_every_worked_example_of_chapter_1():
    sources = " ".join(e["source"] for e in ENTRIES)
    for n in range(1, 20):
        if n == 4:          # Example 1.4 counts degrees of freedom; tested in the kinematics suite
            continue
        assert f"Example 1.{n}," in sources or f"Example 1.{n} " in sources, n
    assert "Section 1.2.4" in sources


@pytest.mark.parametrize("entry", ENTRIES, ids=IDS)
def test_reference_entry_is_well_formed(entry):
    names = tuple(entry["domain"])
    parse_expression(entry["expression"], names)
    for text in entry["args"].values():
        for t in (text if isinstance(text, list) else [text]):
            parse_expression(t, names)
    module, _, name = entry["function"].rpartition(".")
    assert callable(getattr(importlib.import_module(module), name))
    for low, high in entry["domain"].values():
        assert low <= high
    if "scale" in entry:
        parse_expression(entry["scale"], names)


@pytest.mark.parametrize("entry", ENTRIES, ids=IDS)
@settings(max_examples=15, deadline=None)
@given(data=st.data())
def test_core_reproduces_the_notes_result_throughout_the_domain(entry, data):
    env = {name: data.draw(st.floats(low, high), label=name)
           for name, (low, high) in entry["domain"].items()}
    names = tuple(entry["domain"])
    expected = _value(entry["expression"], names, env)
    scale = abs(_value(entry["scale"], names, env)) if "scale" in entry else abs(expected)
    got = _core(entry, env)
    assert got == pytest.approx(expected, rel=1e-9, abs=1e-10 * (1e-3 + scale))


CROSS = [e for e in ENTRIES if "exercise" in e]


@pytest.mark.parametrize("entry", CROSS, ids=[f"{e['exercise']}:{e['part']}" for e in CROSS])
def test_exercise_answer_equals_the_notes_result(entry, bank):
    exercise = bank.get(entry["exercise"])
    renames = entry.get("exercise_vars", {})
    fixed = entry.get("exercise_fixed", {})
    for seed in range(5):
        values, _ = exercise.draw(seed)
        p = exercise.si(values)
        env = {name: fixed[name] if name in fixed else getattr(p, renames.get(name, name))
               for name in entry["domain"]}
        expected = _value(entry["expression"], tuple(entry["domain"]), env)
        answer = exercise.solve(p)[entry["part"]]
        assert float(answer) == pytest.approx(expected, rel=1e-9, abs=1e-12), seed
