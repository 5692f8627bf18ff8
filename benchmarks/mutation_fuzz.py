#!/usr/bin/env python3
"""Mutation fuzz over other authors' inputs: anything but a one-line refusal or a run is a finding.

Kinds (each case is a real input changed in one to three places, written to a copy of the files):
  scenario    esmini's examples and the Euro NCAP scenarios with numbers scaled, negated, zeroed or
              made tiny, enumerations set to other values of the standard, entity references swapped
  transplant  the same files with a Condition, PrivateAction, Position or Event replaced by one taken
              from another file (its entity references pointed at this file's entities)
  road        those scenarios played on their road networks with numbers, links and lane types changed
  clip        the bundled clips (vei-clip JSON and their OpenLABEL conversion) with values replaced,
              keys deleted, list items repeated, swapped or cut, then loaded (and with --compile compiled)

A finding is an exception other than VeiInputError, a refusal of more than one line, a numpy warning
or a run over ``--timeout`` seconds; the file that caused it is kept under the output directory.

    python benchmarks/mutation_fuzz.py KIND [--cases N] [--seed S] [--timeout S] [--compile] [-o DIR]

Runs of this session (2026-11): scenario 4 x 3 000 and 4 000, transplant 4 000, road 1 500 and 4 000,
clip 3 x 3 000 and 2 500 compiled: the findings were fixed (a keep of an actor's own speed or
distance refused by the core's quiet stretch with a ValueError, a lateral distance to the actor
itself, a lane range of a million lanes, numpy warnings before an OpenLABEL refusal).
"""

from __future__ import annotations

import argparse
import copy
import json
import random
import shutil
import signal
import sys
import tempfile
import time
import traceback
import warnings
from pathlib import Path

from lxml import etree

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"

#: Other values of the standard's enumerations a mutation may set.
ENUMS = {
    "rule": ["greaterThan", "lessThan", "equalTo", "greaterOrEqual", "lessOrEqual", "notEqualTo"],
    "dynamicsShape": ["linear", "cubic", "sinusoidal", "step"],
    "dynamicsDimension": ["time", "distance", "rate"],
    "followingMode": ["position", "follow"],
    "coordinateSystem": ["entity", "lane", "road", "trajectory"],
    "relativeDistanceType": ["longitudinal", "lateral", "euclidianDistance"],
    "triggeringEntitiesRule": ["any", "all"],
    "conditionEdge": ["rising", "falling", "risingOrFalling", "none"],
    "displacement": ["leadingReferencedEntity", "trailingReferencedEntity", "any"],
    "priority": ["overwrite", "override", "parallel", "skip"],
    "contactPoint": ["start", "end"],
    "elementType": ["road", "junction"],
}
ROAD_ENUMS = {
    "type": ["driving", "sidewalk", "border", "shoulder", "none", "biking", "stop", "median", "parking"],
    "junction": ["-1", "0", "1", "2", "999"],
    "elementId": ["0", "1", "2", "3", "999"],
    "id": ["-3", "-2", "-1", "0", "1", "2", "3"],
    "rule": ["RHT", "LHT"],
}
TRANSPLANTED = ["Condition", "PrivateAction", "Position", "EntityCondition", "ByValueCondition", "Event"]
JSON_VALUES = [None, True, 0, -1, 1e308, -1e308, 1e-320, 2**63, 3.5, "", "x", "nan", "1e400", [], {}, [1], {"a": 1},
               "2024-13-45T99:99:99Z", -0.0, 1e12, 90.0000001, 180.5, 100000]  # fmt: skip


class _Timeout(Exception):
    pass


def _alarm(*_) -> None:
    raise _Timeout()


def _scenarios(work: Path) -> list[Path]:
    """Copies of esmini's examples and the Euro NCAP scenarios (with their roads and catalogs),
    writable (the shared copies are read-only)."""
    shutil.copytree(SHARED / "esmini" / "xosc", work / "es" / "xosc")
    shutil.copytree(SHARED / "esmini" / "xodr", work / "es" / "xodr")
    shutil.copytree(SHARED / "osc-ncap", work / "nc")
    for d in [work, *work.rglob("*")]:
        d.chmod(d.stat().st_mode | 0o200)
    return sorted(work.glob("es/xosc/*.xosc")) + sorted(work.glob("nc/OpenSCENARIO/NCAP/*/*.xosc"))


def _number(rnd: random.Random, f: float) -> float:
    return rnd.choice([-f, 0.0, f * 1e6, f * 1e-6, 1e-9, -1e-9, f + rnd.uniform(-50, 50), 1e9, 2 * f, f / 2])


def _mutate_attributes(rnd: random.Random, root, enums: dict, times: int) -> None:
    names = [e.get("name") for e in root.iter("ScenarioObject")]
    elements = [e for e in root.iter() if isinstance(e.tag, str) and e.attrib]
    for _ in range(times):
        el = rnd.choice(elements)
        attr = rnd.choice(list(el.attrib))
        if attr in enums and rnd.random() < 0.7:
            el.set(attr, rnd.choice(enums[attr]))
        elif attr in ("entityRef", "masterEntityRef") and names:
            el.set(attr, rnd.choice(names))
        else:
            try:
                el.set(attr, repr(_number(rnd, float(el.get(attr)))))
            except ValueError:
                pass


def _transplant(rnd: random.Random, root, sources: list[Path]) -> None:
    names = [e.get("name") for e in root.iter("ScenarioObject")]
    tag = rnd.choice(TRANSPLANTED)
    here = [e for e in root.iter(tag) if e.getparent() is not None]
    there = list(etree.parse(str(rnd.choice(sources))).getroot().iter(tag))
    if not here or not there:
        return
    new = copy.deepcopy(rnd.choice(there))
    for x in new.iter():
        for a in ("entityRef", "masterEntityRef"):
            if x.get(a) is not None and names:
                x.set(a, rnd.choice(names))
        if x.tag == "Event" and x.get("name"):
            x.set("name", x.get("name") + "_t")
    old = rnd.choice(here)
    old.getparent().replace(old, new)


def _scenario_case(kind: str, rnd: random.Random, sources: list[Path], roads: dict) -> Path:
    """One mutated scenario, written beside its source (so that its relative paths hold)."""
    src = rnd.choice(list(roads) if kind == "road" else sources)
    tree = etree.parse(str(src))
    root = tree.getroot()
    if kind == "scenario":
        _mutate_attributes(rnd, root, ENUMS, rnd.choice([1, 1, 2, 3]))
    elif kind == "transplant":
        for _ in range(rnd.choice([1, 2])):
            _transplant(rnd, root, sources)
    else:
        road = etree.parse(str(roads[src]))
        _mutate_attributes(rnd, road.getroot(), ROAD_ENUMS, rnd.choice([1, 1, 2, 3]))
        mutated_road = roads[src].parent / ".mutated.xodr"
        road.write(str(mutated_road))
        root.find("RoadNetwork/LogicFile").set("filepath", str(mutated_road))
    out = src.parent / ".mutated.xosc"
    tree.write(str(out))
    return out


def _roads(sources: list[Path]) -> dict[Path, Path]:
    out = {}
    for s in sources:
        lf = etree.parse(str(s)).getroot().find("RoadNetwork/LogicFile")
        if lf is not None and lf.get("filepath") and "$" not in lf.get("filepath"):
            road = (s.parent / lf.get("filepath")).resolve()
            if road.is_file():
                out[s] = road
    return out


def _clip_case(rnd: random.Random, docs: list, work: Path) -> Path:
    doc = copy.deepcopy(rnd.choice(docs))
    for _ in range(rnd.choice([1, 1, 2, 3])):
        paths = list(_json_paths(doc))[1:]
        path = rnd.choice(paths)
        parent = doc
        for p in path[:-1]:
            parent = parent[p]
        key, r = path[-1], rnd.random()
        old = parent[key]
        if r < 0.15 and isinstance(parent, dict):
            del parent[key]
        elif r < 0.35 and isinstance(parent, list) and len(parent) > 1:
            i, j = rnd.randrange(len(parent)), rnd.randrange(len(parent))
            if r < 0.25:
                parent.insert(i, copy.deepcopy(parent[j]))
            else:
                parent[i], parent[j] = parent[j], parent[i]
        elif r < 0.6 and isinstance(old, (int, float)) and not isinstance(old, bool):
            parent[key] = _number(rnd, float(old))
        elif r < 0.7 and isinstance(old, list) and old:
            del old[rnd.randrange(len(old)) :]
        else:
            parent[key] = copy.deepcopy(rnd.choice(JSON_VALUES))
    out = work / "clip.json"
    out.write_text(json.dumps(doc))
    return out


def _json_paths(doc, path=()):
    yield path
    items = doc.items() if isinstance(doc, dict) else enumerate(doc[:6]) if isinstance(doc, list) else ()
    for k, v in items:
        yield from _json_paths(v, (*path, k))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("kind", choices=["scenario", "transplant", "road", "clip"])
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--timeout", type=int, default=60, help="a run longer than this is a finding (s)")
    ap.add_argument("--compile", action="store_true", help="clip: also compile each clip that loads")
    ap.add_argument("-o", "--output", default="mutation_findings", help="where the inputs of findings are kept")
    args = ap.parse_args()

    from vei_scenario.clip import load_clip
    from vei_scenario.clip.openlabel import convert_clip
    from vei_scenario.compiler import compile_clip
    from vei_scenario.errors import VeiInputError
    from vei_scenario.interpreter import clear_file_caches, run_scenario

    warnings.simplefilter("error", RuntimeWarning)
    rnd = random.Random(args.seed)
    found = Path(args.output)
    work = Path(tempfile.mkdtemp(prefix="vei-fuzz-"))
    signal.signal(signal.SIGALRM, _alarm)
    if args.kind == "clip":
        docs = []
        for clip in sorted((ROOT / "examples").glob("*/clip.json")):
            converted = work / f"{clip.parent.name}.openlabel.json"
            convert_clip(clip, converted)
            docs += [json.loads(clip.read_text()), json.loads(converted.read_text())]
    else:
        sources = [p for p in _scenarios(work) if not p.name.startswith(".")]
        roads = _roads(sources) if args.kind == "road" else {}
    findings: dict[str, str] = {}
    counts = {"ran": 0, "refused": 0}
    started = time.time()
    for i in range(args.cases):
        case = _clip_case(rnd, docs, work) if args.kind == "clip" else _scenario_case(args.kind, rnd, sources, roads)
        clear_file_caches()
        signal.alarm(args.timeout)
        try:
            if args.kind == "clip":
                load_clip(case)
                if args.compile:
                    compile_clip(case, work / "out" / "scenario.xosc")
            else:
                run_scenario(case, {}, 0.01)
            counts["ran"] += 1
            continue
        except VeiInputError as exc:
            counts["refused"] += 1
            if "\n" not in str(exc).strip():
                continue
            key = "a refusal of more than one line"
        except _Timeout:
            key = f"over {args.timeout} s"
        except Exception as exc:  # noqa: BLE001 (what the fuzz is looking for)
            last = traceback.extract_tb(exc.__traceback__)[-1]
            key = f"{type(exc).__name__} at {Path(last.filename).name}:{last.lineno}: {str(exc)[:120]}"
        finally:
            signal.alarm(0)
        if key not in findings:
            found.mkdir(parents=True, exist_ok=True)
            kept = found / f"{args.kind}_{args.seed}_{i}{case.suffix}"
            shutil.copy(case, kept)
            findings[key] = str(kept)
    shutil.rmtree(work, ignore_errors=True)
    print(
        f"{args.kind}, seed {args.seed}: {args.cases} cases in {time.time() - started:.0f} s "
        f"({counts['ran']} ran or loaded, {counts['refused']} refused in one line); {len(findings)} findings"
    )
    for key, kept in findings.items():
        print(f"  {key}\n    input: {kept}")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
