"""``python -m bench.reliability`` (see bench/reliability/__init__.py)."""
import sys

from .cli import main

sys.exit(main())
