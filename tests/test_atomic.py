"""Files written whole or not at all (`turntable._atomic`)."""

from __future__ import annotations

import stat

import pytest

from turntable._atomic import replacing, write_text


def test_write_text_replaces_the_file_and_leaves_nothing_beside(tmp_path):
    target = tmp_path / "out.json"
    target.write_text("old")
    write_text(target, "new ✓")
    assert target.read_text(encoding="utf-8") == "new ✓"
    assert [p.name for p in tmp_path.iterdir()] == ["out.json"]
    assert stat.S_IMODE(target.stat().st_mode) == 0o644


def test_a_failed_write_keeps_the_old_file_and_removes_the_temporary_one(tmp_path):
    target = tmp_path / "figure.png"
    target.write_text("old")

    def interrupted() -> None:
        with replacing(target) as tmp:
            tmp.write_text("half")
            raise RuntimeError("interrupted")

    with pytest.raises(RuntimeError, match="interrupted"):
        interrupted()
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["figure.png"]


def test_the_temporary_file_is_hidden_beside_the_target_with_its_suffix(tmp_path):
    with replacing(tmp_path / "ball.mp4") as tmp:
        assert tmp.parent == tmp_path
        assert tmp.name.startswith(".ball.mp4.")
        assert tmp.suffix == ".mp4"
        assert not (tmp_path / "ball.mp4").exists()
    assert (tmp_path / "ball.mp4").exists()
