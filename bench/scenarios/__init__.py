"""Scenarios shared by the benchmark and the tests (``extremes``: the extreme regimes that
``python -m bench.reliability`` tabulates and ``tests/extremes/`` asserts)."""
