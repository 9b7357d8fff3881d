"""The scene-file fuzzer in the suite (issue 20, "keep it found").

Default run: a short fixed-seed tier, a few hundred cases (hypothesis, derandomized).
``pytest -m fuzz``: the long tier, FUZZ_CASES cases (default 5000) from FUZZ_SEED (default 1); the
counts are printed (run with -s) and, with FUZZ_REPORT=path, written there as JSON.
The invariants are scene_fuzz.check_case's (see its docstring).
"""
import json
import os
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent))
import scene_fuzz  # noqa: E402
from mutations import make_case  # noqa: E402

BASE = scene_fuzz.corpus()
SHORT = settings(derandomize=True, database=None, deadline=None, max_examples=250,
                 suppress_health_check=list(HealthCheck))


@pytest.fixture(scope="module")
def folder():
    with tempfile.TemporaryDirectory() as d:
        yield Path(d)


@SHORT
@given(rnd=st.randoms(use_true_random=False))
def test_mutated_shipped_scenes_load_or_raise_scene_error(folder, rnd):
    name, raw, done = make_case(rnd, BASE)
    scene_fuzz.check_case(folder / "case.json", raw, f"{name}: {', '.join(done)}")


def test_mutations_never_share_the_fuzzers_constants():
    """A case is its seed: no mutation may put a list or dict of the fuzzer's constants (or of the
    corpus) into a case, where a later mutation would edit it in place for every case after it.
    (m_unknown_key once did: case 1853 of seed 1 depended on the cases before it.)"""
    import copy
    import random
    import mutations

    def containers(*roots):
        out, stack = set(), list(roots)
        while stack:
            v = stack.pop()
            if isinstance(v, (list, dict)):
                out.add(id(v))
                stack += list(v.values()) if isinstance(v, dict) else v
        return out

    shared = containers(BASE, mutations.WEIRD_VALUES, mutations.SHAPES, mutations.DEGENERATE_POLYGONS)
    for i in range(400):
        rnd = random.Random(f"shared:{i}")
        data = copy.deepcopy(rnd.choice(BASE)[1])
        m = mutations.STRUCTURAL[i % len(mutations.STRUCTURAL)]
        m(rnd, data, mutations.Placeholders())
        assert not containers(data) & shared, f"{m.__name__} put a shared object into the case"


# -- scenes written by hypothesis, hostile at the leaves --------------------------------------
finite = st.floats(-1e6, 1e6, allow_nan=False)
hostile_number = st.one_of(st.floats(), st.integers(-10 ** 400, 10 ** 400), st.sampled_from([5e-324, 1e308, -0.0]))
hostile_text = st.text(st.characters(codec=None, categories=["L", "N", "P", "Cs", "Cc", "Zs"]), max_size=12)
leaf = st.one_of(st.none(), st.booleans(), hostile_number, hostile_text, st.lists(hostile_number, max_size=3))


def either(good, p_bad=0.15):
    return st.one_of(good, leaf) if p_bad else good


vec = st.one_of(st.lists(finite, min_size=2, max_size=2), leaf)
shape = st.one_of(
    st.fixed_dictionaries({"box": st.lists(st.one_of(st.floats(1e-3, 1e3), hostile_number), min_size=2, max_size=2)}),
    st.fixed_dictionaries({"circle": st.one_of(st.floats(1e-3, 1e3), hostile_number)}),
    st.fixed_dictionaries({"regular": st.fixed_dictionaries({"sides": st.one_of(st.integers(2, 70), leaf),
                                                             "radius": st.one_of(st.floats(1e-3, 1e3), leaf)})}),
    st.fixed_dictionaries({"polygon": st.lists(vec, min_size=0, max_size=8)}),
    leaf)
body = st.fixed_dictionaries(
    {"shape": shape, "position": vec},
    optional={"name": st.one_of(st.sampled_from(["a", "b", "c"]), hostile_text), "angle": either(finite),
              "velocity": vec, "density": st.one_of(st.floats(1e-6, 1e9), hostile_number),
              "restitution": either(st.floats(0, 1)), "friction": either(st.floats(0, 2)),
              "kind": st.one_of(st.sampled_from(["dynamic", "static", "kinematic"]), leaf)})
spring = st.fixed_dictionaries({"a": st.one_of(st.sampled_from(["a", "b", "c"]), leaf),
                                "b": st.one_of(st.sampled_from(["a", "b", None]), leaf),
                                "stiffness": st.one_of(st.floats(0, 1e9), hostile_number)},
                               optional={"damping": either(st.floats(0, 10)), "rest_length": either(st.floats(0, 5)),
                                         "anchor_a": vec, "anchor_b": vec})
world = st.fixed_dictionaries({}, optional={
    "gravity": vec, "dt": st.one_of(st.floats(1e-5, 1), hostile_number),
    "solver": st.one_of(st.sampled_from(["soft_step", "sequential_impulse", "impulse", "penalty", "hybrid"]), leaf),
    "settings": st.dictionaries(st.sampled_from(["substeps", "relax", "iterations", "warp"]), leaf, max_size=2),
    "sleeping": either(st.booleans())})
scene = st.fixed_dictionaries({"format": either(st.just("stelkropp.scene"), 0.05), "version": either(st.just(1), 0.05),
                               "bodies": st.lists(body, max_size=5)},
                              optional={"world": world, "springs": st.lists(spring, max_size=3),
                                        "name": hostile_text, "camera": st.dictionaries(hostile_text, leaf, max_size=2)})


@settings(SHORT, max_examples=120)
@given(data=scene, ascii_only=st.booleans())
def test_generated_hostile_scenes_load_or_raise_scene_error(folder, data, ascii_only):
    raw = json.dumps(data, ensure_ascii=ascii_only).encode("utf-8", "surrogatepass")
    scene_fuzz.check_case(folder / "generated.json", raw, f"generated: {raw[:300]!r}")


# -- the long tier ----------------------------------------------------------------------------
@pytest.mark.fuzz
def test_long_fuzz_run_has_no_crashes(folder):
    cases = int(os.environ.get("FUZZ_CASES", "5000"))
    seed = int(os.environ.get("FUZZ_SEED", "1"))
    counts = scene_fuzz.run(cases, seed, folder)
    text = json.dumps(counts, indent=2, default=dict)
    print(text)
    if os.environ.get("FUZZ_REPORT"):
        Path(os.environ["FUZZ_REPORT"]).write_text(text + "\n")
    assert counts["cases"] == cases and counts["loaded"] > cases // 10  # the valid quarter does load
    assert counts["crashes"] == 0, "\n".join(counts["violations"][:20])
