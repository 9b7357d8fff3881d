"""``python -m physics simulate|validate|info ...`` (see physics/cli.py)."""
import sys

from .cli import main

sys.exit(main())
