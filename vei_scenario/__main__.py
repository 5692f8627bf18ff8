"""``python -m vei_scenario``: the same command line as ``vei``."""

import sys

from vei_scenario.cli import main

sys.exit(main())
