"""The world fuzzer in the suite (issue 20, "keep it found"): bench/fuzz's random extreme worlds.

Each case is judged by bench/fuzz/check.py's invariants: only ValueError / SimulationError
naming its stage (world.fault set), no silent non-finite state, no energy above the energy
guard's stated bound without a motor (physics/step/energy_guard.py: the guard must have
refused such a step), no hang.

- short tier (default suite): SHORT_CASES fixed cases of seed 1, about a minute here;
- long tier (``pytest -m fuzz``): FUZZ_CASES cases (default 5000) from FUZZ_SEED (default 1);
  ``python -m bench.fuzz --cases 20000 --jobs 2`` is the same run with a progress bar and the
  counts written to docs/reliability.md.
"""
import os

import pytest

from bench.fuzz.check import BAD, run_case, warm_up

SHORT_CASES = 200


def failures(seed: int, cases: int) -> list:
    warm_up()
    return [(i, c["outcome"], c.get("mode"), c.get("detail"))
            for i, c in ((i, run_case(i, seed)) for i in range(cases)) if c["outcome"] in BAD]


def test_short_world_fuzz_tier():
    assert failures(1, SHORT_CASES) == []


@pytest.mark.fuzz
def test_long_world_fuzz_tier():
    seed = int(os.environ.get("FUZZ_SEED", "1"))
    assert failures(seed, int(os.environ.get("FUZZ_CASES", "5000"))) == []
