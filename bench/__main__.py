"""python -m bench [--reps N] [--out bench/results.json]: the benchmark table."""

import sys

from .bench import main

sys.exit(main())
