"""The syntax of prompts for text-to-image and text-to-video generators, read as what it means.

People who want a clip of a traffic situation rendered write it as a generator's prompt, and the
same description then reaches vei. Three parts of that syntax are no scene words as written:

- a **negative prompt** ("Negative prompt: crash, daylight, cartoon", ``"negative_prompt": "..."``,
  Midjourney's ``--no crash``) lists what the clip must *not* show: read as the scene, "crash" would
  make a collision of a calm clip;
- **generation settings** after a double dash at a line's end (``--ar 16:9``, ``--seed 1207``,
  ``--motion 6``) and resolution tags ("4k", "8K") are the tool's, not the scene's;
- **prompt weights** (``(heavy rain:1.3)``, ``((near miss))``, ``wrong-way driver::2``) say how much a
  phrase counts; the phrase is the scene's, the weight is not.

Each is found by its syntax (the label and its colon, the double dash, the number after a colon in
brackets), never by the words inside it. The words set aside are reported as not used.
"""

from __future__ import annotations

import re

#: A negative prompt's label and what it lists: up to the line's end, or in a JSON-like field, up to the
#: field's closing quote. The label opens a line ("Negative prompt:", "neg:", "[Negative] ..."), is a
#: quoted key of a field ("negative_prompt": "..."), or follows a sentence's or a list's mark with its
#: colon ("... brakes hard. Negative prompt: collision."), a bare "negative:" with a list ("... rear-ends
#: it. Negative: sunset, snow", ", negative: collision, daytime"; not "Breath test, negative: the driver").
_NEGATIVE = re.compile(
    r"""(?imx)
    (?:^[\s*>#-]*|(?<=[{,])\s*(?=["'])|(?<=[.!?;|,]\s)(?=\[?neg(?:ative)?(?:[\s_-]*prompts?\]?\s*:|\]?\s*:[^\n,.]*,)))
    (?:["']?\bneg(?:ative)?(?:[\s_-]*prompts?)?["']?\s*[:=]|\[neg(?:ative)?(?:[\s_-]*prompts?)?\]:?)\s*
    (?:"(?P<quoted>[^"\n]*)"|(?P<line>[^\n]*))
    """
)
#: A generator's settings: the tail of a line made of double-dashed names and their values ("--ar 16:9
#: --seed 1207", Midjourney's "--no crash, gore"). Only a tail: a double dash inside prose ("the van --no
#: lights, no indicator-- pulled out", "going 30 --maybe 35-- when") closes again, and is a dash.
_SETTINGS = re.compile(r"(?im)(?<=\s)--[a-z][\w-]*\b(?:(?!--)[^\n])*(?:\s--[a-z][\w-]*\b(?:(?!--)[^\n])*)*$")
#: A resolution or quality tag of a clip ("4k photoreal", "8K, HDR"), which a reader of speeds would take
#: for "4 k" (km/h): a number and "k" after no word of going, before a tag or a list's mark.
_RESOLUTION = re.compile(
    r"(?i)(?<!\bat )(?<!\bdoing )(?<!\babout )(?<!\bgoing )(?<!\bspeed )(?<!\bto )\b(?:2|4|5|6|8|12|16)k\b"
    r"(?=\s*(?:[,.;)|]|$|(?:uhd|hdr|photo\w*|video|footage|resolution|render\w*|quality|cinematic|realistic|"
    r"dashcam|ultra|hyper\w*|\d+\s*fps|\d+p)\b))"
)
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
    text = _SETTINGS.sub(cut, text)
    text = _RESOLUTION.sub(cut, text)
    text = _WEIGHTED.sub(r"\1", text)
    text = _EMPHASIS.sub(r"\1", text)
    text = _MULTI.sub(",", text)
    return text, aside
