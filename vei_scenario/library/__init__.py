"""Scenario libraries: a folder of clips compiled into scenarios with a ranked index
(``vei compile CLIPS/ -o LIBRARY/``)."""

from vei_scenario.library.build import LibraryResult, compile_library

__all__ = ["LibraryResult", "compile_library"]
