"""Every exercise in the bank: well-formed, and able to tell right from wrong.

`dynagrade verify --variants 200` is the full check; here each exercise runs a few
variants so that the suite stays fast, with seeds that differ between exercises.
"""

import re

import pytest

from dynagrade.exercise import open_bank
from dynagrade.exercise.loader import exercise_files, load_file
from dynagrade.exercise.verify import verify_exercise

from bank_ids import bank_ids

BANK = open_bank()
IDS = bank_ids()  # read from the files' text: collecting loads no exercise
VARIANTS = 8


@pytest.fixture(params=IDS)
def exercise(request):
    """Each exercise of the bank, loaded when its test runs."""
    return BANK.get(request.param)


def test_every_variant_can_tell_right_from_wrong(exercise):
    offset = sum(map(ord, exercise.id)) * 1000
    report = verify_exercise(exercise, range(offset, offset + VARIANTS))
    assert report.ok, "\n".join(report.failures[:10])


def test_every_exercise_names_its_source_in_the_notes(exercise):
    assert re.fullmatch(r"(Example \d+\.\d+|Section \d+(\.\d+)*)( .*)?", exercise.source)
    assert exercise.title and exercise.topics
    assert 1 <= exercise.chapter <= 5


def test_the_folder_matches_the_chapter(exercise):
    assert f"/ch{exercise.chapter}_" in exercise.path.replace("\\", "/")


def test_no_two_exercise_files_declare_the_same_id():
    # BANK.all() keeps one exercise per id, so the ids are counted file by file
    folders = sorted({folder.resolve() for folder in BANK.folders if folder.is_dir()})
    ids = [load_file(path).id for folder in folders for path in exercise_files(folder)]
    assert len(ids) == len(set(ids)), sorted(i for i in set(ids) if ids.count(i) > 1)
