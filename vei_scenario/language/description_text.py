"""A description as ``vei describe`` reads it: terminal escapes and control characters taken out,
whitespace made plain within each line, and nothing to read refused.

Why: a description is pasted from anywhere (a terminal, a ticket, a chat), and it ends up in the
scenario's FileHeader, where XML allows no control characters, and on the user's console, where an
escape sequence would act. An empty description, or one of punctuation alone, would quietly give the
default scenario 32 times over: it is refused with what to write instead.
"""

from __future__ import annotations

import re

from vei_scenario.errors import VeiInputError

#: ANSI/VT escape sequences (CSI ... final byte, OSC ... BEL/ST, and two-character escapes).
_ESCAPES = re.compile(r"\x1b\[[0-?]*[ -/]*[@-~]|\x1b\][^\x07\x1b]*(?:\x07|\x1b\\)?|\x1b[@-Z\\-_]|\x9b[0-?]*[ -/]*[@-~]")
#: Characters XML 1.0 does not allow and C1 controls (besides those, whitespace is normalised below).
_CONTROLS = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\ud800-\udfff\ufffe\uffff]")

EXAMPLE = "an e-scooter crosses from the right in front of the ego at 30 km/h"


def plain_text(text: str) -> str:
    """``text`` without escape sequences and control characters, its whitespace single spaces."""
    return " ".join(_CONTROLS.sub(" ", _ESCAPES.sub(" ", text)).split())


def readable_description(text: str) -> str:
    """The description to read: :func:`plain_text` of each of ``text``'s lines, its blank lines left out;
    a VeiInputError when nothing is left to read (empty, blank, or no letter or digit at all). Its line
    breaks stay: a pasted list, form or transcript says by them where an item or a speaker's turn ends,
    and the reader reads them so."""
    clean = "\n".join(line for line in map(plain_text, text.splitlines()) if line)
    if not clean:
        raise VeiInputError(None, "description", f"is empty: describe the scenario in words, e.g. '{EXAMPLE}'")
    if not any(c.isalnum() for c in clean):
        raise VeiInputError(
            None, "description", f"has no words to read (only punctuation or symbols): e.g. '{EXAMPLE}'"
        )
    return clean
