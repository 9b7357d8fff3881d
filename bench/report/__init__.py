"""Reporting a benchmark run: tables (tables.py), the summary on the targets (summary.py), the
terminal report (terminal.py), docs/benchmarks.md (docs.py) and the result files (files.py)."""
