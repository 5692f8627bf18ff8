"""``validate_files``: ASAM XSD validation plus the rules schema validation cannot see.

Problems are data: one :class:`Problem` per finding, naming the file, the line, the rule and what is
wrong; an empty list means valid. The VEI rules cover what a runnable scenario needs and the ASAM
Quality Checker does not flag:

* ``parameter.undeclared``: a ``$Name`` (or a name inside ``${...}``) that no declaration provides;
* ``file.missing``: a ``LogicFile``/``ScenarioFile`` that does not exist (a path given by a parameter at
  its declared value; a ``SceneGraphFile``, a 3D model for viewers, is not needed to run);
* ``trajectory.vertex-time``: polyline vertex times that do not strictly increase, on a path played by
  its times (not one a FollowTrajectoryAction follows without a Timing);
* ``distribution.unknown-parameter``: a distribution varying a parameter its scenario does not declare,
  or a value that does not fit the declared type;
* ``reference.dangling``: an entity, storyboard element or road/junction reference to nothing.
"""

from __future__ import annotations

import json
import re
from dataclasses import asdict, dataclass
from functools import cache
from pathlib import Path

from lxml import etree

from vei_scenario.errors import VeiInputError
from vei_scenario.openscenario import STORYBOARD_ELEMENT_TYPES
from vei_scenario.openscenario.asam_schemas import xsd_path
from vei_scenario.safe_xml import json_hint, safe_parser


@dataclass(frozen=True)
class Problem:
    file: str
    line: int | None
    rule: str
    message: str

    def __str__(self) -> str:
        where = f"{self.file}:{self.line}" if self.line else self.file
        return f"{where}: [{self.rule}] {self.message}"


_PARAM_REF = re.compile(r"\$\{([^}]*)\}|^\$([A-Za-z_][A-Za-z0-9_]*)$")
_EXPR_NAME = re.compile(r"\$([A-Za-z_][A-Za-z0-9_]*)")


@cache
def _schema(path: Path):
    doc = etree.parse(str(path), safe_parser())
    return etree.XMLSchema(doc)


def _parse(path: Path, problems: list[Problem]):
    try:
        return etree.parse(str(path), safe_parser())
    except etree.XMLSyntaxError as exc:
        hint = json_hint(path)
        problems.append(Problem(str(path), exc.lineno or None, "xml.syntax", f"malformed XML: {exc.msg}{hint}"))
    except OSError as exc:
        problems.append(Problem(str(path), None, "file.unreadable", str(exc)))
    return None


def _xsd_problems(path: Path, tree, kind: str, minor: int, problems: list[Problem]) -> None:
    try:
        xsd = xsd_path(kind, minor)
    except KeyError:
        label = "OpenSCENARIO" if kind == "xosc" else "OpenDRIVE"
        problems.append(Problem(str(path), 1, "version.unknown", f"no ASAM XSD for {label} 1.{minor}"))
        return
    if kind == "xodr" and minor >= 8:  # ASAM ships OpenDRIVE 1.8 as XSD 1.1, which lxml cannot read
        import xmlschema

        schema = xmlschema.XMLSchema11(str(xsd))
        for err in schema.iter_errors(tree):
            problems.append(Problem(str(path), getattr(err, "sourceline", None), "xsd", err.reason or str(err)))
        return
    schema = _schema(xsd)
    if not schema.validate(tree):
        for err in schema.error_log:
            problems.append(Problem(str(path), err.line, "xsd", f"{err.message} (ASAM {xsd.parent.name} XSD)"))


def _declared(root) -> dict[str, tuple[str, str]]:
    """Declared names (a leading ``$`` dropped, as the players read ``name="$owner"``)."""
    return {
        d.get("name").lstrip("$"): (d.get("parameterType", ""), d.get("value", ""))
        for d in root.iter("ParameterDeclaration", "VariableDeclaration")
        if d.get("name")
    }


#: Attributes that name a parameter rather than use its value: a catalog entry's parameter (declared in
#: the catalog, not here) and the declarations themselves.
_NAMING = {("ParameterAssignment", "parameterRef"), ("ParameterDeclaration", "name"), ("VariableDeclaration", "name")}


def _parameter_problems(path: Path, root, problems: list[Problem]) -> None:
    declared = _declared(root)
    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        for attr, value in el.attrib.items():
            if "$" not in value or (el.tag, attr) in _NAMING:
                continue
            names = []
            m = _PARAM_REF.match(value)
            if m and m.group(2):
                names = [m.group(2)]
            elif value.startswith("${"):
                names = _EXPR_NAME.findall(value)
            for name in names:
                if name not in declared:
                    problems.append(
                        Problem(
                            str(path),
                            el.sourceline,
                            "parameter.undeclared",
                            f'<{el.tag} {attr}="{value}">: parameter ${name} is not declared',
                        )
                    )


def _file_problems(path: Path, root, problems: list[Problem]) -> None:
    """The files a run needs: the road network and a distribution's scenario. (A SceneGraphFile is a
    3D model for viewers: players run without it, and scenarios are often shared without theirs.)
    A path given by a top-level parameter (``$Road_Logics``) is checked at its declared value."""
    declared = {
        (d.get("name") or "").lstrip("$"): d.get("value", "")
        for d in root.iterfind("ParameterDeclarations/ParameterDeclaration")
    }
    for tag in ("LogicFile", "ScenarioFile"):
        for el in root.iter(tag):
            ref = el.get("filepath", "")
            m = _PARAM_REF.match(ref)
            if m and m.group(2) and m.group(2) in declared:  # (an undeclared one is reported as such)
                ref = declared[m.group(2)]
            if not ref or "$" in ref:
                continue
            if not (path.parent / ref).is_file():
                problems.append(
                    Problem(
                        str(path),
                        el.sourceline,
                        "file.missing",
                        f'<{tag} filepath="{el.get("filepath")}">: no such file next to {path.name}'
                        + (f" ({ref})" if ref != el.get("filepath") else ""),
                    )
                )


def _vertex_problems(path: Path, root, problems: list[Problem]) -> None:
    """Vertex times that do not increase, on a path played by its times: not on one a
    FollowTrajectoryAction follows without a Timing (its times are not read: esmini's
    pedestrian_collision gives every vertex time 0)."""
    for poly in root.iter("Polyline"):
        follow = next(poly.iterancestors("FollowTrajectoryAction"), None)
        if follow is not None and follow.find("TimeReference/Timing") is None:
            continue
        last = None
        for v in poly.iterfind("Vertex"):
            t = v.get("time")
            if t is None or "$" in t:
                continue
            try:
                tv = float(t)
            except ValueError:
                continue  # the XSD reports the type
            if last is not None and tv <= last:
                problems.append(
                    Problem(
                        str(path),
                        v.sourceline,
                        "trajectory.vertex-time",
                        f"vertex time {t} does not increase (previous {last:g})",
                    )
                )
            last = tv


def _reference_problems(path: Path, root, problems: list[Problem]) -> None:
    if root.find("Catalog") is not None:  # a catalog's entries name the entities of the scenarios using it
        return
    entities = {o.get("name") for o in root.iter("ScenarioObject", "EntitySelection")}
    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        for attr in ("entityRef", "masterEntityRef"):
            ref = el.get(attr)
            if ref and "$" not in ref and ref not in entities:
                problems.append(
                    Problem(
                        str(path),
                        el.sourceline,
                        "reference.dangling",
                        f'<{el.tag} {attr}="{ref}">: no entity of that name',
                    )
                )
    elements: dict[str, set[str]] = {}
    for tag in STORYBOARD_ELEMENT_TYPES.values():
        elements[tag] = {e.get("name") for e in root.iter(tag) if e.get("name")}
    elements["Action"] |= {e.get("name") for e in root.iter("PrivateAction", "GlobalAction", "UserDefinedAction")}
    for cond in root.iter("StoryboardElementStateCondition"):
        kind = STORYBOARD_ELEMENT_TYPES.get(cond.get("storyboardElementType", ""))
        ref = cond.get("storyboardElementRef", "")
        if kind and ref and "$" not in ref and ref not in elements[kind] and not _qualified(root, kind, ref):
            problems.append(
                Problem(
                    str(path),
                    cond.sourceline,
                    "reference.dangling",
                    f'storyboardElementRef="{ref}": no {kind} of that name',
                )
            )


def _qualified(root, kind: str, ref: str) -> bool:
    """Whether ``ref`` is esmini's qualified reference to an element of ``kind`` (``Event::Action``,
    ``Maneuver::Event::Action``: the element's name after the names of elements it lies in)."""
    parts = ref.split("::")
    if len(parts) < 2 or not all(parts):
        return False
    for el in root.iter(kind):
        if el.get("name") != parts[-1]:
            continue
        above = [a.get("name") for a in el.iterancestors() if a.get("name") is not None]
        want, k = parts[-2::-1], 0  # (the enclosing names, nearest first, in order)
        for name in above:
            if k < len(want) and name == want[k]:
                k += 1
        if k == len(want):
            return True
    return False


def _distribution_problems(path: Path, root, problems: list[Problem]) -> None:
    sf = root.find(".//ScenarioFile")
    if sf is None:
        return
    target = path.parent / sf.get("filepath", "")
    if not target.is_file():
        return  # reported by _file_problems
    try:
        declared = _declared(etree.parse(str(target), safe_parser()).getroot())
    except etree.XMLSyntaxError:
        problems.append(Problem(str(path), sf.sourceline, "file.unreadable", f"{target.name} is not well-formed XML"))
        return
    for el in root.iter():
        if not isinstance(el.tag, str):
            continue
        name = el.get("parameterName")
        if name is None:
            continue
        if name not in declared:
            problems.append(
                Problem(
                    str(path),
                    el.sourceline,
                    "distribution.unknown-parameter",
                    f"<{el.tag}> varies {name!r}, which {target.name} does not declare",
                )
            )
            continue
        ptype = declared[name][0]
        values = [el.get("value")] if el.get("value") is not None else []
        values += [v.get("value") for v in el.iter("Element") if v.get("value") is not None]
        for v in values:
            if not _fits(ptype, v):
                problems.append(
                    Problem(
                        str(path),
                        el.sourceline,
                        "distribution.value-type",
                        f"value {v!r} of {name!r} is not a valid {ptype}",
                    )
                )


def _fits(ptype: str, value: str) -> bool:
    try:
        if ptype == "double":
            float(value)
        elif ptype in ("int", "integer", "unsignedInt", "unsignedShort"):
            int(value)
        elif ptype == "boolean":
            return value in ("true", "false")
    except ValueError:
        return False
    return True


def _link_problems(path: Path, root, problems: list[Problem]) -> None:
    roads = {r.get("id") for r in root.iter("road")}
    junctions = {j.get("id") for j in root.iter("junction")}
    for road in root.iter("road"):
        link = road.find("link")
        if link is None:
            continue
        for end in link:
            kind, ref = end.get("elementType"), end.get("elementId")
            pool = roads if kind == "road" else junctions if kind == "junction" else None
            if pool is not None and ref not in pool:
                problems.append(
                    Problem(
                        str(path),
                        end.sourceline,
                        "reference.dangling",
                        f"road {road.get('id')} <{end.tag}> names {kind} {ref!r}, which does not exist",
                    )
                )
        if road.get("junction", "-1") not in ("-1", "") and road.get("junction") not in junctions:
            problems.append(
                Problem(
                    str(path),
                    road.sourceline,
                    "reference.dangling",
                    f"road {road.get('id')} belongs to junction {road.get('junction')!r}, which does not exist",
                )
            )
    for conn in root.iter("connection"):
        for attr in ("incomingRoad", "connectingRoad"):
            ref = conn.get(attr)
            if ref is not None and ref not in roads:
                problems.append(
                    Problem(
                        str(path),
                        conn.sourceline,
                        "reference.dangling",
                        f"junction connection {attr}={ref!r}: no road of that id",
                    )
                )


def validate_file(path: Path, xsd: bool = True) -> list[Problem]:
    """Problems of one ``.xosc`` or ``.xodr`` file (empty when valid)."""
    path = Path(path)
    if not path.is_file():
        raise VeiInputError(path, "", "file not found")
    problems: list[Problem] = []
    tree = _parse(path, problems)
    if tree is None:
        return problems
    root = tree.getroot()
    if tree.docinfo.internalDTD is not None:
        problems.append(Problem(str(path), 1, "xml.dtd", "DTDs and entity declarations are not allowed"))
        return problems
    if root.tag == "OpenSCENARIO":
        header = root.find("FileHeader")
        kind = "xosc"
    elif root.tag == "OpenDRIVE":
        header = root.find("header")
        kind = "xodr"
    else:
        return [
            Problem(str(path), root.sourceline, "file.kind", f"root <{root.tag}> is neither OpenSCENARIO nor OpenDRIVE")
        ]
    try:
        major, minor = int(header.get("revMajor")), int(header.get("revMinor"))
    except (AttributeError, TypeError, ValueError):
        return [Problem(str(path), root.sourceline, "version.unknown", "header without numeric revMajor/revMinor")]
    if major != 1:
        return [Problem(str(path), header.sourceline, "version.unknown", f"version {major}.{minor} is not 1.x")]
    if xsd:
        _xsd_problems(path, tree, kind, minor, problems)
    if kind == "xosc":
        _parameter_problems(path, root, problems)
        _file_problems(path, root, problems)
        _vertex_problems(path, root, problems)
        _reference_problems(path, root, problems)
        if root.find("ParameterValueDistribution") is not None:
            _distribution_problems(path, root, problems)
    else:
        _link_problems(path, root, problems)
    return problems


def validate_files(paths: list[Path], xsd: bool = True) -> list[Problem]:
    out: list[Problem] = []
    for p in paths:
        out.extend(validate_file(Path(p), xsd))
    return out


def format_problems(problems: list[Problem], fmt: str, files: list[Path]) -> str:
    if fmt == "json":
        return json.dumps(
            {"valid": not problems, "files": [str(f) for f in files], "problems": [asdict(p) for p in problems]},
            indent=2,
        )
    lines = [str(p) for p in problems]
    lines.append(f"{len(files)} file(s) checked: " + (f"{len(problems)} problem(s)" if problems else "valid"))
    return "\n".join(lines)
