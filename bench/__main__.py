"""``python -m bench``: the benchmark suite (see bench/cli.py)."""
from .cli import main

raise SystemExit(main())
