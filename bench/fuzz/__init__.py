"""The world fuzzer (issue 20, "keep it found"): random extreme worlds in every solver mode.

``worlds.build(rnd)`` makes one random world (shapes, densities 1e-6..1e6 kg/m^2, speeds to
1e5 m/s, springs to 1e9 N/m, dt 1e-5..1 s) and its run plan (steps, a mode switch);
``check.run_case(seed)`` runs it and judges the invariants; ``python -m bench.fuzz --cases N``
runs many with a progress bar and writes the counts (bench/results/fuzz_world.json and the
"World fuzzer" section of docs/reliability.md, report.py).
"""
