"""Where the ego goes at a junction or a roundabout (its route: ``left`` or ``right``), read from the
clauses whose subject is the ego, never from another road user's turn.

A turn is a construction: a verb of turning or of taking a way, then a direction ("turn left", "turns
at right", "turning to the right", "bear left", "make a left", "hang a right", "take the next left",
"making a right turn"). Whose turn it is, is who the clause's subject is:

* a subject before the verb that names the ego ("I", "we", "the ego", "VUT", "the host vehicle");
* a subject that is the complement of a copula whose subject is the ego ("the host vehicle is a truck
  turning right": the truck is the ego);
* no subject of its own (a participle or a verb after "and"): the subject of the clause before it in
  its sentence ("I was going round, turning left at the first exit"), or, at the start of a sentence of
  a narrator's story, the narrator ("Turning right at the lights, ...");
* an instruction (a bare verb with no subject, or after "please", opening its sentence or after a
  place it is done at): the reader told what to do, the ego ("At the lights, please turn left",
  "Bear right at the fork");
* a turn said as a noun opening a sentence of a narrator's story ("Left turn here at the light, ...").

Any other subject ("a guy on a scooter made a left across my lane") makes the turn someone else's.
The closed classes below are grammatical (auxiliaries, determiners, clause breaks) or the handful of
English verbs that take a direction as a turn.
"""

from __future__ import annotations

from vei_scenario.language.clauses import sentence_start, split
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.lexicon import EGO_NOUNS

#: Verbs that take a direction as a turn ("turn left", "bear right", "swing left", "went left").
_TURNING = frozenset(("turn", "bear", "swing", "go", "head"))
#: Words after "right" that make it an intensifier, not a direction ("swung right across my bonnet").
_INTENSIFIED = frozenset(("in", "across", "through", "out", "up", "behind", "next", "there", "now", "away", "over",
                          "past", "beside", "alongside", "under", "round", "around", "at", "by", "into",
                          "onto"))  # fmt: skip
#: Verbs that take "a left" or "the next right" as a turn ("make a left", "hang a right", "take a left").
_TAKING = frozenset(("make", "take", "hang", "do", "pull", "swing", "chuck", "throw"))
#: Verbs of carrying out a manoeuvre, whose object may be the turn ("performs an unprotected left").
_PERFORMING = frozenset(("execute", "perform", "complete", "attempt", "begin", "start", "initiate", "finish",
                         "commence", "undertake"))  # fmt: skip
#: Verbs of leaving a junction, whose direction is the turn ("leaves the roundabout to the right").
_LEAVING = frozenset(("leave", "exit", "quit"))
#: Verbs that leave a junction with "off" ("came off the roundabout to the left").
_COMING = frozenset(("come", "get", "go", "turn", "pull", "drive", "ride"))
#: What is left towards a side: the junction itself ("exits the traffic circle left").
_JUNCTIONS = frozenset(("roundabout", "junction", "circle", "gyratory", "ring", "crossroads", "intersection",
                        "mini-roundabout", "rotary"))  # fmt: skip
#: The ways off a junction that are taken towards a side ("the second exit on the left").
_WAYS_OFF = frozenset(("exit", "turning", "turn", "turn-off", "turnoff", "road", "street"))
#: Places after "right at" that make "right" a direction, not an intensifier ("go right at the lights").
_TURN_PLACES = frozenset(("junction", "roundabout", "lights", "light", "crossroads", "crossroad", "intersection",
                          "exit", "corner", "t-junction", "signals", "fork", "end", "top", "bottom", "next",
                          "first", "second", "third", "mini-roundabout", "gyratory", "church", "lights"))  # fmt: skip
_DIRECTIONS = frozenset(("left", "right"))
_INITIALS = {"l": "left", "r": "right"}
#: What may follow "a left turn" when it is the turn itself (a preposition), not a modifier of a noun.
_AFTER_TURN_NOUN = frozenset(("at", "into", "onto", "across", "from", "in", "on", "towards", "toward", "to", "off",
                              "out", "through", "and", "with", "when", "while"))  # fmt: skip
#: Words between a verb of turning and its direction ("turns at right", "turn to the left", "off left").
_BEFORE_DIRECTION = frozenset(("at", "to", "the", "off", "hard", "sharp", "sharply", "slightly", "then", "on"))
#: Words between "take"/"make" and "left" ("take the next left", "make a quick right", "the first left"),
#: with every ordinal of an exit (in figures tokenised as its number and suffix: "the 4th exit", "4 th").
_BEFORE_TURN_NOUN = frozenset(
    ("a", "an", "the", "next", "quick", "sharp", "hard", "late", "its", "my", "our", "last", "final")
) | frozenset(
    ("first", "second", "third", "fourth", "fifth", "sixth", "1", "2", "3", "4", "5", "6", "st", "nd", "rd", "th")
)
#: What ends a clause: punctuation and the conjunctions that open one.
_BREAK_PUNCT = frozenset(".;!?:,—-()")
_BREAK_WORDS = frozenset(
    ("and", "but", "then", "so", "as", "when", "while", "whilst", "until", "because", "where", "before", "after",
     "once")
)  # fmt: skip
#: Auxiliaries, modals and adverbs between a subject and its verb ("I was just turning").
_BETWEEN = frozenset(
    ("is", "was", "were", "are", "am", "be", "been", "being", "has", "have", "had", "will", "would", "can", "could",
     "should", "must", "to", "just", "then", "also", "still", "already", "about", "going", "slowly", "did", "does",
     "do", "needs", "need", "wants", "want", "starts", "started", "begins", "began", "shall", "'s", "'m", "'re")
)  # fmt: skip
_COPULA = frozenset(("is", "was", "are", "were", "'s"))
#: The ego's names as the reader normalises them.
_EGO_HEADS = frozenset(("i", "we", "ego", "vut", "sut", "sv", "av", "im"))
_EGO_PHRASES = (
    ("host", "vehicle"), ("subject", "vehicle"), ("test", "vehicle"), ("our", "car"), ("my", "car"),
    ("our", "vehicle"), ("my", "vehicle"), ("under", "test"), ("ego", "vehicle"), ("ego", "car"),
)  # fmt: skip
#: Every name the reader knows the ego by, as word tuples ("vehicle under test", "robotaxi"), but the
#: object pronouns, which name the ego only as a subject of their own (see :func:`_names_ego`).
_EGO_NAMES = frozenset(tuple(n.split()) for n in EGO_NOUNS if n not in ("me", "us"))
_FIRST_PERSON = frozenset(("i", "we", "me", "my", "us", "our"))
_PREPOSITIONS = frozenset(("of", "behind", "to", "with", "for", "at", "from", "past", "by", "than", "before", "after",
                           "towards", "toward", "ahead", "beside", "near", "like", "into", "in", "on"))  # fmt: skip
_DETERMINERS = frozenset(("the", "a", "an", "this", "that", "my", "our", "his", "her", "its", "their", "your"))


def _lemma_in(word: str, verbs: frozenset[str]) -> bool:
    forms = {word}
    for found in lemmas(word).values():
        forms.update(found)
    return bool(forms & verbs)


def _turn_noun_at(words: list[str], i: int) -> int | None:
    """Where the verb stands whose object is "a left turn" / "the right turn" at ``i`` (the direction):
    "the ego performs a left turn at the junction", "we completed the right turn"; not "a left-turn lane"
    or "the left turn signal"."""
    if words[i] not in _DIRECTIONS or words[i + 1 : i + 2] != ["turn"] or i < 2 or words[i - 1] not in ("a", "the"):
        return None
    after = words[i + 2 : i + 3]
    if after and after[0] not in _AFTER_TURN_NOUN:
        return None
    return i - 2 if _is_verb(words[i - 2]) or "VERB" in lemmas(words[i - 2]) else None


def _turn_at(words: list[str], i: int) -> str | None:
    """The direction of a turn whose verb stands at ``i``, or None."""
    w = words[i]
    after = words[i + 1 : i + 5]
    if _lemma_in(w, _TURNING):
        if after and after[0] in _INITIALS:
            return _INITIALS[after[0]]  # ("turning R": a terse report's initial)
        for k, x in enumerate(after):
            if x in _DIRECTIONS:
                nxt = after[k + 1] if k + 1 < len(after) else ""
                if x == "right" and nxt in _INTENSIFIED and not _lemma_in(w, frozenset(("turn",))):
                    if not (nxt == "at" and _place_after(after[k + 2 :])):
                        return None  # ("went right at me"; not "go right at the lights")
                return x  # ("turn left", "turns at right", "turning to the right")
            if x not in _BEFORE_DIRECTION:
                break
    off = 1 if after[:1] == ["off"] and _lemma_in(w, _COMING) else 0  # ("came off the roundabout left")
    if (off or _lemma_in(w, _LEAVING)) and after[off : off + 1] in (["the"], ["a"]):
        place = next((k for k in (off + 1, off + 2) if k < len(after) and after[k] in _JUNCTIONS), None)
        if place is not None:
            return _towards_side(words[i + 2 + place : i + 6 + place])  # ("leaves the roundabout to the right")
    if _lemma_in(w, _TAKING | _LEAVING):
        by = 1 if after[:1] and after[0] in _BY_WAY and _lemma_in(w, _LEAVING) else 0  # ("leaves by the 2nd exit")
        way = next((k for k, x in enumerate(after) if k >= by and x not in _BEFORE_TURN_NOUN), None)
        if way is not None and after[way] in _WAYS_OFF and (way > 0 or _lemma_in(w, _TAKING)):
            return side_of_way(words[i + 2 + way : i + 7 + way])  # ("took the second exit on the left")
    if _lemma_in(w, _TAKING | _PERFORMING):
        for k, x in enumerate(after):
            if x in _DIRECTIONS:
                nxt = after[k + 1] if k + 1 < len(after) else ""
                if (k > 0 or nxt == "turn") and nxt not in ("lane", "side", "hand", "of", "kerb", "arm", "pavement"):
                    return x  # ("make a left", "take the next right", "making a right turn")
                if k == 0 and _lemma_in(w, frozenset(("make",))) and (nxt in _AFTER_BARE_TURN or not nxt):
                    return x  # ("was making left on green", "made right onto Main": the article left out)
                break
            if x not in _BEFORE_TURN_NOUN and not (k > 0 and _adjective(x)):
                break
    return None


#: What follows a bare "make left" when it is a turn: where or when it is made ("on green", "onto Main").
_AFTER_BARE_TURN = frozenset(("on", "at", "onto", "into", "across", "from", "in", "off", "out", "through"))


def _adjective(word: str) -> bool:
    """Whether ``word`` may be an adjective ("unprotected", "slow", "wide"), as may stand before "left"
    in "an unprotected left": then "left" is the turn, the noun of the phrase."""
    return word not in _DIRECTIONS and "ADJ" in lemmas(word)


def _place_after(words: list[str]) -> bool:
    """Whether ``words`` (after "right at") name a place of the road ("the lights", "the next
    junction") or a number (a speed, a time), not a road user or a person ("me", "the car")."""
    head = words[1:] if words[:1] and words[0] in ("the", "a", "an", "about", "around", "roughly") else words
    if head[:1] and head[0].replace(".", "", 1).isdigit():
        return True  # ("go right at 15 mph", "went right at about 30": a speed or a time, no one aimed at)
    return bool(head) and head[0] in _TURN_PLACES


#: Words between a verb of leaving and the way it leaves by ("exits at the first exit", "via exit 2").
_BY_WAY = frozenset(("at", "by", "via", "through", "on"))


def side_of_way(words: list[str]) -> str | None:
    """The side ``words`` (after a way off: "exit", "turning") say it leads to: with the way's number
    left out ("exit 2 (right)": a spec's number, then its side in brackets, which the reader drops),
    a side or its initial right after it ("1st exit (L)"), or as :func:`_towards_side` reads it."""
    if words[:1] and words[0].isdigit():
        words = words[1:]
    if words[:1] and words[0] in _INITIALS:
        return _INITIALS[words[0]]
    return _towards_side(words)


def _way_said_alone(words: list[str]) -> str | None:
    """The side of a way off that opens a clause with no verb ("1st exit (left)", "exit 3 (R)", "the
    second exit on the right"): a spec's or a note's route after the name of whose it is."""
    k = 0
    while k < len(words) and words[k] in _BEFORE_TURN_NOUN:
        k += 1
    if k >= len(words) or words[k] not in ("exit", "turning", "turn-off", "turnoff"):
        return None
    if any(w in _COPULA or _is_verb(w) for w in words[k + 1 :]):
        return None  # (a clause about the way: "the exit on the right was shut")
    return side_of_way(words[k + 1 : k + 6])


def _ego_name_length(words: list[str]) -> int:
    """How many words of ``words`` open them with a name of the ego ("the ego", "host vehicle",
    "SUT"), or 0."""
    head = 1 if words[:1] and words[0] in ("the", "our", "my") else 0
    if words[head : head + 1] and words[head] in _EGO_HEADS:
        return head + 1
    found = [len(p) for p in (*_EGO_PHRASES, *_EGO_NAMES) if tuple(words[head : head + len(p)]) == p]
    return head + max(found) if found else 0


def _ego_label(words: list[str]) -> bool:
    """Whether the clause ``words`` is the ego's name alone, a spec's label ("Ego:", "SUT -"): what
    the sentence after it says with no subject of its own is the ego's."""
    return bool(words) and _ego_name_length(words) == len(words)


def _way_after_ego(words: list[str]) -> str | None:
    """The side of a way off said right after the ego's name with no verb ("Ego - 2nd exit (right)",
    "SUT 1st exit left"), else None."""
    k = _ego_name_length(words)
    return _way_said_alone(words[k:]) if k else None


def _towards_side(words: list[str]) -> str | None:
    """The side ``words`` say a way off leads to: right after it ("exits left"), or after "to the", "on
    the", "towards the" ("leaves the roundabout to the right", "the exit on the left"); else None."""
    k = 0
    while k < len(words) and words[k] in ("to", "on", "towards", "toward", "the", "its", "our", "my", "your"):
        k += 1
    if k < len(words) and words[k] in _DIRECTIONS and (k == 0 or words[k - 1] in ("the", "its", "our", "my", "your")):
        nxt = words[k + 1] if k + 1 < len(words) else ""
        return words[k] if nxt not in ("lane", "side", "hand", "kerb", "pavement", "of") else None
    return None


def _subject_before(words: list[str], i: int) -> list[str]:
    """The words of the subject before the verb at ``i`` (past auxiliaries and adverbs). A verb in the
    infinitive ("... to turn left") shares the subject of the clause it completes ("I'm sat waiting to
    turn right", "I pulled up to the junction to turn left"), unless "for" names its own ("for the van
    to turn")."""
    j = i - 1
    while j >= 0 and (words[j] in _BETWEEN or words[j].endswith("ly")):
        j -= 1
    if i > 0 and words[i - 1] == "to":
        before = words[: i - 1]
        if "for" in before[-4:]:
            return before[before.index("for", max(0, len(before) - 4)) + 1 :]
        for k, w in enumerate(before):
            if w in _EGO_HEADS and k == 0:
                return [w]
            if w not in _BETWEEN and _is_verb(w):
                return _subject_before(before, k)  # (none before a participle: "pulling out to go right")
    return words[: j + 1]


def _is_verb(w: str) -> bool:
    found = lemmas(w)
    return "VERB" in found and "NOUN" not in found


def _names_ego(phrase: list[str]) -> bool:
    """Whether the noun phrase ending ``phrase`` is the ego: it ends with one of the ego's names (a
    pronoun "I"/"we" right before the verb is always its subject; "ego" not after a preposition, as in
    "the car behind the ego"), or it opens with one and goes on with no preposition ("the ego Skoda
    Octavia": the ego and its make)."""
    if not phrase:
        return False
    if phrase[-1] in ("i", "we") or phrase == ["me"]:
        return True  # ("me turning R": a terse note's subject, with nothing before it)
    if phrase[-1] in _EGO_HEADS:  # (after a report's label and number: "Disengagement #4471 - AV executing")
        if len(phrase) > 2 and phrase[-2] == "the" and phrase[-3] in _PREPOSITIONS:
            return False  # ("the van ahead of the ego": the ego inside another's noun phrase)
        return len(phrase) == 1 or phrase[-2] in ("the", "our", "my", "and") or phrase[-2].isdigit()
    if any(tuple(phrase[-len(p) :]) == p for p in _EGO_PHRASES):
        return True
    if any(tuple(phrase[-len(p) :]) == p and not _PREPOSITIONS & set(phrase[: -len(p)]) for p in _EGO_NAMES):
        return True  # ("the robotaxi", "the vehicle under test"; not "the van behind the test vehicle")
    return _opens_with_ego(phrase) and not _PREPOSITIONS & set(phrase)


def _opens_with_ego(words: list[str]) -> bool:
    """Whether ``words`` open with a name of the ego ("the ego 30 mph", "host vehicle is ...")."""
    head = words[1:] if words and words[0] in ("the", "our", "my") else words
    return bool(head) and (
        head[0] in _EGO_HEADS or any(tuple(head[: len(p)]) == p for p in (*_EGO_PHRASES, *_EGO_NAMES))
    )


def _whose(subject: list[str]) -> str | None:
    """``ego``, ``other`` or None (no subject) for the words before a verb."""
    if not subject:
        return None
    if _names_ego(subject):
        return "ego"
    # the complement of a copula: "the host vehicle is a 40 t truck (turning right)"
    for k in range(len(subject) - 1, 0, -1):
        if subject[k] in _COPULA:
            return "ego" if _names_ego(subject[:k]) else "other"
    return "other"


def _own_subject(words: list[str]) -> str | None:
    """The clause's own subject, told apart as the ego or someone else: the words before its first verb."""
    if words and words[0] in _EGO_HEADS:
        return "ego"
    for k, w in enumerate(words):
        if w in _COPULA and k > 0 and _opens_with_ego(words[k + 1 :]):
            return "ego"  # ("caller is the ego": whoever the subject is, it is the ego)
        if k > 0 and w not in _BETWEEN and "VERB" in lemmas(w) and words[k - 1] not in _DETERMINERS:
            return _whose(_subject_before(words, k))
    return "ego" if _opens_with_ego(words) else None  # (a noun phrase alone: "Ego 30 mph, T-junction, ...")


#: The words of a lane kept for a turn, after its side ("the right turn lane", "the left filter").
_TURN_LANE_WORDS = frozenset(("turn", "turning", "filter", "turn-only", "turning-only"))
#: Verbs (lemmas) of signalling a turn ("indicated left", "signalling right").
_SIGNALLING = frozenset(("indicate", "signal", "blink"))
#: A vehicle's signal, after a possessive and a side ("my left indicator", "our right blinker").
_SIGNALS = frozenset(("indicator", "indicators", "blinker", "blinkers", "signal", "indicator-light"))
#: What a signal is for when it is not a turn: a lane change, an overtake, pulling over or in.
_NOT_A_TURN = frozenset(("overtake", "pass", "lane", "lanes", "merge", "undertake", "lay-by", "layby"))
#: Verbs (lemmas) that with "in", "over" or "up" pull to the side ("pulled in", "pull over", "move over").
_PULLING = frozenset(("pull", "move", "tuck", "draw"))


def _turn_lane_at(words: list[str], i: int) -> str | None:
    """The side of a lane kept for a turn that the preposition at ``i`` places someone in ("in the
    right-turn lane", "on the left filter", "into the right turning lane", "in the left-turn-only
    lane"), else None; "in the right lane" is a lane by its side, no turn."""
    if words[i] not in ("in", "on", "into"):
        return None
    k = i + 1
    while k < len(words) and words[k] in ("the", "a", "my", "our", "its"):
        k += 1
    head = words[k] if k < len(words) else ""
    side = next((d for d in _DIRECTIONS if head.startswith(d + "-turn")), None)
    if side is not None:
        return side  # ("the right-turn lane", "the left-turn-only lane")
    nxt = words[k + 1] if k + 1 < len(words) else ""
    return head if head in _DIRECTIONS and nxt in _TURN_LANE_WORDS else None


def _signal_at(words: list[str], i: int) -> str | None:
    """The side the verb of signalling at ``i`` signals ("indicated left", "signalling to the right"),
    or the side of the possessed signal at ``i`` ("my left indicator"), else None."""
    if _lemma_in(words[i], _SIGNALLING):
        k = i + 1
        while k < len(words) and words[k] in ("to", "the"):
            k += 1
        return words[k] if k < len(words) and words[k] in _DIRECTIONS else None
    if words[i] in _DIRECTIONS and words[i + 1 : i + 2] and words[i + 1] in _SIGNALS and i > 0:
        return words[i] if words[i - 1] in ("my", "our") else None
    return None


def _signals_a_turn(rest: list[str]) -> bool:
    """Whether a signal whose sentence goes on with ``rest`` is for a turn, not for a lane change, an
    overtake or pulling over ("indicated right to overtake", "signalled left and pulled over")."""
    if any(w in _NOT_A_TURN or _lemma_in(w, frozenset(("overtake", "pass", "merge"))) for w in rest):
        return False
    return not any(
        _lemma_in(w, _PULLING) and rest[k + 1 : k + 2] in (["in"], ["over"], ["up"]) for k, w in enumerate(rest)
    )


def _held_at(words: list[str], i: int) -> tuple[str, int] | None:
    """A route said by where the ego waits or what it signals, at ``i``: (the side, where the verb
    whose subject is its owner stands), else None ("I was in the right-turn lane", "we sat in the
    left filter lane", "I indicated left")."""
    side = _turn_lane_at(words, i)
    if side is not None:
        verb = i - 1 if i > 0 and words[i - 1] not in _BETWEEN and "VERB" in lemmas(words[i - 1]) else i
        return side, verb
    side = _signal_at(words, i)
    return (side, i) if side is not None else None


#: Words that may stand before an instruction's verb and are no subject ("please turn left").
_BEFORE_INSTRUCTION = frozenset(("please", "pls", "plz", "kindly", "now", "then", "simply", "just", "next"))


def _instruction(words: list[str], verb: int, opens: bool) -> bool:
    """Whether the verb at ``verb`` is an instruction to the reader, the ego: in its bare form, with
    nothing before it but "please", "now" and the like, and either after "please" or opening its
    sentence (``opens``: nothing before it in the sentence but a place it is done at). Not a
    participle ("Turning left, the lorry ..."), a past ("turned left") or one after a subject."""
    before = words[:verb]
    if before and before[0] in _PREPOSITIONS and before[-1] in _TURN_PLACES | _JUNCTIONS:
        before = []  # ("at the roundabout take the third exit on the right": where it is done, no subject)
    if any(w not in _BEFORE_INSTRUCTION for w in before):
        return False
    word = words[verb]
    if word.endswith(("ing", "ed", "s")) or word not in lemmas(word).get("VERB", ()):
        return False
    return opens or bool({"please", "pls", "plz", "kindly"} & set(before))


def _turn_said_as_noun(words: list[str]) -> str | None:
    """The side of a turn said as a noun that opens a clause ("left turn here at the light", "right
    turn onto Main"): the side, then "turn", then a place, "here" or nothing; not "left turn lane"."""
    if len(words) < 2 or words[0] not in _DIRECTIONS or words[1] != "turn":
        return None
    after = words[2:3]
    return words[0] if not after or after[0] in _AFTER_TURN_NOUN or after[0] in ("here", "now") else None


def _opens_after_place(clauses: list[tuple[list[str], bool]], n: int) -> bool:
    """Whether clause ``n`` opens its sentence or only places before it in the sentence say where it
    is done ("At the second set of lights, turn left")."""
    k = n
    while k > 0 and not clauses[k][1]:
        k -= 1
        if clauses[k][0][0] not in _PREPOSITIONS:
            return False
    return True


def instruction_at(tokens: list[str], i: int) -> bool:
    """Whether the verb at token ``i`` is a turn said as an instruction to the reader (see
    :func:`_instruction`): "At the lights, please turn left when your light is green" is the ego's turn,
    whoever is named after it. Looks back only to the start of its sentence."""
    if i >= len(tokens) or _turn_at(tokens, i) is None:
        return False
    start = sentence_start(tokens, i)
    clauses = split(tokens[start : i + 1], _BREAK_PUNCT | _BREAK_WORDS)
    if not clauses:
        return False
    words, _ = clauses[-1]
    return _instruction(words, len(words) - 1, _opens_after_place(clauses, len(clauses) - 1))


def ego_route(tokens: list[str]) -> str | None:
    """``left`` or ``right`` when a clause whose subject is the ego turns, else None; from the reader's
    normalised, lowercased tokens."""
    story = bool(_FIRST_PERSON & set(tokens))
    previous: str | None = None
    clauses = split(tokens, _BREAK_PUNCT | _BREAK_WORDS)
    label = False
    for n, (words, first) in enumerate(clauses):
        if first:
            previous = "ego" if label else None  # ("Ego: takes 1st exit (left)": said of the label)
        label = _ego_label(words)
        if (previous == "ego" and (side := _way_said_alone(words))) or (side := _way_after_ego(words)):
            return side  # ("Ego: exit 3 (R)", "Ego - 2nd exit (right), 25 km/h")
        for i in range(len(words)):
            direction, verb = _turn_at(words, i), i
            if direction is None:
                verb = _turn_noun_at(words, i)
                direction = words[i] if verb is not None else None
            if direction is None and (held := _held_at(words, i)) is not None:
                direction, verb = held
                if _signal_at(words, i) and not _signals_a_turn(_rest_of_sentence(clauses, n, words, i)):
                    continue
                if words[i - 1 : i] in (["my"], ["our"]):
                    return direction  # ("with my right blinker on")
            if direction is None or verb is None:
                continue
            who = _whose(_subject_before(words, verb))
            if _instruction(words, verb, _opens_after_place(clauses, n)):
                return direction  # ("please turn left when your light is green", "bear right at the fork")
            if who is None and previous is not None:
                who = previous
            elif who is None and first:
                # a sentence opening with the turn: the narrator's in a story, else the subject of the
                # main clause after it ("While turning right, the ego meets a cyclist")
                following = clauses[n + 1] if n + 1 < len(clauses) and not clauses[n + 1][1] else None
                who = "ego" if story else _own_subject(following[0]) if following else None
            if who == "ego":
                return direction
        if first and story and (side := _turn_said_as_noun(words)) is not None:
            return side  # ("Left turn here at the light, it's a green arrow")
        own = _own_subject(words)
        previous = own or previous
    return None


def turn_taken_at(tokens: list[str], i: int) -> bool:
    """Whether "left" or "right" at token ``i`` is a turn said as the object of a light verb ("hung a
    right", "made a left", "took the right"): the turn itself, so a place phrase after it ("... a right
    in front of me") is where the turn is made, and "right" does not stress that phrase."""
    if tokens[i] not in ("left", "right") or i < 2 or tokens[i - 1] not in ("a", "the"):
        return False
    return bool(set(lemmas(tokens[i - 2]).get("VERB", ())) & _TAKING)


def _rest_of_sentence(clauses: list[tuple[list[str], bool]], n: int, words: list[str], i: int) -> list[str]:
    """The words after ``words[i]`` (in clause ``n``) that go on with the same subject: the rest of
    its clause and the clauses after it in its sentence up to one with a subject of its own ("I
    indicated left and pulled over"; not "... and a van overtook me")."""
    rest = list(words[i + 1 :])
    for following, first in clauses[n + 1 :]:
        if first or (_own_subject(following) not in (None, "ego") and not _is_verb(following[0])):
            break  # (a clause opening on its verb goes on with the same subject)
        rest += following
    return rest
