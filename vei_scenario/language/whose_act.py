"""Whose act a verb is, and whether it is an act at all.

A story told by the ego's driver leaves its subject out where it is the narrator ("Had to jump on the
brakes.", "Waited for a gap and passed them wide."): the reader would otherwise give the verb to the
last road user named, and the ego's reaction becomes the road user's extra behaviour (a spurious
hard stop, an overtake of the ego). The grammar says whose it is:

* a sentence whose subject is left out, told in the first person, is the narrator's when its first
  verb (or the modal before it: "had to", "needed to") is in the past tense or the plain form; the
  third person ("Brakes hard.") stays the road user's; a modal said after a clause's verb with
  nothing joining it ("pulled out right in front of me had to brake", "..., had to stamp on the
  brakes") or right after the ego as an object ("shot off the kerb in front of me had to brake")
  opens such a sentence, as said aloud without a full stop;
* in such a sentence, a reaction (braking, stopping, slowing, swerving) is the narrator's, and so is
  a verb whose object is a road user said before as "him", "her", "them" or "it": whoever does it to
  that road user is not that road user ("passed them wide": the narrator passes, the riders go on).

"The rider" said alone names the road user named before that rides (a cyclist, an e-scooter rider):
read as no one, its verb would go to whoever was the subject last (often the ego, "the SV follows").

A behaviour said as a noun after "no" ("no braking", "no crossing intended", "no overtaking") or as
what an intent or a sign is denied of ("no intention of crossing", "without any sign of stopping")
does not happen: nothing is read of it, also with its modifiers between ("no pre-impact braking", "no
harsh braking"). (A verb denied, "does not stop", is read by the reader as what the road user does
instead.)

Two more constructions give a verb a subject that is not the road user named last:

* **a person named by a name** ("Marco braked hard and swerved", "Jack slowed and passed wide"): a
  driving lesson, a debrief or a club report names the ego's driver by name. Such a name stands with
  no article, capitalised, at the start of its clause; unless it was said with a road user ("my
  brother Sam in his Golf"), the person is nobody the scenario places, and the verbs of that clause
  are theirs: the ego's side of the story, not the road user's;
* **a verb of causing with its object** ("forcing him to brake", "causing us to stop", "made me slam
  on the brakes"): the verb after the object is the object's act; where the object is no road user
  named (the ego, "him", "us"), it is not the subject's.

A sentence with its subject left out that opens with a modal of having to ("Had to brake hard.",
"Needed to stop.") is the protagonist's reaction in a story told of someone else too: a road user's
own braking is said with its subject.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from vei_scenario.language.function_words import SAYING
from vei_scenario.language.lemmas import lemmas
from vei_scenario.language.lexicon import MOTOR_TWO_WHEELERS

#: What a narrator does to keep clear: braking, stopping, slowing, moving aside.
_REACTIONS = frozenset(("sudden_stop", "stop", "change_speed", "cut_in", "change_lane", "cut_out", "give_way"))
#: A road user said again as the object of a verb.
_OBJECT_PRONOUNS = frozenset(("him", "her", "them", "it"))
#: Words between a verb of passing and its object ("went round him", "got past her").
_ROUND = frozenset(("round", "around", "past", "by"))
#: Mentions that name someone: a subject, where one stands first.
_NAMING = frozenset(("actor", "pronoun", "member"))
#: Mentions that hold a sentence's first verb.
_VERB_SLOTS = frozenset(("modal", "unknown_verb", "behaviour", "stationary", "ego_verb", "to_stop"))
#: Nouns of a plan or of the sign of one: what "no" denies in "no intention of crossing".
_INTENT = frozenset(("intent", "intention", "intentions", "sign", "signs", "attempt", "indication", "plan", "wish"))
#: Words between "no" and such a noun ("no real intention", "without any sign").
_BEFORE_INTENT = frozenset(("any", "real", "apparent", "obvious", "clear", "visible"))


def _plain_or_past(word: str) -> bool:
    """Whether ``word`` is a verb in the past tense or the plain form ("had", "slowed", "brake"), not
    the third person ("brakes") nor a participle ("braking"): the forms of a verb whose subject,
    left out in a first-person story, is "I"."""
    verbs = lemmas(word).get("VERB", ())
    if not verbs:
        return False
    return not word.endswith("ing") and (word in verbs or not word.endswith("s"))


def narrators_acts(clauses: list, tokens: list[str], first_person: bool) -> dict[int, bool]:
    """The verbs the narrator does in sentences whose subject is left out, by their mention's start,
    each with whether the narrator passes the road user it names as its object (``tokens``: those
    the mentions index). Told of someone else, only a sentence that opens with a modal of having to
    ("Had to brake hard.") is read so, and only its reactions."""
    out: dict[int, bool] = {}
    bare = False  # (in a sentence with no subject so far, whose first verb is the narrator's form)
    lead_seen = False
    for _, mentions in clauses:
        if not (mentions and mentions[0].slot == "link"):  # (a new sentence: no "then" or "while" before)
            bare, lead_seen = True, False
        acted = False  # (a verb said in this clause so far)
        for k, m in enumerate(mentions):
            if m.slot == "modal" and (acted or _after_an_object_pronoun(mentions, k, tokens)) and _run_on(mentions, k):
                bare, lead_seen = True, False  # ("... right in front of me had to brake": a new one)
            if m.slot in _NAMING:
                bare = False
            acted = acted or m.slot in _VERB_SLOTS
            if not bare:
                continue
            if m.slot not in _VERB_SLOTS:
                continue
            if not lead_seen:
                lead_seen = True
                if not _plain_or_past(m.words.split()[0]) or not (first_person or _having_to(m)):
                    bare = False
                    break
            if m.slot != "behaviour":
                continue
            if not first_person and m.value[0] not in _REACTIONS:
                continue
            after = tokens[m.end : m.end + 2]
            objected = bool(after) and (
                after[0] in _OBJECT_PRONOUNS
                or (after[0] in _ROUND and after[1:2] != [] and after[1] in _OBJECT_PRONOUNS)
            )
            to_the_ego = _towards_the_ego(mentions[k + 1 :])
            if objected or (m.value[0] in _REACTIONS and not to_the_ego):
                out[m.start] = objected and m.value[0] == "overtake"
    return out


#: The ego said as a subject: after it a clause of its own begins ("Waited till I could see").
_EGO_SUBJECTS = frozenset(("i", "we"))


def _towards_the_ego(after: list) -> bool:
    """Whether the ego is named in ``after`` (the mentions after a verb) as what the verb goes
    towards ("Cut in right in front of me."), not as the subject of a clause of its own ("Waited
    till I could see it was clear": the narrator waited)."""
    for x in after:
        if x.slot == "actor" and x.value == "ego":
            return x.words not in _EGO_SUBJECTS
        if x.slot in ("conj", "link", "relative") or x.slot in _NAMING:
            return False
    return False


#: Modals of having to: a reaction said with them and no subject is the protagonist's.
_HAVING_TO = frozenset(("had", "needed", "have", "need"))


def _having_to(m) -> bool:
    """Whether mention ``m`` is a modal of having to ("had to", "needed to")."""
    return m.slot == "modal" and m.words.split()[0] in _HAVING_TO


def acts_not_the_subjects(clauses: list, tokens: list[str], first_person: bool, text: str) -> dict[int, bool]:
    """Every verb whose subject is not the road user named last, by its mention's start, each with
    whether its doer passes the road user named last: the narrator's (:func:`narrators_acts`), a
    named person's (:func:`named_persons_acts`) and a caused one's (:func:`caused_acts`)."""
    out = narrators_acts(clauses, tokens, first_person)
    out.update(named_persons_acts(clauses, tokens, text))
    out.update(caused_acts(clauses, tokens))
    out.update(unread_subjects_reactions(clauses, tokens))
    out.update(unread_subjects_passes(clauses, tokens))
    out.update(agentless_reactions(clauses, tokens))
    return out


#: Words after which a clause's subject comes: a sentence's start, a conjunction.
_CLAUSE_OPENERS = frozenset((".", "!", "?", ";", ":", ",", "and", "but", "then", "so", "when", "while", "as"))
#: Words that end the stretch a subject governs: a sentence's end, a clause with a subject of its own.
_CLAUSE_ENDS = frozenset(
    (".", "!", "?", ";", "when", "while", "as", "because", "until", "till", "if", "before", "after")
)
#: Titles said before a surname ("Mr Hughes").
_TITLES = frozenset(("mr", "mrs", "ms", "miss", "dr"))
_NAMING_SLOTS = _NAMING
#: Mentions that are a verb of a clause.
_ACT_SLOTS = frozenset(("behaviour", "unknown_verb", "ego_verb", "to_stop", "stationary"))


#: Marks after which a capital opens a sentence, a list item or a quote, and names nobody.
_OPENING_MARKS = frozenset(".!?:;|\u2022*-\u2013\u2014\"'(\u201c\u2018>#")


def _person_names(text: str) -> frozenset[str]:
    """The words of ``text`` that may be names of people (lower-cased): said capitalised inside a
    sentence somewhere ("a lesson with Jack", "Debrief, Marcus, 3pm"), or said capitalised more than
    once only where sentences start and known to the dictionary as no word at all ("Paul was driving
    ... Paul braked": a news item or a leaflet opens its sentences with its driver's name)."""
    out = set()
    openers: dict[str, int] = {}
    for m in re.finditer(r"\b[A-Z][a-z]+\b", text):
        word = m.group().lower()
        before = text[: m.start()].rstrip()
        opening = not before or before[-1] in _OPENING_MARKS or text[m.start() - 1] == "\n"
        if not opening:
            out.add(word)
        else:
            openers[word] = openers.get(word, 0) + 1
    out.update(w for w, n in openers.items() if n > 1 and len(w) > 2 and not lemmas(w))
    return frozenset(out)


def _riding_names(text: str) -> frozenset[str]:
    """The names ``text`` says with a vehicle of their own (lower-cased): "Sam in his Golf", "Priya on
    her bike", "Sam's van": that person drives or rides a road user."""
    found = re.finditer(r"\b([A-Z][a-z]+)(?:'s\b| (?:in|on) (?:his|her|their) \w)", text)
    return frozenset(m.group(1).lower() for m in found)


def named_persons_acts(clauses: list, tokens: list[str], text: str) -> dict[int, bool]:
    """The verbs of a person named by a name at the start of a clause ("Marco braked hard and
    swerved", "Mr Jones braked"), by their mention's start, each with whether it passes someone; not those of a name
    said with a road user ("my brother Sam in his Golf ... Sam braked"), whose verbs are a road
    user's. ``tokens``: those the mentions index."""
    names, riding = _person_names(text), _riding_names(text)
    flat = [m for _, ms in clauses for m in ms]
    covered = {  # (words read as something: a road user, a place; "Jack" may be read as an unknown verb)
        i for m in flat if m.slot != "unknown_verb" for i in range(m.start, max(m.end, m.start + 1))
    }
    road_users = [m for m in flat if m.slot == "actor" and m.value != "ego"]
    persons: dict[int, bool] = {}
    if not names and not _TITLES & set(tokens):
        return persons
    actors_at = {i for m in flat if m.slot == "actor" for i in range(m.start, m.end)}
    for i, tok in enumerate(tokens):
        titled = i > 0 and tokens[i - 1] in _TITLES and _word(tok) and i not in actors_at
        if not titled and (tok not in names or i in covered or (i and tokens[i - 1] in names)):
            continue  # (a title makes the word after it a name, whatever it reads as alone: "Mr Jones")
        before = tokens[i - 1] if i else "."
        if before in _TITLES:
            before = tokens[i - 2] if i > 1 else "."
        if before not in _CLAUSE_OPENERS:
            continue
        end = i + 1
        while end < len(tokens) and tokens[end] in names and end not in covered:
            end += 1
        acts = _acts_after(flat, tokens, end)
        if not acts:
            continue
        if tok in riding or any(
            t == tok and any(r.end <= j <= r.end + 1 for r in road_users) for j, t in enumerate(tokens) if j != i
        ):  # ("Sam in his Golf", "the cyclist, Sam": a road user's driver or rider)
            continue
        for m in acts:
            persons[m.start] = _passes(m)
    return persons


def _acts_after(flat: list, tokens: list[str], end: int) -> list:
    """The verbs said of a subject that ends at token ``end``: the first within two words after it,
    and those joined to it after, up to a road user named or the end of the clause."""
    out: list = []
    for m in flat:
        if m.start < end:
            continue
        if any(t in _CLAUSE_ENDS for t in tokens[end : m.start]):
            break
        if m.slot in _NAMING_SLOTS:
            break
        if not out and (m.start - end > 2 or not all(map(_word, tokens[end : m.start]))):
            break  # (its own verb comes right after it: not "Manoeuvre: cut-in")
        if m.slot in _ACT_SLOTS:
            out.append(m)
    return out


def _word(token: str) -> bool:
    """Whether ``token`` is a word, not punctuation or a number."""
    return token.replace("-", "").replace("'", "").isalpha()


def _passes(m) -> bool:
    """Whether behaviour mention ``m`` is a pass ("passed wide", "went past")."""
    return m.slot == "behaviour" and m.value[0] == "overtake"


#: Verbs (lemmas) of making, wanting or letting someone do something, said with an object and "to":
#: the verb after their object is the object's ("forced him to brake", "expects the ego to stop").
_CAUSING = frozenset(
    ("force", "cause", "make", "compel", "oblige", "expect", "want", "require", "need", "ask", "tell", "allow")
)
#: Of those, the one said with a bare infinitive ("made me brake").
_CAUSING_BARE = frozenset(("make",))
#: Objects said as a pronoun ("forcing him to brake").
_PERSON_OBJECTS = frozenset(("me", "us", "him", "her", "them", "you"))
#: Words that open an object said as a noun ("causing the driver to swerve").
_DETERMINERS = frozenset(("the", "a", "an", "my", "our", "his", "her", "their"))


def caused_acts(clauses: list, tokens: list[str]) -> dict[int, bool]:
    """The verbs a road user makes someone else do ("forcing him to brake", "causing us to stop",
    "made me slam on the brakes"), by their mention's start: the object's act, not the subject's,
    where the object names no road user (the ego, "him", "the driver"). ``tokens``: those the mentions
    index."""
    out: dict[int, bool] = {}
    flat = [m for _, ms in clauses for m in ms]
    road_users = [m for m in flat if m.slot == "actor" and m.value != "ego"]
    for m in flat:
        if m.slot not in _ACT_SLOTS or m.start < 2:
            continue
        bare = tokens[m.start - 1] != "to"
        end = m.start - (0 if bare else 1)  # (the object ends before the verb, or before its "to")
        j = end - 1
        if tokens[j] not in _PERSON_OBJECTS:
            j = next(
                (i for i in range(end - 1, max(end - 4, -1), -1) if not _word(tokens[i]) or tokens[i] in _DETERMINERS),
                -1,
            )
            if j < 0 or tokens[j] not in _DETERMINERS or "way" in tokens[j:end]:
                continue  # (the object "the driver", "the bus behind"; "made its way into my lane": no one made to)
        j -= 1
        verbs = set(lemmas(tokens[j]).get("VERB", ())) if j >= 0 else set()
        if not verbs & (_CAUSING_BARE if bare else _CAUSING):
            continue
        if any(j < r.start < end for r in road_users):
            continue  # ("forced the bus behind to brake": the bus's act, for the reader)
        for act in _acts_after(flat, tokens, m.start):  # ("to stamp on the brakes", "to brake and swerve")
            out[act.start] = False
    return out


def _after_an_object_pronoun(mentions: list, k: int, tokens: list[str]) -> bool:
    """Whether the modal at ``mentions[k]`` follows the ego said as an object after a verb the lexicon
    lacks ("... shot off the footpath right in front of me had to brake"): an object cannot be the
    modal's subject, so a clause of its own starts there. With no verb between the one named before
    and the ego ("a cyclist ahead of me had to brake") the modal is that one's."""
    before = mentions[k - 1] if k else None
    if before is None or before.slot != "actor" or before.value != "ego" or before.words not in ("me", "us"):
        return False
    named = next((x for x in reversed(mentions[: k - 1]) if x.slot in _NAMING), None)
    if named is None or named.value == "ego":
        return False
    span = range(named.end, before.start)
    return any(_a_past_verb(tokens[j]) and tokens[j - 1] not in _BEFORE_A_NOUN for j in span)


#: Words after which a past form is a noun or a side ("on the left", "to my left").
_BEFORE_A_NOUN = frozenset(("the", "a", "an", "my", "our", "his", "her", "their", "its", "your", "to"))


def _a_past_verb(word: str) -> bool:
    """Whether ``word`` is a verb in the past tense ("shot", "came"), not its plain form."""
    return _plain_or_past(word) and word not in lemmas(word).get("VERB", ())


def _run_on(mentions: list, k: int) -> bool:
    """Whether the modal at ``mentions[k]``, said after a verb in its clause, opens a clause of its own
    with its subject left out ("pulled out right in front of me had to brake", "..., had to stamp on
    the brakes"): nothing joins it to what came before ("and", "then") and no road user stands right
    before it as its subject ("the cyclist ahead of me had to brake" is the cyclist's)."""
    j = k - 1
    while j >= 0 and mentions[j].slot == "punct" and mentions[j].value == ",":
        j -= 1
    if j < 0:
        return False
    before = mentions[j]
    if before.slot in ("conj", "link", "relative"):
        return False
    return not (before.slot in _NAMING and before.value != "ego")


def not_meant(tokens: list[str], i: int) -> bool:
    """Whether the behaviour word at ``tokens[i]`` is said not to happen as a noun: right after "no"
    ("no braking", "no crossing intended") or as what an intent or its sign is denied of ("no
    intention of crossing", "without any sign of stopping")."""
    if i >= 1 and tokens[i - 1] == "no":
        return True
    if tokens[i].endswith("ing") and _modified_after_no(tokens, i):
        return True
    j = i - 1
    if j >= 0 and tokens[j] in ("of", "to"):
        j -= 1
    if j < 0 or tokens[j] not in _INTENT:
        return False
    j -= 1
    while j >= 0 and tokens[j] in _BEFORE_INTENT:
        j -= 1
    return j >= 0 and tokens[j] in ("no", "without")


def _modified_after_no(tokens: list[str], i: int) -> bool:
    """Whether the noun in -ing at ``tokens[i]`` follows "no" past one or two modifiers ("no
    pre-impact braking", "no sudden, harsh braking"): adjectives or hyphened words, never a noun of its
    own ("no lights braking": the lights are what is denied)."""
    j = i - 1
    while j >= 0 and i - j <= 2 and _modifier(tokens[j]):
        j -= 1
    return j < i - 1 and j >= 0 and tokens[j] == "no"


def _modifier(word: str) -> bool:
    """Whether ``word`` can modify a noun: an adjective ("harsh", "heavy") or a hyphened word ("pre-impact")."""
    return ("-" in word.strip("-") and word.isascii()) or "ADJ" in lemmas(word)


#: Road-user types that are ridden: "the rider" is one of them.
_RIDDEN = frozenset(("bicycle", "e-scooter"))
#: Words before "rider" that say it is one named before ("the rider", "this rider").
_BACK = frozenset(("the", "this", "that"))


#: Words that put someone on what they ride, before "one" that stands for it ("a kid on one").
_ON_ONE = frozenset(("on", "riding", "astride"))
#: Pronouns after "one of" that point back to the vehicles named ("on one of them", "riding one of those").
_OF_THEM = frozenset(("them", "those", "these"))


def _names_something(word: str) -> bool:
    """Whether ``word`` after "one" makes it a count of a noun ("on one side", "on one occasion", "on one
    of the crossings"), not the pronoun: a noun that is no inflected verb ("shot", "swerved" are verbs)."""
    pos = lemmas(word) if word.isalpha() else {}
    return word == "of" or ("NOUN" in pos and word in pos.get("VERB", (word,)))


def ridden_one(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> list[str]:
    """``tokens`` with "one" (or "one of them", "one of those") that stands for a ridden vehicle named
    before, said after "on" or "riding" ("E-scooters are everywhere. A teenager on one came flying out",
    "a lad riding one of them cut across"), said as one of that vehicle's kind ("an e-scooter": one,
    not the vehicles in general said again): the person rides it, one road user. Only right after a
    person's noun: with no one said on it, "riding one of those in the snow" names no road user. "One"
    that counts a noun after it ("on one side", "on one of the lanes") is left."""
    out: list[str] = []
    ridden: str | None = None
    person_end = -1  # (where the last person's noun ended in ``out``: the one on it comes right before)
    i = 0
    while i < len(tokens):
        found = kind_at(tokens, i)
        if found is not None:
            ridden = found[0] if found[0] in _RIDDEN else ridden
            out.extend(tokens[i : i + found[1]])
            person_end = len(out) if found[0] == "pedestrian" else person_end
            i += found[1]
            continue
        length = 3 if tokens[i + 1 : i + 3] in (["of", w] for w in _OF_THEM) else 1
        after = tokens[i + length] if i + length < len(tokens) else ""
        if (
            tokens[i] == "one"
            and ridden is not None
            and out[-1:]
            and out[-1] in _ON_ONE
            and person_end == len(out) - 1
            and kind_at(tokens, i + length) is None
            and not _names_something(after)
        ):
            out.extend(("an" if ridden[0] in "aeiou" else "a", ridden))  # ("a kid on one": on an e-scooter, a new one)
            i += length
            continue
        out.append(tokens[i])
        i += 1
    return out


def the_rider(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> list[str]:
    """``tokens`` with "the rider" (or "this rider") said as the word of
    the last ridden road user named before it ("a cyclist ... the rider": "the cyclist"), where
    ``kind_at`` (the reader's) reads no road user at that word and one was named. ``kind_at(tokens,
    i)`` gives the road-user type a phrase at ``i`` names and its length."""
    out = list(tokens)
    for i, tok in enumerate(out):
        if tok != "rider" or not i or out[i - 1] not in _BACK or kind_at(out, i) is not None:
            continue
        word, j = None, 0
        while j < i:
            found = kind_at(out, j)
            if found is not None and found[0] in _RIDDEN:
                word = out[j]
            j += found[1] if found is not None else 1
        if word is not None:
            out[i] = word
    return out


#: Nouns that say only who a person is (age, sex, a term of abuse), not what they do on the road: said
#: back with "the" where no one on foot was named, they name whoever rides or drives the road user named
#: last ("a lad on an e-scooter ... the lad", "a cyclist ... the boy rode off", "a van ... the idiot").
WHO_SOMEONE_IS = frozenset({"kid", "child", "boy", "girl", "lad", "lass", "man", "woman", "guy", "bloke", "fella",
                            "fellow", "chap", "teenager", "teen", "youth", "youngster", "lady", "gentleman", "dude",
                            "gent", "idiot", "lunatic", "maniac", "moron", "nutter", "muppet", "clown",
                            "fool", "person", "individual", "male", "female", "adult", "juvenile", "student",
                            "pupil", "schoolboy", "schoolgirl", "schoolkid", "kiddo", "victim",
                            "casualty"})  # fmt: skip
#: Words that, between "the" and such a noun, tell the person apart from one named before ("the other
#: lad", "the second man"): someone else, not the rider said again.
_TOLD_APART = frozenset({"other", "second", "third", "another", "different", "new", "next", "first"})
#: At most this many words that describe the person between "the" and the noun ("the poor young lad").
_DESCRIBING = 2
#: Words after such a noun that open a phrase placing or describing the person, who is then someone
#: else ("the man on the crossing", "the woman with the pram", "the lad who ...").
_DESCRIBED_BY = frozenset({"on", "in", "at", "with", "from", "by", "near", "outside", "beside", "behind", "who",
                           "that", "walking", "pushing", "crossing", "standing", "waiting", "'s"})  # fmt: skip


def _one_word_for(phrase: list[str], kind: str, kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> str:
    """The one word of ``phrase`` that names a road user of ``kind`` alone ("e-scooter rider": "rider"
    or "e-scooter"), the last first, or "" where none does: what a person said back is rewritten to."""
    for word in reversed(phrase):
        found = kind_at([word], 0)
        if found is not None and found[0] == kind:
            return word
    return ""


def _said_back(tokens: list[str], i: int) -> bool:
    """Whether the person's phrase starting at ``i`` opens with "the", "this" or "that", past up to
    :data:`_DESCRIBING` words that only describe the person ("the young man", "the poor kid"), none of
    which tells them apart from one named before ("the other lad")."""
    j = i - 1
    while j > 0 and i - j <= _DESCRIBING and tokens[j] not in _BACK and _modifier(tokens[j]):
        if tokens[j] in _TOLD_APART:
            return False
        j -= 1
    return j >= 0 and tokens[j] in _BACK


def the_person_said_back(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> list[str]:
    """``tokens`` with "the lad", "the kid", "the idiot" (:data:`WHO_SOMEONE_IS`, after "the", "this" or
    "that", also past a word or two that describe them: "the young man") said as the word of the road
    user named last before it, where no one on foot was named before and the person is not placed or
    described there ("the man on the crossing" is someone), nor a word that describes a road user's
    noun after it ("the female driver"): the person at its handlebars or wheel, no second road user."""
    out = list(tokens)
    last: str | None = None
    walker = False
    i = 0
    while i < len(out):
        found = kind_at(out, i)
        head = i + found[1] - 1 if found is not None and found[0] == "pedestrian" else i  # ("the old man")
        if out[head] in WHO_SOMEONE_IS and _said_back(out, i) and last is not None and not walker:
            nxt = out[head + 1] if head + 1 < len(out) else ""
            if nxt not in _DESCRIBED_BY and kind_at(out, head + 1) is None:
                out[head] = last
                i = head + 1
                continue
        if found is not None:
            if found[0] == "pedestrian":
                walker = True
            elif found[0] != "ego":
                last = _one_word_for(out[i : i + found[1]], found[0], kind_at) or last  # ("e-scooter rider")
            i += found[1]
            continue
        i += 1
    return out


def unnamed_rider(tokens: list[str], kind_at: Callable[[list[str], int], tuple[str, int] | None]) -> list[str]:
    """``tokens`` with a bare "rider" after a verb that no ridden road user named before stands for, and whose
    vehicle the text never says ("car clipped rider at roundabout", "Driver states rider was coming
    the wrong way"), said as "e-scooter": who rides, the two-wheeler this reader is about. Read
    before who is who, so that a report's one vehicle set against it is the ego. A rider said with
    what they ride ("rider on a moped"), a rider of a motorbike or moped named in the text, and "the
    rider" (said back, :func:`the_rider`) are left as they are."""
    out = list(tokens)
    ridden = False
    i = 0
    while i < len(out):
        found = kind_at(out, i)
        if found is not None:
            ridden = ridden or found[0] in _RIDDEN
            i += found[1]
            continue
        if out[i] == "rider" and not ridden and _after_a_verb(out, i) and _rides_nothing_said(out, i):
            out[i] = "e-scooter"
        i += 1
    return out


def _after_a_verb(tokens: list[str], i: int) -> bool:
    """Whether "rider" at ``i`` is said with no article right after a verb, as a terse note says the
    object or a reported subject ("car clipped rider", "driver states rider was coming"), not after a
    word that describes it ("young rider", "TP rider"). (After a mark, "Rider fell.", it is often the
    outcome's, or the ego of a test: "one: rider doing 15 km/h".)"""
    prev = tokens[i - 1] if i else ""
    pos = lemmas(prev) if prev.isalpha() else {}
    return ("VERB" in pos and not pos.keys() & {"ADJ", "NOUN"}) or prev in _SAYS


#: Verbs of telling, several of them nouns as well ("states", "reports", "says").
_SAYS = SAYING


def _rides_nothing_said(tokens: list[str], i: int) -> bool:
    """Whether the text says nothing of what a bare "rider" at ``i`` rides: no vehicle with it ("rider
    on a moped") and no motorbike or moped named anywhere (then "rider" is its rider)."""
    nxt = tokens[i + 1] if i + 1 < len(tokens) else ""
    if nxt in ("on", "of", "riding", "in", "aboard", "astride"):
        return False
    text = " ".join(tokens)
    singulars = {t[:-1] if t.endswith("s") else t for t in tokens}
    return not any(w in text for w in MOTOR_TWO_WHEELERS if " " in w) and not singulars & MOTOR_TWO_WHEELERS


#: What opens a sentence: a subject standing first after one of these is its clause's own.
_SENTENCE_ENDS = frozenset((".", "!", "?", ";", ":"))
#: Determiners and possessives a subject's noun phrase may open with ("the planner", "our software").
_SUBJECT_OPENERS = frozenset(("the", "a", "an", "our", "my", "its", "their", "his", "her"))
#: Adverbs that may stand between a subject and its verb ("the autopilot then braked").
_BETWEEN_SUBJECT_AND_VERB = frozenset(("then", "also", "immediately", "instantly", "just", "quickly", "finally"))


def unread_subjects_reactions(clauses: list, tokens: list[str]) -> dict[int, bool]:
    """The reactions (braking, stopping, slowing, swerving) whose subject is a common noun the reader
    reads as no road user, opening its sentence ("Planner braked to a full stop.", "The autopilot
    slowed sharply.", "Trainee stopped dead."), by their mention's start, with the verbs joined to
    them: a report names the ego's side by its role or its system (a planner, a candidate, a
    controller), and the reaction is theirs, not the road user named before. A subject read as a road
    user ("Jogger stopped dead.") keeps its verb, and so does a sentence with no subject ("Then braked
    sharply.") or one whose noun is no subject ("Seconds later the van braked"). A reaction said as a
    noun such a subject owns ("let the player's braking decide") is theirs as well."""
    out: dict[int, bool] = {}
    flat = [m for _, ms in clauses for m in ms]
    read = _read_positions(flat)
    by_start = {m.start: m for m in flat if m.slot in _ACT_SLOTS}
    for s, tok in enumerate(tokens):
        if s and tokens[s - 1] not in _SENTENCE_ENDS:
            continue
        i = s + (tok in _SUBJECT_OPENERS)
        j = i
        while j < len(tokens) and j - i < 3 and j not in read and _common_noun(tokens[j]):
            j += 1
        if j == i:
            continue
        while j < len(tokens) and tokens[j] in _BETWEEN_SUBJECT_AND_VERB:
            j += 1
        verb = by_start.get(j)
        if verb is None or verb.slot != "behaviour" or verb.value[0] not in _REACTIONS:
            continue
        for m in [verb, *_acts_after(flat, tokens, verb.end)]:
            out[m.start] = False
    for p, tok in enumerate(tokens):  # ("let the player's braking decide": the player's, said as a noun)
        if tok != "'s":
            continue
        i = _unread_nouns_before(tokens, p, read)
        if i == p or not (i == 0 or tokens[i - 1] in _SUBJECT_OPENERS or tokens[i - 1] in _SENTENCE_ENDS):
            continue
        noun = next((by_start[k] for k in range(p + 1, p + 3) if k in by_start), None)
        if noun is None or noun.slot != "behaviour" or noun.value[0] not in _REACTIONS:
            continue
        head = noun.words.split()[0]
        if any(k in read for k in range(p + 1, noun.start)) or not ("NOUN" in lemmas(head) or head.endswith("ing")):
            continue  # (its noun is a vehicle, whose verb follows: "the neighbour's van pulled out")
        out[noun.start] = False
    return out


def unread_subjects_passes(clauses: list, tokens: list[str]) -> dict[int, bool]:
    """The verbs of passing whose subject is a common noun the reader reads as no road user, opening
    its clause ("... and our rider overtakes it", "the learner overtook him wide", ", then the trainee
    went round her"), and whose object is a road user said before as a pronoun, by their mention's
    start, each True: the one passed is that road user, not the subject (no one is their own object),
    and the subject is the ego's side told by its role. A subject read as a road user ("a van overtook
    him") keeps its verb, and so does a verb of passing with no object pronoun after it."""
    out: dict[int, bool] = {}
    flat = [m for _, ms in clauses for m in ms]
    read = _read_positions(flat)
    for m in flat:
        after = tokens[m.end : m.end + 2]
        if m.slot != "behaviour" or not _passes(m) or not after:
            continue
        if not (after[0] in _OBJECT_PRONOUNS or (after[0] in _ROUND and after[1:] and after[1] in _OBJECT_PRONOUNS)):
            continue
        j = m.start
        while j > 0 and tokens[j - 1] in _BETWEEN_SUBJECT_AND_VERB:
            j -= 1
        i = _unread_nouns_before(tokens, j, read)
        if i == j:
            continue
        i -= i > 0 and tokens[i - 1] in _SUBJECT_OPENERS
        if i == 0 or tokens[i - 1] in _CLAUSE_OPENERS:
            out[m.start] = True
    return out


def _read_positions(flat: list) -> set[int]:
    """The token positions the reader's mentions ``flat`` cover (a verb it does not know covers none):
    a word there is read as something, so it is no unread noun of a subject."""
    return {i for m in flat if m.slot != "unknown_verb" for i in range(m.start, max(m.end, m.start + 1))}


def _unread_nouns_before(tokens: list[str], end: int, read: set[int]) -> int:
    """Where the run of up to three common nouns the reader read as nothing, right before ``end``,
    starts (``end`` where there is none): a subject told by its role ("the driving examiner")."""
    i = end
    while i > 0 and end - i < 3 and i - 1 not in read and _common_noun(tokens[i - 1]):
        i -= 1
    return i


def _common_noun(word: str) -> bool:
    """Whether ``word`` is a common noun and nothing else a subject could be (not a verb's form
    only, not a pronoun or an adverb): "planner", "candidate", "autopilot"."""
    found = lemmas(word)
    return "NOUN" in found and "ADV" not in found and "PRON" not in found and word.isalpha()


#: Participles of carrying out a reaction said as a noun ("brakes applied", "emergency stop performed").
_CARRIED_OUT = frozenset(("applied", "activated", "engaged", "initiated", "performed", "executed", "deployed",
                          "triggered", "actuated", "commanded", "taken", "made", "done", "used"))  # fmt: skip
#: Auxiliaries of a passive between the noun and its participle ("the brakes were applied").
_PASSIVE_BE = frozenset(("was", "were", "is", "are", "been", "being", "had", "has", "have", "then", "immediately"))


def agentless_reactions(clauses: list, tokens: list[str]) -> dict[int, bool]:
    """The reactions said as a noun opening a sentence in the passive with no agent ("Emergency brake
    applied.", "Brakes were applied hard", "Emergency braking initiated, no contact"), by their
    mention's start: a report's way of saying what its own driver did, so none of the road user named
    before. One whose agent is said ("... initiated by the lorry") is that agent's and stays."""
    out: dict[int, bool] = {}
    flat = [m for _, ms in clauses for m in ms]
    read = _read_positions(flat)
    for m in flat:
        if m.slot != "behaviour" or m.value[0] not in _REACTIONS:
            continue
        s = m.start
        while s > 0 and m.start - s < 2 and s - 1 not in read and _before_a_noun(tokens[s - 1]):
            s -= 1  # ("Evasive braking performed", "Full emergency braking applied": its modifiers)
        s -= s > 0 and tokens[s - 1] in _SUBJECT_OPENERS
        if s and tokens[s - 1] not in _SENTENCE_ENDS:
            continue
        j = m.end
        while j < len(tokens) and tokens[j] in _PASSIVE_BE:
            j += 1
        if j < len(tokens) and tokens[j] in _CARRIED_OUT and tokens[j + 1 : j + 2] != ["by"]:
            out[m.start] = False
    return out


def _before_a_noun(word: str) -> bool:
    """Whether ``word`` may stand before a noun of a reaction ("evasive", "emergency", "full"): an
    adjective, a noun or a hyphened word, no number."""
    found = lemmas(word)
    return _modifier(word) or (word.isalpha() and "NOUN" in found)
