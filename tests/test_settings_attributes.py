"""A mode's settings as attributes (``world.settings.iterations = 20``): the same validation as
items, and an unknown or misspelt name raises instead of being stored and then ignored."""
import copy
import pickle

import pytest

import physics
from physics.settings import UnknownSetting


def test_an_attribute_reads_and_writes_the_setting():
    w = physics.World(solver="soft_step")
    w.settings.iterations = 7
    assert w.settings["iterations"] == 7
    w.settings["substeps"] = 6
    assert w.settings.substeps == 6
    # the step reads it: the mode's parameter record takes the new value
    assert w._pipeline.params(w).get("substeps") == 6


def test_a_misspelt_setting_raises_naming_it():
    w = physics.World(solver="soft_step")
    with pytest.raises(UnknownSetting, match="iteratons"):
        w.settings.iteratons = 3
    with pytest.raises(AttributeError, match="iteratons"):
        w.settings.iteratons  # noqa: B018  (reading it raises too)
    assert not hasattr(w.settings, "iteratons")


def test_a_bad_value_is_refused_as_for_items():
    w = physics.World(solver="soft_step")
    with pytest.raises(ValueError, match="iterations"):
        w.settings.iterations = -1
    assert w.settings.iterations == w.settings["iterations"]


def test_every_setting_is_listed_and_the_view_copies():
    w = physics.World(solver="sequential_impulse")
    assert set(w.settings.keys()) <= set(dir(w.settings))
    w.settings.velocity_iterations = 11
    for other in (copy.copy(w.settings), pickle.loads(pickle.dumps(w.settings))):
        assert other.velocity_iterations == 11
