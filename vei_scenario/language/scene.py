"""Which parts of a text describe the scene at all.

Real descriptions wrap the scene in material that is not the scene: the answer options of a quiz
question, questions put to the reader ("Was it my fault?", "Thoughts?"), questions reported of
someone ("She asked whether hire scooters could be geofenced"), what did not happen ("If he'd been
sat on the lorry's bumper, ..."), thread numbering ("1/") and hashtags. Read as the scene, these give
road users, behaviours, speeds and settings nobody saw. Each is recognised by its structure (a question
mark, a run of lettered options after it, a verb of asking before "whether", a past perfect after
"if"), never by its wording, and is set aside whole: its words are reported as not used. So is what
a generator's prompt says the clip must not show (:mod:`generation_prompt`).

What is kept is what may be the scene: a question or an option list that names a road user and is
not answering a question ("Can you make a scenario where a cyclist cuts in?", "Scenario: A) ego at
50 km/h, B) a van cuts in") stays, and a text that would keep no road user is kept as it was.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language.generation_prompt import without_prompt_syntax
from vei_scenario.language.settings import TURN_LABEL

#: Between sentences: whitespace after an end mark, or a line break.
_BREAK = re.compile(r"((?<=[.!?])\s+|\s*\n\s*)")
#: The marker of an answer option: "A)", "(a)", "A.", "1.", "1)" at the start of a line or after
#: whitespace, followed by a space.
_OPTION = r"(?:^|(?<=\s))\(?{}[.)]\s"
_FIRST = re.compile(_OPTION.format("[Aa1]"))
_SECOND = re.compile(_OPTION.format("[Bb2]"))
#: Thread numbering at the start of a line ("1/", "2/"), a hashtag, pictographs.
_THREAD = re.compile(r"(?m)^\s*\d{1,2}/(?=\s)")
_HASHTAG = re.compile(r"#[A-Za-z]\w*")
_PICTOGRAPH = re.compile("[\u2600-\u27bf\U0001f000-\U0001faff\ufe0f\u200d]")
#: The emoji of a feeling or a gesture (faces, hands): a writer's comment on what they follow, as "lol" is.
_FEELING = "[\U0001f600-\U0001f64f\U0001f910-\U0001f92f\U0001f970-\U0001f97f\U0001f44a-\U0001f450\u2639\u263a]"
#: A run of pictographs with a feeling's between two words of a message: the comment ends the clause
#: before it, as a comma does. A pictograph of a thing alone ("a lady with a stroller \U0001f6bc crossed")
#: stands for the word it follows and ends nothing.
_PICTOGRAPH_BETWEEN = re.compile(
    r"(?<=\w)[ \t]*(?:"
    + _PICTOGRAPH.pattern
    + r"[ \t]*)*"
    + _FEELING
    + r"(?:[ \t]*"
    + _PICTOGRAPH.pattern
    + r")*[ \t]*(?=\w)"
)
#: What only the scene has: a number (a speed, a gap, a clock time) or the ego named as such. A question
#: with one asks for the scene ("Can the ego be doing 50 km/h?").
_OF_THE_SCENE = re.compile(r"\d|\bego\b", re.IGNORECASE)
#: A verb of asking or wondering, then the word that opens the question it reports.
_ASKED = re.compile(
    r"\b(ask|asks|asked|asking|wonder|wonders|wondered|query|queried|queries|enquired|inquired)\s+"
    r"(whether|if|what|why|how|who|when|where)\b",
    re.IGNORECASE,
)
#: A condition in the past perfect, not denied ("if he'd been", "if I had left"): what did not happen.
#: ("if I hadn't braked, I would have hit him" says what did happen, and is kept.)
_COUNTERFACTUAL = re.compile(r"^\W*if\b[^,;]*?(?:\w(?:'d|’d)|\bhad)\s+(?!not\b)\w+", re.IGNORECASE)
#: The formulas that frame a record or a letter rather than tell of the road: a meeting's roll and
#: decisions ("Present: ...", "Apologies: ...", "RESOLVED that ...", "Minutes of ...",
#: "The minutes of the last meeting were agreed"), and a letter's salutation and close ("Dear ...,",
#: "Kind regards," and the name after it).
_RECORD = re.compile(
    r"^\W*(?:present|apologies|attendees|in attendance|agenda|cc)\s*:"
    r"|^\W*resolved\b|^\W*(?:the\s+)?minutes\s+of\b|^\W*dear\b[^.!?\n]*,\s*$",
    re.IGNORECASE,
)
_CLOSE = re.compile(
    r"^\W*(?:(?:kind|best|warm)\s+(?:regards|wishes)|regards|yours\s+(?:faithfully|sincerely|truly)|"
    r"many\s+thanks|thanks\s+in\s+advance)\s*,?\s*$",
    re.IGNORECASE,
)
#: A past modal perfect said by someone afterwards ("I should've waited", "you could have stopped").
_SHOULD_HAVE = re.compile(r"\bshould\s*(?:'ve|’ve|\s+have)\b", re.IGNORECASE)


#: A quotation: an opening mark not after a letter, then words (an apostrophe inside a word, "don't",
#: is no mark), then a closing mark not before a letter.
_QUOTE = re.compile(
    r"(?<![\w])['\"\u2018\u201c]((?:[^'\"\u2018\u2019\u201c\u201d]|(?<=\w)['\u2019](?=\w))+?)['\"\u2019\u201d](?![\w])"
)
#: A verb of saying, after the speaker ("she told the Echo", "he said") or before them ("said the driver").
_SAYING = (
    r"(?:said|says|say|told|tells|added|adds|recalled|recalls|explained|explains|admitted|admits|insisted"
    r"|claimed|stated|states|wrote|writes)"
)
#: The speaker named right after a quotation (", she told", "he said", "said Emeka") or right before it
#: ("She said: '...'", "The driver told us: '...'").
_SPEAKER_AFTER = re.compile(
    rf"\s*,?\s*(?:(he|she|they)\s+{_SAYING}\b|(?:[A-Za-z]+\s+){{0,3}}{_SAYING}\b)", re.IGNORECASE
)
_SPEAKER_BEFORE = re.compile(rf"(?:\b(he|she|they)|\b[A-Za-z]+)\s+{_SAYING}(?:\s+\w+)?\s*[:,]?\s*$", re.IGNORECASE)
#: The first person, and what it is in the third person of a speaker said as "he", "she" or "they" (the
#: plural's, whoever speaks).
_FIRST_PERSON = re.compile(r"\b(i|me|my|mine|myself|we|us|our|ours)\b", re.IGNORECASE)
_PLURAL = {"we": "they", "us": "them", "our": "their", "ours": "theirs"}
_THIRD = {
    "he": {"i": "he", "me": "him", "my": "his", "mine": "his", "myself": "himself", **_PLURAL},
    "she": {"i": "she", "me": "her", "my": "her", "mine": "hers", "myself": "herself", **_PLURAL},
    "they": {"i": "they", "me": "them", "my": "their", "mine": "theirs", "myself": "themselves", **_PLURAL},
}


def _speaker(text: str, quote: re.Match) -> str | None:
    """The pronoun of the speaker said right before or after ``quote`` ("they" for a speaker named by a
    noun), or None where no verb of saying frames it (a sign's words, a name in quotes)."""
    after = _SPEAKER_AFTER.match(text, quote.end())
    if after is not None:
        return (after.group(1) or "they").lower()
    before = _SPEAKER_BEFORE.search(text, max(0, quote.start() - 40), quote.start())
    if before is not None:
        return (before.group(1) or "they").lower()
    return None


def quoted_speakers(text: str) -> str:
    """``text`` with the first person of a quotation said in the third person of its speaker ("'I don't
    know how I stopped in time,' she told the Echo": she stopped), where the text around its quotations
    is told in the third person: a news report or a letter quoting someone is not told by that someone,
    so the quoted "I" is the one the report names (the driver of the van), not a narrator of its own."""
    quotes = list(_QUOTE.finditer(text))
    if not quotes or _FIRST_PERSON.search(_QUOTE.sub(" ", text)):
        return text
    out, last = [], 0
    for m in quotes:
        speaker = _speaker(text, m)
        if speaker is None:
            continue
        third = _THIRD[speaker]
        out += [text[last : m.start(1)], _FIRST_PERSON.sub(lambda w, t=third: t[w.group(1).lower()], m.group(1))]
        last = m.end(1)
    out.append(text[last:])
    return "".join(out)


def only_the_scene(text: str, names_road_user: Callable[[str], object]) -> tuple[str, list[str]]:
    """(the parts of ``text`` that may describe the scene, the words of the parts set aside).

    ``names_road_user(phrase)`` is truthy when the phrase names a road user; a question or an option
    list that names none is not the scene, and the scene must keep at least one if the text has one."""
    text, aside = without_prompt_syntax(text)  # ("Negative prompt: crash", "--ar 16:9", "(rain:1.3)")
    text = _PICTOGRAPH_BETWEEN.sub(", ", text)  # (a feeling between words ends a clause: "braked 😱 nobody hit")
    text = _PICTOGRAPH.sub(" ", text)
    text = _THREAD.sub(" ", text)
    for tag in _HASHTAG.findall(text):
        aside.append(tag[1:])
    text = _HASHTAG.sub(" ", text)
    cut = list(aside)  # (set aside whatever the sentences are)
    kept: list[str] = []
    parts = _BREAK.split(text)
    k = 0
    while k < len(parts):
        sentence, sep = parts[k], parts[k + 1] if k + 1 < len(parts) else ""
        rest = "".join(parts[k + 2 :])
        if sentence.rstrip().endswith("?") and _options_follow(rest):
            aside += _words(sentence) + _words(rest)  # (a quiz: the stem before it is the scene)
            break
        if _CLOSE.match(sentence):
            aside += _words(sentence) + _words(rest)  # (a letter's close and the signature after it)
            break
        if _not_the_scene(sentence, names_road_user):
            aside += _words(sentence)
            # (the line it ended still ends, "fine. Outcome?\n", and a question's mark with it, so the next
            # line answers it: "Q: Time of day? / A: Evening.")
            label = _TURN_LABEL.match(sentence)  # (a dialogue's turn keeps its speaker: "INVESTIGATOR: ?")
            ends = ("?\n" if sentence.rstrip().endswith("?") else "\n") if "\n" in sep else " "
            kept.append((label.group(0) if label else "") + ends)
        else:
            kept.append(sentence + sep)
        k += 2
    scene = "".join(kept).strip()
    if not scene or (names_road_user(text) and not names_road_user(scene)):
        return text, cut
    return scene, aside


#: A speaker's label opening a line, after any stamp ("OFFICER: ", "[00:01:10] Ms Lee: ").
_TURN_LABEL = re.compile(rf"^\s*(?:[\[(]?\d{{1,2}}:\d\d(?::\d\d)?[\])]?[ \t]+)?{TURN_LABEL}")


def _options_follow(rest: str) -> bool:
    """Whether ``rest`` opens with a first answer option and has a second one after it."""
    first = _FIRST.match(rest.lstrip())
    return bool(first) and bool(_SECOND.search(rest.lstrip(), first.end()))


def _not_the_scene(sentence: str, names_road_user: Callable[[str], object]) -> bool:
    """A question to the reader, a reported question, a counterfactual, or what someone says should
    have been done: none of them is what happened."""
    said = sentence.strip()
    if said.endswith("?") and not (names_road_user(said) or _OF_THE_SCENE.search(said) or tag_question(said)):
        return True  # ("Is this allowed?", "Was it your fault?", "Thoughts?")
    if _ASKED.search(said):
        return True  # ("She asked whether hire scooters could be geofenced off pavements.")
    if _RECORD.match(said):
        return True  # (a meeting's roll or decisions, a letter's salutation)
    return bool(_COUNTERFACTUAL.match(said) or _SHOULD_HAVE.search(said))


#: Wh-words and the openers of a question to the reader: a tag question's tag never opens with one.
_WH = frozenset(("what", "why", "how", "who", "whom", "whose", "when", "where", "which", "any", "anyone", "anybody",
                 "thoughts"))  # fmt: skip
#: Words that open a question proper: an auxiliary or modal put before its subject, or one of :data:`_WH`.
_ASKING = _WH | frozenset(
    ("is", "was", "were", "are", "am", "do", "does", "did", "can", "could", "would", "will", "should", "shall", "may",
     "might", "must", "have", "has", "had")
)  # fmt: skip
#: Words that open a sentence before its clause ("so", "and", "well", "ok"): the clause follows them.
_OPENERS = frozenset(("so", "and", "but", "well", "ok", "okay", "now", "then", "right"))
#: The auxiliaries and modals that open a yes/no question before its subject ("Was that van ...?",
#: "Did the car ...?"): a wh-question ("Why was the van behind us?") takes what it asks about as given.
YES_NO_OPENERS = _ASKING - _WH
#: Words that open a sentence before its clause, public for :mod:`~vei_scenario.language.not_told`.
OPENERS = _OPENERS
#: The longest tag a statement asked back takes ("correct", "isn't it", "is that right").
TAG_WORDS = 3


def tag_question(said: str) -> bool:
    """Whether ``said``, ending with a question mark, is a statement asked back for confirmation ("It was
    raining that evening, correct?", "You were doing 30, weren't you?"): a clause of three words or more
    that opens with its subject, not an auxiliary or a wh-word, then after its last comma a short tag
    that opens with no wh-word. Why: a cross-examination, an interview or a voice note states the scene
    this way; only a question proper leaves it open."""
    body, comma, tag = said.rstrip("?").rpartition(",")
    words = [w.lower() for w in re.findall(r"[A-Za-z][A-Za-z'-]*", body)]
    while words and words[0] in _OPENERS:
        words = words[1:]
    tag_words = re.findall(r"[A-Za-z][A-Za-z'-]*", tag.lower())
    if not comma or len(words) < 3 or not 0 < len(tag_words) <= TAG_WORDS:
        return False
    return words[0] not in _ASKING and tag_words[0] not in _WH


def _words(part: str) -> list[str]:
    return [w.lower() for w in re.findall(r"[A-Za-z][A-Za-z'-]*", part)]
