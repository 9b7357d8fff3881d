"""Stelkropp's benchmark: speed and accuracy against pymunk and pybox2d, and reliability at the
extremes.

    python -m bench [--quick]            # the suite (cli.py) -> bench/results/, docs/benchmarks.md
    python -m bench.reliability          # the extreme scenarios in every mode -> docs/reliability.md
    python -m bench.profile              # where one scene's step goes
    python -m bench.collision            # broad and narrow phase on their own

One concept per module, imports running one way (top to bottom):

* cli.py, session.py -- the command line; one run of the chosen parts into one result dict.
* report/ -- tables, the terminal report, docs/benchmarks.md, the result files; plots.py.
* speed.py, scaling.py, accuracy_runs.py, profile.py, overhead.py, startup.py -- the parts.
* timing.py (interleaved chunks), metrics.py (penetration, drift), accuracy.py (scenarios with
  known answers).
* cases.py, configs.py, scenes.py, desc.py -- plain data: cases, solver configurations, the
  benchmark scenes, scene descriptions.  A case carries its description and settings, never
  live objects, so it runs the same in any process.
* engines/ -- one module per engine behind one ``Sim`` interface (ours, pymunk, pybox2d).
* scenarios/extremes/ -- the extreme scenarios that bench.reliability and tests/extremes share.
"""
