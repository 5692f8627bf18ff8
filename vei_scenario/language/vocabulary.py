"""The rules backend's vocabulary: phrases a description may use, and what each one means.

Every phrase maps to a (slot, value) pair. The parser matches the longest phrase first; a word no
phrase covers and that is not a filler word is reported back as not understood. Keep phrases lower
case, words separated by single spaces; ``#`` stands for a number.
"""

from __future__ import annotations

#: Words that name a vehicle by its place in a line of them, right before its noun ("following truck").
IN_LINE = frozenset({"following", "lead", "leading", "trailing", "rear", "front"})
#: Person nouns of each gender, by their possessive, a small closed class: one named besides the driver
#: may be "she"/"he" ("a girl ran out ... she stopped"; "a woman walking ... in front of her").
GENDERED = {
    "her": frozenset("woman women girl girls lady mother mum gran grandmother schoolgirl daughter".split()),
    "his": frozenset("man men boy boys lad lads gentleman father dad grandad schoolboy son bloke".split()),
}

ACTORS = {
    "ego": ("ego", None),
    "ego vehicle": ("ego", None),
    "ego car": ("ego", None),
    "the av": ("ego", None),
    "vehicle under test": ("ego", None),
    "autonomous vehicle": ("ego", None),
    "us": ("ego", None),
    "car": ("actor", "car"),
    "sedan": ("actor", "car"),
    "vehicle": ("actor", "car"),
    "suv": ("actor", "car"),
    "adversarial vehicle": ("actor", "car"),
    "adversary": ("actor", "car"),
    "other car": ("actor", "car"),
    "other vehicle": ("actor", "car"),
    "van": ("actor", "van"),
    "truck": ("actor", "truck"),
    "lorry": ("actor", "truck"),
    "bicycle": ("actor", "bicycle"),
    "bike": ("actor", "bicycle"),
    "cyclist": ("actor", "bicycle"),
    "e-scooter": ("actor", "e-scooter"),
    "escooter": ("actor", "e-scooter"),
    "scooter": ("actor", "e-scooter"),
    "e-scooter rider": ("actor", "e-scooter"),
    "scooter rider": ("actor", "e-scooter"),
    "pedestrian": ("actor", "pedestrian"),
    "person": ("actor", "pedestrian"),
    "walker": ("actor", "pedestrian"),
    "child": ("actor", "pedestrian"),
}
#: References back to an actor already named ("it", "the car"): the clause's subject stays.
PRONOUNS = {"it", "they", "he", "she", "itself", "its", "their", "his", "her", "the same car"}

MAPS = {
    "crossroad": "crossroad",
    "crossroads": "crossroad",
    "intersection": "crossroad",
    "junction": "crossroad",
    "four-way crossroad": "crossroad",
    "signalised intersection": "crossroad",
    "traffic light": "crossroad",
    "traffic lights": "crossroad",
    "roundabout": "roundabout",
    "traffic circle": "roundabout",
    "curve": "curve",
    "curved road": "curve",
    "bend": "curve",
    "winding road": "curve",
    "straight road": "straight",
    "highway": "straight",
    "motorway": "straight",
    "freeway": "straight",
    "road": "straight",
    "multi-lane road": "straight",
    "two-lane road": "straight",
    "street": "straight",
}
LANE_COUNTS = {"single-lane": 1, "one-lane": 1, "two-lane": 2, "three-lane": 3, "four-lane": 4, "multi-lane": 2}
WEATHER = {
    "clear": "clear",
    "sunny": "clear",
    "sunny day": "clear",
    "dry": "clear",
    "cloudy": "cloudy",
    "overcast": "cloudy",
    "rain": "rain",
    "rainy": "rain",
    "raining": "rain",
    "wet": "rain",
    "drizzle": "rain",
    "rainy day": "rain",
    "heavy rain": "heavy_rain",
    "pouring rain": "heavy_rain",
    "storm": "heavy_rain",
    "fog": "fog",
    "foggy": "fog",
    "mist": "fog",
    "misty": "fog",
    "snow": "snow",
    "snowy": "snow",
    "snowing": "snow",
    "icy": "snow",
}
TIMES = {
    "dawn": "06:00",
    "morning": "08:30",
    "misty morning": "07:30",
    "noon": "12:00",
    "midday": "12:00",
    "afternoon": "15:30",
    "dusk": "19:30",
    "evening": "20:00",
    "night": "23:00",
    "at night": "23:00",
    "rush hour": "17:30",
}
DENSITY = {
    "no traffic": "none",
    "empty road": "none",
    "light traffic": "light",
    "sparse traffic": "light",
    "little traffic": "light",
    "moderate traffic": "moderate",
    "some traffic": "moderate",
    "heavy traffic": "heavy",
    "dense traffic": "heavy",
    "busy": "heavy",
    "congested": "heavy",
    "traffic": "moderate",
}
RELATIONS = {
    "on the left": "left",
    "in the left lane": "left",
    "on the left lane": "left",
    "left lane": "left",
    "from the left lane": "left",
    "in the adjacent left lane": "left",
    "to the left of the ego": "left",
    "on the right": "right",
    "in the right lane": "right",
    "on the right lane": "right",
    "right lane": "right",
    "from the right lane": "right",
    "to the right of the ego": "right",
    "ahead": "ahead",
    "in front": "ahead",
    "ahead of the ego": "ahead",
    "leading": "ahead",
    "lead": "ahead",
    "behind": "behind",
    "behind the ego": "behind",
    "following": "behind",
    "oncoming": "oncoming",
    "from the opposite direction": "oncoming",
    "in the opposite lane": "oncoming",
    "from the left entrance": "junction_left",
    "at the left entrance": "junction_left",
    "from the left side": "junction_left",
    "from the left road": "junction_left",
    "from the right entrance": "junction_right",
    "at the right entrance": "junction_right",
    "from the right side": "junction_right",
    "from the right road": "junction_right",
    "from the roadside": "roadside_right",
    "from the kerb": "roadside_right",
    "from the curb": "roadside_right",
    "from the sidewalk": "roadside_right",
    "from the pavement": "roadside_right",
    "from the left sidewalk": "roadside_left",
    "from the left kerb": "roadside_left",
}
BEHAVIOURS = {
    "cuts in": ("cut_in", {}),
    "cut in": ("cut_in", {}),
    "cutting in": ("cut_in", {}),
    "cuts into": ("cut_in", {}),
    "merges in": ("cut_in", {}),
    "squeezes in": ("cut_in", {}),
    "overtakes": ("overtake", {}),
    "overtake": ("overtake", {}),
    "overtaking": ("overtake", {}),
    "passes": ("overtake", {}),
    "follows": ("follow_vehicle", {}),
    "follow": ("follow_vehicle", {}),
    "tailgates": ("follow_vehicle", {}),
    "following closely": ("follow_vehicle", {}),
    "suddenly stops": ("sudden_stop", {}),
    "stops suddenly": ("sudden_stop", {}),
    "sudden stop": ("sudden_stop", {}),
    "brakes hard": ("sudden_stop", {}),
    "slams on the brakes": ("sudden_stop", {}),
    "emergency brakes": ("sudden_stop", {}),
    "brakes suddenly": ("sudden_stop", {}),
    "suddenly brakes": ("sudden_stop", {}),
    "stops": ("stop", {}),
    "stop": ("stop", {}),
    "comes to a stop": ("stop", {}),
    "halts": ("stop", {}),
    "turns right forcefully": ("forced_turn", {"turn": "right"}),
    "forcefully turns right": ("forced_turn", {"turn": "right"}),
    "forces a right turn": ("forced_turn", {"turn": "right"}),
    "force right turn": ("forced_turn", {"turn": "right"}),
    "forced right turn": ("forced_turn", {"turn": "right"}),
    "turns right": ("forced_turn", {"turn": "right"}),
    "makes a right turn": ("forced_turn", {"turn": "right"}),
    "runs the red light": ("run_red_light", {}),
    "runs a red light": ("run_red_light", {}),
    "running the red light": ("run_red_light", {}),
    "running red light": ("run_red_light", {}),
    "ignores the red light": ("run_red_light", {}),
    "jumps the red light": ("run_red_light", {}),
    "runs the red": ("run_red_light", {}),
    "crosses": ("cross_in_front", {}),
    "crosses the road": ("cross_in_front", {}),
    "crossing the road": ("cross_in_front", {}),
    "crosses in front": ("cross_in_front", {}),
    "darts out": ("cross_in_front", {}),
    "steps out": ("cross_in_front", {}),
    "rides across": ("cross_in_front", {}),
    "keeps going": ("keep_going", {}),
    "continues": ("keep_going", {}),
    "carries on": ("keep_going", {}),
    "keeps its lane": ("keep_lane", {}),
    "keeps lane": ("keep_lane", {}),
    "stays in its lane": ("keep_lane", {}),
    "accelerates": ("change_speed", {"speed_delta_mps": 4.0}),
    "speeds up": ("change_speed", {"speed_delta_mps": 4.0}),
    "decelerates": ("change_speed", {"speed_delta_mps": -4.0}),
    "slows down": ("change_speed", {"speed_delta_mps": -4.0}),
    "changes lane to the left": ("change_lane", {"direction": 1.0}),
    "changes lane to the right": ("change_lane", {"direction": -1.0}),
    "changes lanes": ("change_lane", {}),
    "changes lane": ("change_lane", {}),
}
#: Ego verbs: they say the ego drives (and where), no adversarial behaviour.
EGO_VERBS = {
    "drives": None,
    "driving": None,
    "is driving": None,
    "goes straight": "straight",
    "goes": None,
    "drives straight": "straight",
    "going straight": "straight",
    "passes through": "straight",
    "crosses the junction": "straight",
    "approaches": None,
    "approaching": None,
    "travels": None,
    "cruises": None,
    "moves": None,
    "heads": None,
    "turns left": "left",
    "ego turns right": "right",
    "goes through": "straight",
    "straight": "straight",
    "is": None,
    "enters": None,
    "entering": None,
    "rides": None,
    "ride": None,
    "riding": None,
    "ride side by side": None,
    "appears": None,
    "appear": None,
    "shows up": None,
    "comes into view": None,
}
CRITICALITY = {
    "aggressively": "dangerous",
    "aggressive": "dangerous",
    "dangerously": "dangerous",
    "dangerous": "dangerous",
    "very closely": "dangerous",
    "closely": "dangerous",
    "very close": "dangerous",
    "abruptly": "dangerous",
    "recklessly": "dangerous",
    "sharply": "dangerous",
    "forcefully": "dangerous",
    "at the last moment": "dangerous",
    "in a decent way": "moderate",
    "decently": "moderate",
    "normally": "moderate",
    "moderately": "moderate",
    "in a normal way": "moderate",
    "at a moderate distance": "moderate",
    "reasonably": "moderate",
    "remotely": "safe",
    "far ahead": "safe",
    "safely": "safe",
    "gently": "safe",
    "smoothly": "safe",
    "cautiously": "safe",
    "at a safe distance": "safe",
    "with a large gap": "safe",
    "far away": "safe",
    "politely": "safe",
    "from far": "safe",
}
INTENTS = {
    "almost hits": "near_miss",
    "nearly hits": "near_miss",
    "almost hit": "near_miss",
    "almost collides": "near_miss",
    "nearly collides": "near_miss",
    "near miss": "near_miss",
    "narrowly misses": "near_miss",
    "barely misses": "near_miss",
    "hits": "collision",
    "crashes into": "collision",
    "collides with": "collision",
    "rams": "collision",
    "without danger": "safe",
    "safe": "safe",
    "no danger": "safe",
}
#: Words that carry no meaning of their own here.
FILLER = set(
    """a an the of in on at to and then with is are was be it its into onto from by for as this that which who
    while when after before so lane lanes side front way road's ego's some one there their where just
    but also very quite across through near next up down out off over way toward towards around
    vehicle's car's""".split()
)
SEQUENCE_WORDS = {"then", "after that", "afterwards", "and then", "next"}
PARALLEL_WORDS = {"while", "at the same time", "simultaneously", "meanwhile"}
#: Speeds: "# km/h", "# kph", "# mph", "# m/s".
SPEED_UNITS = {"km/h": 1 / 3.6, "kph": 1 / 3.6, "kmh": 1 / 3.6, "mph": 0.44704, "m/s": 1.0}
SPEED_WORDS = {
    "fast": 1.25,
    "faster": 1.25,
    "quickly": 1.2,
    "slowly": 0.7,
    "slow": 0.7,
    "slower": 0.7,
    "slow-moving": 0.6,
    "slow moving": 0.6,
    "at high speed": 1.35,
    "at low speed": 0.65,
}

#: Nouns that name any vehicle: a definite one of them is the most recent vehicle named (discourse); a party
#: said to be one names no kind of road user yet (lettered_parties).
GENERAL_VEHICLE = frozenset({"vehicle", "vehicles"})

#: Roles of the person a driving lesson or test is about ("the pupil", "cand", "applicant"): at a road
#: speed or at a vehicle's controls, that person drives the ego.
LEARNER = frozenset({"pupil", "learner", "trainee", "candidate", "cand", "applicant", "student"})

#: The people of a narrator's own party, by what the narrator calls them ("Dad", "my husband", "Mum"): a
#: closed class. One of them at the wheel, in a story told from inside the car, drives the ego.
PARTY = frozenset(
    {"dad", "daddy", "papa", "pa", "father", "mum", "mummy", "mom", "mommy", "mama", "mam", "mother", "grandad",
     "granddad", "grandpa", "grandma", "granny", "gran", "nan", "nana", "husband", "hubby", "wife", "partner",
     "brother", "sister", "son", "daughter", "uncle", "aunt", "auntie", "aunty", "cousin", "boyfriend",
     "girlfriend", "fiance", "fiancee", "friend", "mate", "bhaiya", "didi", "chacha", "mamu", "missus", "missis",
     "grandson", "granddaughter", "nephew", "niece", "stepdad", "stepmum", "stepmom", "appa", "amma", "abba"}
)  # fmt: skip


#: The last word of a road's name ("King St", "Elm Close", "Station Road"), abbreviated or not.
STREET_WORDS = frozenset(
    {"road", "rd", "street", "st", "lane", "ln", "avenue", "ave", "close", "way", "drive", "dr", "crescent",
     "terrace", "grove", "boulevard", "blvd", "parade", "gardens", "mews", "place", "court", "row", "hill"}
)  # fmt: skip
