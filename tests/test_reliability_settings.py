"""``python -m bench.reliability --samples --set NAME=VALUE``: the samples beside Box2D v3 run with
soft_step settings other than the defaults (how issue 18's experiments are measured:
bench/results/issue18_experiments.md), and a bad setting is an error naming it."""
from __future__ import annotations

import pytest

from bench.reliability import cli
from bench.reliability.samples import measure_ours, parse_settings, run_ours


def test_settings_are_parsed_by_their_declared_type():
    got = parse_settings(["substeps=8", "contact_hertz=30", "block_solver=off", "solver_layout=coloured"])
    assert got == {"substeps": 8, "contact_hertz": 30.0, "block_solver": False, "solver_layout": "coloured"}
    assert isinstance(got["substeps"], int)


@pytest.mark.parametrize("bad, named", [(["substeps=0"], "substeps"), (["relax=maybe"], "relax"),
                                        (["contact_hertz=abc"], "contact_hertz"), (["nosuch=1"], "nosuch"),
                                        (["substeps"], "substeps")])
def test_a_bad_setting_is_an_error_naming_it(bad, named):
    with pytest.raises(ValueError, match=named):
        parse_settings(bad)


def test_the_cli_refuses_a_bad_setting_before_running_anything(capsys):
    with pytest.raises(SystemExit) as e:
        cli.main(["--samples", "--only", "small_stack", "--set", "damping_ratio=-1"])
    assert e.value.code == 2
    assert "damping_ratio" in capsys.readouterr().err


def test_the_settings_reach_the_world_and_change_the_figure():
    """Five 1 cm boxes: a soft contact's static deflection is C = a / omega^2 (Catto, Solver2D
    2024), so a quarter of the frequency (15 Hz against 60, stiffening capped at 4x the mode's
    frequency: constraints/contact_stiffness.py) must sink the stack several times deeper."""
    _, _, sim = run_ours("small_stack", 0.1, settings={"contact_hertz": 15.0, "damping_ratio": 1.0})
    assert sim.world.settings["contact_hertz"] == 15.0 and sim.world.settings["damping_ratio"] == 1.0
    soft = {d["id"]: d["value"] for d, _ in measure_ours("small_stack", progress=False,
                                                          settings={"contact_hertz": 15.0})}
    stock = {d["id"]: d["value"] for d, _ in measure_ours("small_stack", progress=False)}
    assert soft["small_stack.sink_4s"] > 3.0 * stock["small_stack.sink_4s"] > 0.0


def test_a_figure_keeps_the_substeps_its_id_names():
    """``--set substeps=N`` applies to the figures that ask for no sub-step count; the cart's
    ``substeps12`` figures name theirs, so a run under ``substeps=8`` must still step them at 12."""
    _, _, own = run_ours("cart", 0.05, substeps=12, scene_kw={"substeps": 12}, settings={"substeps": 8})
    _, _, rest = run_ours("small_stack", 0.05, settings={"substeps": 8})
    _, _, stock = run_ours("vertical_stack", 0.05)
    _, _, small = run_ours("small_stack", 0.05)
    assert own.world.settings["substeps"] == 12
    assert rest.world.settings["substeps"] == 8
    # with no count given the world chooses: 4 for 1 m boxes, 8 for 1 cm ones (solvers/soft_step/fit.py)
    assert stock.world.settings["substeps"] == 4 and stock.world.settings.chosen() == {}
    assert small.world.settings["substeps"] == 8 and "small" in small.world.settings.chosen()["substeps"][1]
