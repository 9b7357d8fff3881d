"""soft_step chooses its sub-steps from the scene (physics/solvers/soft_step/fit.py): eight for a
dynamic shape thinner than 2 linear slops (1 cm), a dynamic body smaller than 20 (10 cm) or one
above a body at least 100 times lighter, else the declared four; it says what it chose and why,
and a user's setting always wins.

The thresholds come from Box2D v3's samples (docs/reliability.md): the Card House's 2 mm cards
and the Tiny Pyramid's 5 cm boxes fail at four sub-steps and hold at eight
(tests/accuracy/test_scene_fit_figures.py measures them in the default mode), and so does
HighMassRatio2's 400 kg box dropped on 1 kg boxes; no speed-suite scene and no shipped scene but
mass_ratio.json is chosen for (their cost is unchanged).
"""
import json

import pytest

import physics
from physics.scene import load_scene, save_scene
from physics.solvers.soft_step.fit import SUBSTEPS


def world_with(*sizes, kind="dynamic"):
    """A ground and one dynamic box per (width, height)."""
    w = physics.World(sleeping=False)
    w.add_body(physics.Polygon.box(20, 1), position=(0, -0.5), kind="static")
    for i, (bw, bh) in enumerate(sizes):
        w.add_body(physics.Polygon.box(bw, bh), position=(2.0 * i, 0.5 * bh + 0.01), kind=kind, name=f"b{i}")
    return w


def h_of(world):
    """The sub-step length the step runs with."""
    world.step()
    return world._pipeline.params(world).get("h")


def test_a_pile_of_metre_boxes_keeps_four_sub_steps():
    w = world_with((1, 1), (1, 1), (0.2, 1.0))
    assert w.settings.chosen() == {} and w.settings["substeps"] == 4
    assert h_of(w) == pytest.approx(w.dt / 4)


def test_a_card_is_thin_and_gets_eight_with_the_reason():
    w = world_with((1, 1), (0.002, 0.4))
    value, why = w.settings.chosen()["substeps"]
    assert value == SUBSTEPS == w.settings["substeps"]
    assert "thin" in why and "'b1'" in why and "2 mm" in why
    assert h_of(w) == pytest.approx(w.dt / SUBSTEPS)


def test_a_five_centimetre_box_is_small_and_gets_eight():
    w = world_with((0.05, 0.05))
    value, why = w.settings.chosen()["substeps"]
    assert value == SUBSTEPS and "small" in why and "50 mm" in why


@pytest.mark.parametrize("sizes", [[(0.05, 1.0)], [(0.001, 0.005)]], ids=["rod", "speck"])
def test_a_rod_is_not_thin_and_a_speck_counts_as_small(sizes):
    """A 5 cm x 1 m rod is neither (a pendulum's rod keeps four); a 1 x 5 mm speck is not a
    card (its long side is short) but it is small."""
    w = world_with(*sizes)
    chosen = w.settings.chosen()
    if sizes[0][1] >= 1.0:
        assert chosen == {}
    else:
        assert "small" in chosen["substeps"][1]


def test_static_and_kinematic_bodies_do_not_count():
    assert world_with((0.002, 0.4), kind="static").settings.chosen() == {}
    assert world_with((0.05, 0.05), kind="kinematic").settings.chosen() == {}


def test_the_users_setting_wins_and_del_hands_it_back():
    w = world_with((0.002, 0.4))
    w.settings["substeps"] = 4
    assert w.settings["substeps"] == 4 and w.settings.chosen() == {}
    assert h_of(w) == pytest.approx(w.dt / 4)
    del w.settings["substeps"]
    assert w.settings["substeps"] == SUBSTEPS
    assert h_of(w) == pytest.approx(w.dt / SUBSTEPS)


def test_the_choice_follows_edits():
    w = world_with((1, 1))
    assert w.settings.chosen() == {}
    card = w.add_body(physics.Polygon.box(0.002, 0.4), position=(3, 1))
    w.step()
    assert w.settings.chosen()["substeps"][0] == SUBSTEPS
    w.remove(card)
    w.step()
    assert w.settings.chosen() == {} and h_of(w) == pytest.approx(w.dt / 4)


def test_the_thresholds_are_in_linear_slops():
    """At a tenth of the default slop (0.5 mm) a 5 cm box is 100 slops: not small."""
    w = world_with((0.05, 0.05))
    assert w.settings.chosen()
    w.linear_slop = 0.0005
    w.step()
    assert w.settings.chosen() == {}


def test_info_and_the_cli_say_what_was_chosen(tmp_path, capsys):
    w = world_with((0.002, 0.4))
    info = w.info()
    assert info["chosen"]["substeps"]["value"] == SUBSTEPS and "thin" in info["chosen"]["substeps"]["why"]
    assert info["settings"]["substeps"] == SUBSTEPS
    path = tmp_path / "card.json"
    save_scene(w, path)
    from physics.cli import main
    assert main(["info", str(path)]) == 0
    out = capsys.readouterr().out
    assert f"chosen:     substeps={SUBSTEPS} (thin shapes" in out


def test_a_saved_scene_chooses_again_and_keeps_the_users_value(tmp_path):
    """The chosen value is not written (the loaded scene chooses again, so it follows later
    edits); a value the user set is written, even when it equals the default, and wins on loading."""
    w = world_with((0.002, 0.4))
    save_scene(w, tmp_path / "a.json")
    assert "substeps" not in json.loads((tmp_path / "a.json").read_text())["world"]["settings"]
    assert load_scene(tmp_path / "a.json").settings.chosen()["substeps"][0] == SUBSTEPS
    w.settings["substeps"] = 4
    save_scene(w, tmp_path / "b.json")
    assert json.loads((tmp_path / "b.json").read_text())["world"]["settings"]["substeps"] == 4
    back = load_scene(tmp_path / "b.json")
    assert back.settings["substeps"] == 4 and back.settings.chosen() == {}


def heavy_over_light(dx=0.0, dy=2.0, ratio=400.0, gravity=(0.0, -10.0)):
    """A 1 kg box on the ground and a box ``ratio`` times heavier at (dx, dy) from it."""
    w = physics.World(sleeping=False, gravity=gravity)
    w.add_body(physics.Polygon.box(20, 1), position=(0, -0.5), kind="static")
    w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5), name="light")
    w.add_body(physics.Polygon.box(2, 2), position=(dx, 0.5 + dy), density=ratio / 4.0, name="heavy")
    return w


def test_a_heavy_body_above_a_light_one_gets_eight():
    """Falling onto it (2 m up) or resting on it (1.5 m: touching) at 400:1, Box2D v3's
    HighMassRatio2 ratio; HighMassRatio2 sinks 0.49 m at four sub-steps and 0.018 m at eight."""
    for dy in (2.0, 1.5):
        value, why = heavy_over_light(dy=dy).settings.chosen()["substeps"]
        assert value == SUBSTEPS and "mass ratio" in why and "'heavy' (400 kg) is above body 'light' (1 kg)" in why


def test_a_body_a_thousand_times_heavier_also_gets_the_stiffest_contacts():
    """At 1000:1 the contacts take a quarter of the rate of eight sub-steps (120 Hz at dt 1/60:
    fit.py's module doc); at 400:1 they keep the default; the user's own value wins."""
    w = heavy_over_light(dy=1.5, ratio=1000.0)
    hz, why = w.settings.chosen()["contact_hertz"]
    assert hz == pytest.approx(0.25 * SUBSTEPS / w.dt) and "1000:1" in why
    assert w.settings["contact_hertz"] == hz and w.settings.chosen()["substeps"][0] == SUBSTEPS
    assert "contact_hertz" not in heavy_over_light(dy=1.5, ratio=400.0).settings.chosen()
    w.settings["contact_hertz"] = 30.0
    assert w.settings["contact_hertz"] == 30.0 and "contact_hertz" not in w.settings.chosen()


@pytest.mark.parametrize("case", ["beside", "below", "weightless", "light_enough"])
def test_a_heavy_body_beside_or_below_or_weightless_or_99_to_1_does_not(case):
    w = {"beside": lambda: heavy_over_light(dx=3.0),
         "below": lambda: heavy_over_light(gravity=(0.0, 10.0)),  # gravity up: the heavy box is below
         "weightless": lambda: heavy_over_light(gravity=(0.0, 0.0)),
         "light_enough": lambda: heavy_over_light(ratio=99.0)}[case]()
    assert w.settings.chosen() == {}


def test_shipped_scenes_choose_nothing_but_the_mass_ratio_one():
    """No other shipped scene has a thin, small or heavy-over-light dynamic body: their speed and
    recorded end states stay.  scenes/mass_ratio.json (100 kg on 1 kg) is there to show it."""
    from pathlib import Path
    root = Path(__file__).resolve().parent.parent / "scenes"
    chosen = {p.stem: load_scene(p).settings.chosen() for p in sorted(root.glob("*.json")) if "schema" not in p.name}
    assert len(chosen) > 20 and {k for k, c in chosen.items() if c} == {"mass_ratio"}, chosen
    assert "mass ratio" in chosen["mass_ratio"]["substeps"][1]
