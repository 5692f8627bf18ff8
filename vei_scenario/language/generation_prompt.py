"""The syntax of prompts for text-to-image and text-to-video generators, read as what it means.

People who want a clip of a traffic situation rendered write it as a generator's prompt, and the
same description then reaches vei. Three parts of that syntax are no scene words as written:

- a **negative prompt** ("Negative prompt: crash, daylight, cartoon", ``"negative_prompt": "..."``,
  Midjourney's ``--no crash``) lists what the clip must *not* show: read as the scene, "crash" would
  make a collision of a calm clip;
- **generation settings** after a double dash (``--ar 16:9``, ``--seed 1207``, ``--motion 6``) are
  the tool's, not the scene's;
- **prompt weights** (``(heavy rain:1.3)``, ``((near miss))``, ``wrong-way driver::2``) say how much a
  phrase counts; the phrase is the scene's, the weight is not.

Each is found by its syntax (the label and its colon, the double dash, the number after a colon in
brackets), never by the words inside it. The words set aside are reported as not used.
"""

from __future__ import annotations

import re

#: A negative prompt's label at the start of a line or after a field's quote ("Negative prompt:",
#: "negative:", "neg prompt =", "negative_prompt": "...") and what it lists: up to the line's end, or in
#: a JSON-like field, up to the field's closing quote.
_NEGATIVE = re.compile(
    r"""(?imx)
    (?:^[\s*>#-]*|(?<=[{,])\s*(?=["'])|(?<=[.!?;|]\s)(?=neg(?:ative)?[\s_-]*prompt))
    # (a line's label; a quoted key of a field; "negative prompt" in full after a sentence's end)
    ["']?\bneg(?:ative)?(?:[\s_-]*prompts?)?["']?\s*[:=]\s*
    (?:"(?P<quoted>[^"\n]*)"|(?P<line>[^\n]*))
    """
)
#: Midjourney's negative parameter: "--no" and the words up to the next parameter or the line's end.
_NO = re.compile(r"(?im)(?:^|(?<=\s))--no\s+(?P<line>[^\n]*?)(?=\s--[a-z]|$)")
#: A generator's setting: a double dash, its name and one value ("--ar 16:9", "--seed 1207", "--v 6.1").
_SETTING = re.compile(r"(?i)(?:^|(?<=\s))--[a-z][\w-]*(?:\s+(?!--)[\w.:/-]+)?(?=\s|$)")
#: A weighted phrase: "(heavy rain:1.3)", "[night:0.8]" (words, then a weight of one digit and its
#: decimals: not a clock, "[18:12]", "(Thu, 14:32)").
_WEIGHTED = re.compile(r"[(\[]\s*([^():\[\]\n]*[A-Za-z][^():\[\]\n]*?)\s*:\s*\d(?:\.\d{1,2})?\s*[)\]]")
#: Emphasis by brackets around a phrase: "((near miss))", "(((rain)))".
_EMPHASIS = re.compile(r"\({2,}\s*([^()\n]+?)\s*\){2,}")
#: A multi-prompt's weight: "wrong-way driver::2", "rain::-0.5" (a comma then ends the phrase).
_MULTI = re.compile(r"::\s*-?\d+(?:\.\d+)?")


def without_prompt_syntax(text: str) -> tuple[str, list[str]]:
    """(``text`` with negative prompts and settings cut out and weights taken off their phrases, the
    words cut out)."""
    aside: list[str] = []

    def cut(m: re.Match) -> str:
        aside.extend(re.findall(r"[a-z][a-z'-]*", m.group(0).lower()))
        return " "

    text = _NEGATIVE.sub(cut, text)
    text = _NO.sub(cut, text)
    text = _SETTING.sub(cut, text)
    text = _WEIGHTED.sub(r"\1", text)
    text = _EMPHASIS.sub(r"\1", text)
    text = _MULTI.sub(",", text)
    return text, aside
