"""``python -m vei_scenario``: the same command line as ``vei``."""

from vei_scenario.cli import console

console()
