"""The joint and shape speed commands (bench/joint_speed.py, bench/shape_speed.py) share one table
and one command line: each table names what its scenes are made of, and an unknown scene is an
error naming the known ones, before anything is measured."""
import pytest

from bench import joint_speed, shape_speed

ROW = dict(scene="s", bodies=1, joints=2, fixtures=3, steps=4, ms_ours=1.0, ms_pymunk=0.5, ratio=2.0,
           first_step_s=0.1, status="ok")


@pytest.mark.parametrize("count,value", [("joints", "2"), ("fixtures", "3")])
def test_each_table_shows_its_own_count(count, value):
    hdr, _, row = joint_speed.table_md([ROW], count)
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert count in hdr and cells[2] == value and cells[6] == "2.00"


@pytest.mark.parametrize("mod,known", [(joint_speed, "pendulum"), (shape_speed, "compounds")])
def test_unknown_scene_is_refused_naming_the_known_ones(mod, known, capsys):
    with pytest.raises(SystemExit) as info:
        mod.main(["--scenes", "nope"])
    assert info.value.code == 2
    err = capsys.readouterr().err
    assert "unknown scene: nope" in err and known in err
