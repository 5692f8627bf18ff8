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
#: The longest description read, in characters: five times the longest of the thousands the reader is
#: measured on (a pleading of about 1 800). A longer text is a whole document, not a scenario's
#: description, and the reader's time grows faster than its length.
MAX_DESCRIPTION = 10_000


def plain_text(text: str) -> str:
    """``text`` without escape sequences and control characters, its whitespace single spaces."""
    return " ".join(_CONTROLS.sub(" ", _ESCAPES.sub(" ", text)).split())


#: A line break as a text file writes one (not the vertical tab, form feed or separators ``str.splitlines``
#: also breaks at, which :func:`plain_text` takes out as control characters).
_LINE_BREAK = re.compile(r"\r\n|\r|\n")
#: A line's end that ends its sentence, field or table row, where the break after it stays.
_BREAK_KEPT = re.compile(r"[.!?:;)\]|]$")
#: A line's start that opens an item, a speaker's turn, a sentence, a table's row, a comment or heading,
#: or a tag ("- ", "2) ", "CT: ", "A van ...", "| 70 |", "# note", "@urban"), where the break before it
#: stays; a wrapped line goes on in lower case ("came\nout of a side road").
_LINE_OPENS = re.compile(
    r"(?:[-*\u2022\u00b7\u2013]\s|\d{1,2}[.)]\s|[^\W\d_][\w.'/-]*(?: [\w.'/-]+){0,2}:|[A-Z0-9\[|#@])"
)
#: The marks of a quoted mail's line ("> ", ">> "): the quote is the text ("> yesterday the car in\n> front
#: of me braked"); ">50 km/h", with no space, is "more than".
_QUOTE_MARKS = re.compile(r"^(?:>[ \t]?)*>[ \t]+")


def readable_description(text: str) -> str:
    """The description to read: :func:`plain_text` of each of ``text``'s lines; a VeiInputError when
    nothing is left to read (empty, blank, or no letter or digit at all) or when it is longer than
    :data:`MAX_DESCRIPTION`. A line break stays where it ends a sentence, a field or a table's row, or
    opens an item, a speaker's turn, a sentence, a row or a comment: a pasted list, form, transcript or
    feature file says by them where an item or a turn ends, and the reader reads them so. A blank line
    stays, as one, before a line that does not go on in lower case (a heading over its body, a table
    after its outline, "**Summary**" under a title). A break inside a sentence (a text wrapped at a
    width: "came" at one line's end, "out of a side road" at the next, with or without a blank line
    between) is a space, and a quoted mail's marks ("> ") go: the quote is the text. Why: ``vei
    describe`` reads the text the way :func:`~vei_scenario.language.reader.read` is measured on."""
    lines: list[str] = []
    after_blank: list[bool] = []  # (whether a blank line stands before each line kept)
    raw_prev = ""
    for line in (plain_text(_QUOTE_MARKS.sub("", raw)) for raw in _LINE_BREAK.split(text)):
        if line:
            after_blank.append(bool(lines) and not raw_prev)
            lines.append(line)
        raw_prev = line
    clean = "".join(
        line
        if k == 0
        else (
            ("\n\n" if after_blank[k] else "\n")
            if _BREAK_KEPT.search(lines[k - 1]) or _LINE_OPENS.match(line) or (after_blank[k] and not line[0].islower())
            else " "
        )
        + line
        for k, line in enumerate(lines)
    )
    if not clean:
        raise VeiInputError(None, "description", f"is empty: describe the scenario in words, e.g. '{EXAMPLE}'")
    if len(clean) > MAX_DESCRIPTION:
        raise VeiInputError(
            None,
            "description",
            f"is {len(clean)} characters long; vei describe reads up to {MAX_DESCRIPTION}: give the paragraph "
            "that tells what happened",
        )
    if not any(c.isalnum() for c in clean):
        raise VeiInputError(
            None, "description", f"has no words to read (only punctuation or symbols): e.g. '{EXAMPLE}'"
        )
    return clean
