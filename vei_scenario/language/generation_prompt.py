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
#: The most words of an item of a negative prompt's list ("deformed bicycle", "distorted text on bus"); a
#: sentence after "Negative:" is a critique ("Negative: when the cyclist pulled out you braked late").
_ITEM_WORDS = 4
#: A generator's settings: the tail of a line made of double-dashed names, each with one value at most
#: ("--ar 16:9 --seed 1207 --style raw"), and Midjourney's "--no" with its list ("--no crash, gore").
#: Only such a tail: a dash in prose ("the van --no lights-- pulled out", "at 30 mph --hit it square on")
#: closes again or goes on in words.
_SETTING_ITEM = r"--(?:no[ \t]+(?:(?!--)[^\n])+?|[a-z][\w-]*(?:[ \t]+(?!--)\S+)?)"
_SETTINGS = re.compile(
    rf"(?im)(?<=\s)(?:{_SETTING_ITEM}(?:[ \t]+{_SETTING_ITEM})+|--[a-z][\w-]*[ \t]+[\w.:/-]*\d[\w.:/-]*)[ \t]*$"
)  # (two settings or more, or one with a figure: "--ar 16:9"; "at 30 mph --hit it" is a dash in prose)
#: A resolution or quality tag of a clip ("4k photoreal", "8K, HDR"), which a reader of speeds would take
#: for "4 k" (km/h): a number and "k" as an item of its own in a list of tags, or before a tag.
_TAG = r"\b(?:2|4|5|6|8|12|16)k\b"
_RESOLUTION = re.compile(
    rf"(?im)(?:^|(?<=[,|])|(?<=[,|]\s)){_TAG}(?=\s*(?:[,.;|]|$))"
    rf"|(?<!\bat )(?<!\bdoing )(?<!\babout )(?<!\bgoing )(?<!\bspeed )(?<!\bto ){_TAG}"
    r"(?=\s+(?:uhd|hdr|photo\w*|video|footage|resolution|render\w*|quality|cinematic|realistic|"
    r"dashcam|ultra|hyper\w*|\d+\s*fps|\d+p)\b)"
)
#: A weighted phrase: "(heavy rain:1.3)", "[night:0.8]" (words, then a weight of one digit and its
#: decimals: not a clock, "[18:12]", "(Thu, 14:32)").
_WEIGHTED = re.compile(r"[(\[]\s*([^():\[\]\n]*[A-Za-z][^():\[\]\n]*?)\s*:\s*\d(?:\.\d{1,2})?\s*[)\]]")
#: Emphasis by brackets around a phrase: "((near miss))", "(((rain)))".
_EMPHASIS = re.compile(r"\({2,}\s*([^()\n]+?)\s*\){2,}")
#: A multi-prompt's weight: "wrong-way driver::2", "rain::-0.5" (a comma then ends the phrase).
_MULTI = re.compile(r"::\s*-?\d+(?:\.\d+)?")


#: A clip's aspect ratio after its name ("aspect ratio 9:16", "-ar 16:9", "ratio: 21:9") or before a word
#: of its shape ("9:16 vertical"): not a clock.
_ASPECT = re.compile(
    r"(?i)(?:\b(?:aspect(?:[ _]ratio)?|ratio|-{1,2}ar)\b[\s:=\"']*\d{1,2}(?:\.\d+)?:\d{1,2}\b"
    r"|\b\d{1,2}(?:\.\d+)?:\d{1,2}(?=\s*(?:vertical|widescreen|portrait|landscape|format|aspect)\b))"
)


#: A "Positive:" label: beside it, "Negative:" lists what went badly (feedback, a review), no prompt's.
_POSITIVE = re.compile(r"(?im)(?:^|[.;]\s)\W*positives?\s*:")


def without_prompt_syntax(text: str) -> tuple[str, list[str]]:
    """(``text`` with negative prompts and settings cut out and weights taken off their phrases, the
    words cut out)."""
    aside: list[str] = []

    def cut(m: re.Match) -> str:
        aside.extend(re.findall(r"[a-z][a-z'-]*", m.group(0).lower()))
        return " "

    pros_and_cons = _POSITIVE.search(text) is not None  # ("Positive: good mirrors. Negative: hit a cyclist")

    def cut_a_list(m: re.Match) -> str:  # (a list of things not to show, not a sentence: "Negative: when ...")
        if pros_and_cons:
            return m.group(0)
        listed = m.group("quoted") if m.group("quoted") is not None else m.group("line")
        items = [x.split() for x in re.split(r"[,;|]", listed.strip().rstrip("."))]
        return cut(m) if all(len(x) <= _ITEM_WORDS for x in items) else m.group(0)

    text = _NEGATIVE.sub(cut_a_list, text)
    text = _SETTINGS.sub(cut, text)
    text = _RESOLUTION.sub(cut, text)
    text = _ASPECT.sub(cut, text)
    text = _WEIGHTED.sub(r"\1", text)
    text = _EMPHASIS.sub(r"\1", text)
    text = _MULTI.sub(",", text)
    return text, aside
