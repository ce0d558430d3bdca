"""`python -m graphplan` is the same program as the `graphplan` console script."""
import sys

from .cli import main

sys.exit(main())
