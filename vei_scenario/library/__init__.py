"""From a dataset to scenarios: a long recording cut into interaction clips (``vei clip split``,
:mod:`vei_scenario.library.split`) and a folder of clips compiled into a ranked scenario library
(``vei compile CLIPS/ -o LIBRARY/``, :mod:`vei_scenario.library.build`)."""

from vei_scenario.library.build import LibraryResult, compile_library

__all__ = ["LibraryResult", "compile_library"]
