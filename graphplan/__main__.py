"""`python -m graphplan` is the same program as the `graphplan` console script."""
import sys

from graphplan.cli.main import main

sys.exit(main())
