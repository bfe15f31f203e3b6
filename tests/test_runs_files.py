"""Every file dynagrade writes: only over a regular file or nothing, private ones 0600
(issue 26, item 1).

The device is a stand-in made by the test in its own temporary folder (the numbers of
``/dev/null``, which only root may make), never the real one.
"""

from __future__ import annotations

import os
import socket
import stat
from pathlib import Path

import pytest
from click.testing import CliRunner

from dynagrade.cli import main
from dynagrade.errors import DynagradeError
from dynagrade.runs.files import OutputFileError, write_atomic
from serve_support import exam_copy, exam_dir  # noqa: F401


def _device(folder: Path) -> Path:
    """A character device with the numbers of /dev/null, in ``folder``."""
    if os.geteuid() != 0:
        pytest.skip("making a device node needs root (mknod)")
    path = folder / "null"
    os.mknod(path, stat.S_IFCHR | 0o600, os.makedev(1, 3))
    return path


def _fifo(folder: Path) -> Path:
    path = folder / "pipe"
    os.mkfifo(path)
    return path


def _socket(folder: Path) -> Path:
    path = folder / "sock"
    listener = socket.socket(socket.AF_UNIX)
    listener.bind(str(path))
    listener.close()  # the socket file stays
    return path


def _link_outside(folder: Path) -> Path:
    outside = folder.parent / f"{folder.name}-outside.txt"
    outside.write_text("someone else's file\n")
    path = folder / "link"
    path.symlink_to(outside)
    return path


def _folder(folder: Path) -> Path:
    path = folder / "sub"
    path.mkdir()
    (path / "kept.txt").write_text("kept\n")
    return path


TARGETS = {"character device": (_device, "a character device"),
           "FIFO": (_fifo, "a FIFO"),
           "socket": (_socket, "a socket"),
           "symbolic link": (_link_outside, "a symbolic link"),
           "folder": (_folder, "a folder")}


def _state(path: Path) -> tuple:
    """What the test compares before and after: the node itself and what a link or a
    folder leads to."""
    status = os.lstat(path)
    behind = path.resolve().read_text() if path.is_symlink() else \
        sorted(p.name for p in path.iterdir()) if path.is_dir() else None
    return status.st_ino, status.st_mode, status.st_rdev, behind


@pytest.mark.parametrize("kind", list(TARGETS))
def test_write_atomic_refuses_what_is_not_a_regular_file(tmp_path, kind):
    make, named = TARGETS[kind]
    target = make(tmp_path)
    before = _state(target)
    with pytest.raises(OutputFileError) as refused:
        write_atomic(target, "secret links\n", private=True)
    assert isinstance(refused.value, DynagradeError)
    assert str(target) in str(refused.value) and named in str(refused.value)
    assert _state(target) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == [target.name]  # no temporary left


def test_write_atomic_replaces_a_regular_file_and_sets_the_modes(tmp_path):
    plain = tmp_path / "plain.txt"
    plain.write_text("old")
    write_atomic(plain, "new")
    assert plain.read_text() == "new"
    assert stat.S_IMODE(plain.stat().st_mode) == 0o666 & ~_umask()
    private = tmp_path / "made" / "key.csv"
    write_atomic(private, "student,answer\n", private=True)
    assert stat.S_IMODE(private.stat().st_mode) == 0o600
    assert stat.S_IMODE(private.parent.stat().st_mode) == 0o700
    plain.chmod(0o644)
    write_atomic(plain, "private now", private=True)  # a replaced file takes the new mode
    assert stat.S_IMODE(plain.stat().st_mode) == 0o600



@pytest.mark.parametrize("leftover", ["file", "link"])
def test_a_temporary_left_by_a_killed_run_of_this_process_id_is_removed_not_followed(
        tmp_path, leftover):
    target = tmp_path / "sheet.md"
    temporary = tmp_path / f".sheet.md.{os.getpid()}.tmp"
    elsewhere = tmp_path / "elsewhere.txt"
    elsewhere.write_text("untouched")
    if leftover == "file":
        temporary.write_text("half-written")
    else:
        temporary.symlink_to(elsewhere)
    write_atomic(target, "whole")
    assert target.read_text() == "whole"
    assert elsewhere.read_text() == "untouched"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["elsewhere.txt", "sheet.md"]


def test_write_atomic_makes_missing_folders_on_the_way(tmp_path):
    deep = tmp_path / "students" / "s-001" / "sheet.html"
    write_atomic(deep, "<p>hi</p>")
    assert deep.read_text() == "<p>hi</p>"

def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _links(manifest: Path, out: Path):
    return CliRunner().invoke(main, ["links", str(manifest), "-o", str(out)])


@pytest.mark.parametrize("kind", ["character device", "FIFO", "symbolic link"])
def test_links_refuses_an_output_that_is_not_a_regular_file(exam_dir, tmp_path, kind):
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    make, named = TARGETS[kind]
    target = make(tmp_path / "exam")
    before = _state(target)
    result = _links(manifest, target)
    assert result.exit_code == 1
    assert result.output.strip().splitlines() == \
        [line for line in result.output.strip().splitlines() if line.startswith("Error: ")]
    assert f"{target}: is {named}" in result.output and "Traceback" not in result.output
    assert _state(target) == before
    # refused before any link was made: a later run writes every student's link
    good = tmp_path / "links.csv"
    assert _links(manifest, good).exit_code == 0
    assert all(row.split(",")[-1].strip() for row in good.read_text().splitlines()[1:])


def test_sheet_and_figure_refuse_a_fifo(tmp_path):
    fifo = _fifo(tmp_path)
    for command in (["sheet", "projectile-range", "--student", "s1", "-o", str(fifo)],
                    ["show", "projectile-range", "--figure", str(fifo)]):
        result = CliRunner().invoke(main, command)
        assert result.exit_code == 1 and f"{fifo}: is a FIFO" in result.output, result.output
        assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_secrets_keys_manifests_links_and_the_database_are_private(exam_dir, tmp_path):
    for name in ("key.csv", "manifest.json"):
        assert stat.S_IMODE((exam_dir / name).stat().st_mode) == 0o600, name
    assert stat.S_IMODE(exam_dir.stat().st_mode) == 0o700
    manifest = exam_copy(exam_dir, tmp_path / "exam")
    out = tmp_path / "links.csv"
    assert _links(manifest, out).exit_code == 0
    assert stat.S_IMODE(out.stat().st_mode) == 0o600
    database = tmp_path / "exam.serve.sqlite3"  # beside the exam folder
    assert stat.S_IMODE(database.stat().st_mode) == 0o600
    for companion in tmp_path.glob("exam.serve.sqlite3-*"):  # -wal, -shm: SQLite's own
        assert stat.S_IMODE(companion.stat().st_mode) == 0o600, companion.name


def test_a_new_secret_file_is_private_in_a_private_folder(tmp_path):
    from dynagrade.exam.secret import load_secret

    path = tmp_path / "secrets" / "exam.secret"
    secret = load_secret(path)
    assert path.read_text() == secret + "\n"
    assert stat.S_IMODE(path.stat().st_mode) == 0o600
    assert stat.S_IMODE(path.parent.stat().st_mode) == 0o700
