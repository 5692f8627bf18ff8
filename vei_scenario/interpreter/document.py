"""Load an OpenSCENARIO scenario for execution: safe parsing and parameter resolution.

Every attribute holding ``$Name`` or ``${expression}`` is replaced by its value before the storyboard is
built, scope by scope (a ``ParameterDeclarations`` inside a Story or Maneuver adds to the scope of that
element). ``--param Name=Value`` overrides a top-level declaration; an unknown name or a value of the
wrong type is refused, as is any reference to an undeclared parameter, naming the line.

A file is read and checked once per process while its content stays the same (``_template``: a sweep
loads it once per variant); each load resolves a copy, visiting only the elements that need it and
checking again only the numbers its parameters gave (tests/test_scenario_template.py: the same XML as
resolving the whole file afresh).
"""

from __future__ import annotations

import copy
import functools
import math
import os
import re
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from vei_scenario.errors import VeiInputError
from vei_scenario.interpreter.expressions import ExpressionError, evaluate
from vei_scenario.openscenario.numeric_attributes import check_numbers
from vei_scenario.safe_xml import content_key, parse_xml

_REF = re.compile(r"^\$([A-Za-z_][A-Za-z0-9_]*)$")


@dataclass
class ScenarioDocument:
    path: Path
    root: etree._Element  # parameters resolved in place
    minor_version: int
    parameters: dict[str, str]  # top-level values after overrides
    parameter_types: dict[str, str]
    road_file: Path | None


def check_type(type_: str, value: str) -> str | None:
    """None when ``value`` is a valid literal of the OpenSCENARIO parameter type, else the reason."""
    try:
        if type_ == "double":
            if not math.isfinite(float(value)):
                return "is not a finite number"
        elif type_ in ("int", "integer", "unsignedInt", "unsignedShort"):
            n = int(value)
            if type_.startswith("unsigned") and n < 0:
                return "must not be negative"
            if abs(n) > INT_LIMITS.get(type_, 2**31):
                return f"is outside the range of an OpenSCENARIO {type_}"
        elif type_ == "boolean" and value not in ("true", "false"):
            return "must be true or false"
    except ValueError:
        return f"is not a valid {type_}"
    return None


def typed_value(type_: str, value: str) -> str | float | int | bool:
    """A parameter's text as the JSON value of its declared type (double a number, the integer types
    an integer, boolean true/false), so outputs a program reads keep the type the scenario declared;
    string, dateTime and any text its type does not parse stay text."""
    if check_type(type_, value) is not None:
        return value
    if type_ == "double":
        return float(value)
    if type_ in ("int", "integer", "unsignedInt", "unsignedShort"):
        return int(value)
    if type_ == "boolean":
        return value == "true"
    return value


#: Largest magnitude of the OpenSCENARIO integer types (xsd:int, xsd:unsignedInt, xsd:unsignedShort).
INT_LIMITS = {"int": 2**31, "integer": 2**31, "unsignedInt": 2**32 - 1, "unsignedShort": 2**16 - 1}


def check_values(types: dict[str, str], values: dict[str, str], where: str = "--param", file=None) -> None:
    """Refuse a value for an undeclared parameter or one that is not of its declared type."""
    for k, v in values.items():
        if k not in types:
            raise VeiInputError(
                file, where, f"unknown parameter {k!r} (declared: {', '.join(sorted(types)) or 'none'})"
            )
        problem = check_type(types[k], v)
        if problem:
            raise VeiInputError(file, where, f"{k}={v!r} {problem} ({types[k]} parameter)")


def _format_number(value: float) -> str:
    return repr(int(value)) if value.is_integer() and abs(value) < 1e15 else repr(value)


@functools.lru_cache(maxsize=4096)
def _reference(value: str) -> str | None:
    """The parameter name of a plain ``$name`` value, else None (a sweep resolves the same few
    attribute values for every variant)."""
    m = _REF.match(value)
    return m.group(1) if m else None


def resolve_value(path: Path, el, attr: str, value: str, scope: dict[str, str]) -> str:
    name = _reference(value)
    if name is not None:
        if name not in scope:
            raise VeiInputError(
                path, f"line {el.sourceline}", f'<{el.tag} {attr}="{value}">: parameter ${name} is not declared'
            )
        return scope[name]
    if value.startswith("${") and value.endswith("}"):
        try:
            result = evaluate(value[2:-1], scope)
        except ExpressionError as exc:
            raise VeiInputError(path, f"line {el.sourceline}", f'<{el.tag} {attr}="{value}">: {exc}') from None
        if not math.isfinite(result):
            raise VeiInputError(
                path, f"line {el.sourceline}", f'<{el.tag} {attr}="{value}">: the result {result} is not finite'
            )
        return _format_number(result)
    return value


def _declare(path: Path, decls, scope: dict[str, str], types: dict[str, str]) -> None:
    for d in decls.iterfind("ParameterDeclaration"):
        # a leading "$" in the declared name is the reference syntax, not part of the name (esmini agrees)
        name, type_ = (d.get("name") or "").removeprefix("$"), d.get("parameterType", "string")
        if not name:
            raise VeiInputError(path, f"line {d.sourceline}", "ParameterDeclaration without a name")
        value = resolve_value(path, d, "value", d.get("value", ""), scope)
        problem = check_type(type_, value)
        if problem:
            raise VeiInputError(path, f"line {d.sourceline}", f"parameter {name} = {value!r} {problem}")
        scope[name] = value
        types[name] = type_


def redeclare(path: Path, decls, fixed: dict[str, str]) -> tuple[dict[str, str], dict[str, str]]:
    """The values and types of the top-level declarations ``decls`` with those named in ``fixed``
    given: the others evaluated in order, so a parameter derived from a fixed one follows it."""
    scope: dict[str, str] = {}
    types: dict[str, str] = {}
    for d in decls.iterfind("ParameterDeclaration"):
        name = (d.get("name") or "").removeprefix("$")
        value = fixed[name] if name in fixed else resolve_value(path, d, "value", d.get("value", ""), scope)
        scope[name], types[name] = value, d.get("parameterType", "string")
    return scope, types


def derived_parameters(path: str | Path) -> tuple[object, set[str]]:
    """The raw top-level ParameterDeclarations of a scenario and the names whose value refers to
    other parameters (``$name`` or ``${...}``): those a variant must evaluate again."""
    root = parse_xml(Path(path)).getroot()
    top = root.find("ParameterDeclarations")
    if top is None:
        return None, set()
    derived = {
        (d.get("name") or "").removeprefix("$")
        for d in top.iterfind("ParameterDeclaration")
        if "$" in (d.get("value") or "")
    }
    return top, derived


#: Attribute vei sets on an element copied from a catalog: the file it came from (for error messages).
SOURCE_FILE = "{urn:vei-scenario}source"
#: Catalog entries referencing catalog entries: deeper than this is refused (a cycle is named earlier).
MAX_CATALOG_DEPTH = 32


def source_of(el, default):
    """The file an element was read from: the catalog file for an element copied from a catalog."""
    node = el
    while node is not None:
        src = node.get(SOURCE_FILE) if isinstance(node.tag, str) else None
        if src:
            return Path(src)
        node = node.getparent()
    return default


class Catalogs:
    """Catalog entries by (catalog name, entry name), read lazily from the scenario's
    ``CatalogLocations`` directories (every ``.xosc`` file in them).

    A reference whose catalog name matches no ``<Catalog name>`` is looked up, as esmini does, by its
    entry name in the directories of the location of that name (``<EnvironmentCatalog>`` for
    ``catalogName="EnvironmentCatalog"``), then among all entries if only one has that name."""

    def __init__(self, path: Path, root) -> None:
        self.path = path
        self.dirs = [
            (d.getparent().tag, _directory(str(path.parent), d.get("path")))
            for d in root.iterfind("CatalogLocations/*/Directory")
            if d.get("path") and not d.get("path").startswith("$")
        ]
        self._entries: dict[tuple[str, str], object] | None = None
        self._by_location: dict[tuple[str, str], object] = {}
        self._by_name: dict[str, list] = {}
        self._files: dict[int, Path] = {}  # id(entry element) -> the catalog file it is in
        #: the entries being resolved, outermost first: a reference back to one of them is a cycle
        self.active: list[tuple[Path, str]] = []

    def file_of(self, entry) -> Path:
        return self._files.get(id(entry), self.path)

    def _load(self) -> None:
        files = tuple((location, f, content_key(f)) for location, d in self.dirs for f in _catalog_files(d))
        self._entries, self._by_location, self._by_name, self._files = _catalog_index(files)

    def entry(self, ref):
        if self._entries is None:
            self._load()
        catalog, name = ref.get("catalogName"), ref.get("entryName")
        found = self._entries.get((catalog, name))
        if found is None:
            found = self._by_location.get((catalog, name))
        if found is None and len(self._by_name.get(name, [])) == 1:
            found = self._by_name[name][0]
        if found is None:
            where = ", ".join(str(d) for _, d in self.dirs) or "no CatalogLocations"
            raise VeiInputError(
                self.path, f"line {ref.sourceline}", f"catalog entry {catalog}/{name} not found ({where})"
            )
        return found


def _catalog_files(directory: Path) -> tuple[Path, ...]:
    """The ``.xosc`` files in a catalog directory, sorted (none when it is not a directory); listed
    again whenever the directory changes (a file added, removed or renamed changes its times)."""
    try:
        st = os.stat(directory)
    except OSError:
        return ()
    return _listing(str(directory), st.st_ino, st.st_mtime_ns, st.st_ctime_ns)


@functools.lru_cache(maxsize=256)
def _listing(directory: str, inode: int, mtime_ns: int, ctime_ns: int) -> tuple[Path, ...]:
    d = Path(directory)
    if not d.is_dir():
        return ()
    return tuple(sorted(d / n for n in os.listdir(d) if n.endswith(".xosc")))


@functools.lru_cache(maxsize=64)
def _road_network_problem(path: str, key: bytes) -> str | None:
    """Why the LogicFile is no OpenDRIVE road network (its first element alone is read, once per
    content); None when it is one. Why: a file that is not a road (a stray path, another format)
    must be refused before the run, not found out by a plot or a lane lookup afterwards."""
    from vei_scenario.safe_xml import SAFE_OPTIONS

    try:
        for _event, el in etree.iterparse(path, events=("start",), **SAFE_OPTIONS):
            tag = el.tag if isinstance(el.tag, str) else ""
            return None if tag == "OpenDRIVE" else f"is not an OpenDRIVE file (its root element is <{tag}>)"
    except etree.XMLSyntaxError as exc:
        return f"is not an OpenDRIVE file (malformed XML, line {exc.lineno or 0}: {exc.msg})"
    except OSError as exc:
        return f"cannot be read ({exc.strerror or exc})"
    return "is empty"


@functools.lru_cache(maxsize=256)
def _directory(parent: str, path: str) -> Path:
    """A CatalogLocations directory, resolved once per process (a sweep names the same ones for
    every variant)."""
    return (Path(parent) / path).resolve()


@functools.lru_cache(maxsize=16)
def _catalog_index(files: tuple) -> tuple[dict, dict, dict, dict]:
    """The entries of the catalog ``files`` ((location, file, content key) each, in the order they
    are searched) by (catalog, name), by (location, name) and by name, and the file of each: built
    once per process while the files stay as they were. Only read (entries are copied where used)."""
    entries: dict = {}
    by_location: dict = {}
    by_name: dict = {}
    files_of: dict = {}
    for location, f, key in files:
        for cat in _catalog_tree(str(f), key).getroot().iterfind("Catalog"):
            for item in cat:
                if isinstance(item.tag, str) and item.get("name"):
                    name = item.get("name")
                    entries.setdefault((cat.get("name"), name), item)
                    by_location.setdefault((location, name), item)
                    by_name.setdefault(name, []).append(item)
                    files_of[id(item)] = f
    return entries, by_location, by_name, files_of


def catalog_file(path: Path):
    """A catalog file's tree, parsed once per process while the file stays as it was (a sweep loads
    the same catalogs for every variant; their entries are only read, and copied where used)."""
    return _catalog_tree(str(path), content_key(path))


@functools.lru_cache(maxsize=64)
def _catalog_tree(path: str, key: bytes):
    return parse_xml(path)


def _resolve_catalog_reference(path: Path, ref, scope: dict[str, str], catalogs: Catalogs) -> None:
    """Replace ``<CatalogReference>`` by a copy of its entry, the entry's parameters set by the
    reference's ``ParameterAssignments`` (resolved in the scenario's scope)."""
    for attr in ("catalogName", "entryName"):
        if "$" in (ref.get(attr) or ""):
            ref.set(attr, resolve_value(path, ref, attr, ref.get(attr), scope))
    source = catalogs.entry(ref)
    file = catalogs.file_of(source)
    key = (file, source.get("name"))
    if key in catalogs.active:
        chain = " -> ".join(f"{f.name}:{n}" for f, n in catalogs.active[catalogs.active.index(key) :] + [key])
        raise VeiInputError(path, f"line {ref.sourceline}", f"catalog references form a cycle: {chain}")
    if len(catalogs.active) >= MAX_CATALOG_DEPTH:
        raise VeiInputError(path, f"line {ref.sourceline}", f"catalog references nest deeper than {MAX_CATALOG_DEPTH}")
    assigned = {}
    for a in ref.iterfind("ParameterAssignments/ParameterAssignment"):
        assigned[a.get("parameterRef", "").lstrip("$")] = resolve_value(path, a, "value", a.get("value", ""), scope)
    local: dict[str, str] = {}
    decls = source.find("ParameterDeclarations")
    if decls is not None:
        for d in decls.iterfind("ParameterDeclaration"):
            name = d.get("name")
            local[name] = (
                assigned[name] if name in assigned else resolve_value(file, d, "value", d.get("value", ""), local)
            )
    unknown = set(assigned) - set(local)
    if unknown:
        raise VeiInputError(
            path, f"line {ref.sourceline}", f"catalog entry has no parameter(s) {', '.join(sorted(unknown))}"
        )
    merged = {**scope, **local}
    named = _names_in(source)  # (None: it refers to other entries, whose parameters it passes on)
    memo = None if named is None else (source, tuple((n, merged.get(n)) for n in named))
    entry = _RESOLVED.get(memo) if memo is not None else None
    if entry is not None:
        ref.getparent().replace(ref, copy.deepcopy(entry))
        return
    entry = copy.deepcopy(source)
    entry.set(SOURCE_FILE, str(file))  # errors inside the entry name the catalog file, not the scenario
    if decls is not None:
        entry.remove(entry.find("ParameterDeclarations"))
    catalogs.active.append(key)
    try:
        _substitute(file, entry, merged, {}, catalogs)
        check_numbers(file, entry)
    finally:
        catalogs.active.pop()
    if memo is not None:
        if len(_RESOLVED) >= 4096:
            _RESOLVED.clear()
        _RESOLVED[memo] = copy.deepcopy(entry)
    ref.getparent().replace(ref, entry)


#: Catalog entries resolved, per process: (entry, the values of the parameters its text names) -> the
#: entry with them substituted and checked. A sweep resolves the same entries with the same values for
#: most variants; the entries are those of the cached catalog index, kept while their files are.
_RESOLVED: dict[tuple, object] = {}
_NAMES: dict[object, tuple[str, ...] | None] = {}
_UNREAD = object()
#: A parameter named in an attribute value: ``$name`` alone or inside ``${...}`` (the expressions' names).
_NAMED = re.compile(r"\$([A-Za-z_][A-Za-z0-9_]*)")


def _names_in(source) -> tuple[str, ...] | None:
    """The parameters the attribute values of catalog entry ``source`` name (the ones its resolution
    reads), sorted, or None when it holds a CatalogReference (resolving it reads whatever the
    referenced entries name)."""
    found = _NAMES.get(source, _UNREAD)
    if found is _UNREAD:
        if source.find(".//CatalogReference") is not None:
            found = None
        else:
            found = tuple(sorted({n for el in source.iter() for v in el.attrib.values() for n in _NAMED.findall(v)}))
        if len(_NAMES) >= 4096:
            _NAMES.clear()
        _NAMES[source] = found
    return found


def _substitute(
    path: Path,
    el,
    scope: dict[str, str],
    types: dict[str, str],
    catalogs: Catalogs | None = None,
    visit: set | None = None,
    changed: list | None = None,
) -> None:
    """Resolve the parameters of ``el`` and below in place (catalog references replaced by their
    entries); ``visit``: the only elements below it that need it (None: all); ``changed``: collects
    the elements whose attributes were set, in document order."""
    if el.tag == "CatalogReference" and catalogs is not None and el.getparent().tag != "Catalog":
        _resolve_catalog_reference(path, el, scope, catalogs)
        return
    local = el.find("ParameterDeclarations")
    if local is not None and el.tag != "OpenSCENARIO":
        scope = dict(scope)
        _declare(path, local, scope, dict(types))
    touched = False
    for attr, value in el.attrib.items():
        if "$" in value and not (el.tag == "ParameterDeclaration" and attr == "name"):
            try:
                el.set(attr, resolve_value(path, el, attr, value, scope))
                touched = True
            except VeiInputError:
                if attr != "name":  # a name is only an identifier: esmini's string expressions may stay
                    raise
    if touched and changed is not None:
        changed.append(el)
    for child in list(el):
        if (visit is None or child in visit) and isinstance(child.tag, str) and child.tag != "ParameterDeclarations":
            _substitute(path, child, scope, types, catalogs, visit, changed)


@dataclass(frozen=True)
class _Template:
    """A scenario file as read and checked before its parameters are resolved: what every load of
    the unchanged file starts from (a sweep loads the same file once per variant). Never changed
    after it is built; a load resolves a copy of ``root``."""

    root: etree._Element  # comments and processing instructions stripped
    minor_version: int
    scope: dict[str, str]  # the top-level parameters with their declared values, and their types
    types: dict[str, str]
    needs: frozenset[int]  # elements (by document order) that hold a parameter, a catalog reference
    # or declarations of their own, or have such an element below them: the only ones resolving visits
    numbers_ok: bool  # every number written out (not a parameter) passed check_numbers


@functools.lru_cache(maxsize=16)
def _template(path: str, key: bytes) -> _Template:
    """The template of the file at ``path``, read once per process while it holds ``key``'s content."""
    return _read_template(Path(path), parse_xml(path))


def _read_template(path: Path, tree) -> _Template:
    """Check the file's root, header and top-level declarations (in the order a load refuses them)
    and note what resolving its parameters will visit."""
    if tree.docinfo.internalDTD is not None:
        raise VeiInputError(path, "line 1", "DTDs are not accepted in OpenSCENARIO files")
    root = tree.getroot()
    # Comments and processing instructions may stand anywhere; the interpreter reads elements only.
    etree.strip_elements(root, etree.Comment, etree.ProcessingInstruction, with_tail=False)
    if root.tag != "OpenSCENARIO":
        raise VeiInputError(path, f"line {root.sourceline}", f"root element <{root.tag}> is not <OpenSCENARIO>")
    header = root.find("FileHeader")
    try:
        major, minor = int(header.get("revMajor")), int(header.get("revMinor"))
    except (AttributeError, TypeError, ValueError):
        raise VeiInputError(path, f"line {root.sourceline}", "FileHeader without numeric revMajor/revMinor") from None
    if major != 1 or minor > 3:
        raise VeiInputError(
            path, f"line {header.sourceline}", f"OpenSCENARIO {major}.{minor} is not supported (1.0-1.3)"
        )
    if root.find("Storyboard") is None:
        kind = (
            "a ParameterValueDistribution" if root.find("ParameterValueDistribution") is not None else "not a scenario"
        )
        raise VeiInputError(path, f"line {root.sourceline}", f"{kind}: no <Storyboard> to run")
    scope: dict[str, str] = {}
    types: dict[str, str] = {}
    top = root.find("ParameterDeclarations")
    if top is not None:
        _declare(path, top, scope, types)
    order = {el: i for i, el in enumerate(root.iter())}
    # (found by lxml's own search, not element by element in Python: a third of the time on big files)
    marked = [*root.xpath("descendant-or-self::*[@*[contains(., '$')]]"), *root.iter("CatalogReference")]
    marked += (p for d in root.iter("ParameterDeclarations") if (p := d.getparent()) is not root)
    needs: set[int] = set()
    for el in marked:  # each with the elements above it
        while el is not None and order[el] not in needs:
            needs.add(order[el])
            el = el.getparent()
    try:
        check_numbers(path, root, references=False)
        numbers_ok = True
    except VeiInputError:  # (a load checks the whole file again and refuses it there, in order)
        numbers_ok = False
    return _Template(root, minor, scope, types, frozenset(needs), numbers_ok)


def parameter_text(value: object) -> str:
    """A parameter value as OpenSCENARIO writes it: Python booleans as true/false, numbers by repr (so
    ``run_scenario(p, {"CapEnabled": True, "TimeShift": 1.5})`` means what it says)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    return value if isinstance(value, str) else str(value)


def load_scenario(
    path: str | Path, overrides: dict[str, object] | None = None, tree: etree._ElementTree | None = None
) -> ScenarioDocument:
    """The scenario at ``path`` with parameters (``overrides`` over the declared values), catalogs
    and expressions resolved in place; ``tree``: the file already parsed (it is changed)."""
    path = Path(path)
    if tree is None:  # (a copy of the file as read once: the file's own text is parsed once per process)
        template = _template(str(path), content_key(path))
        root = copy.deepcopy(template.root)
    else:
        template = _read_template(path, tree)
        root = template.root
    minor = template.minor_version
    scope, types = dict(template.scope), dict(template.types)
    top = root.find("ParameterDeclarations")
    overrides = {name: parameter_text(value) for name, value in (overrides or {}).items()}
    check_values(types, overrides, "--param", path)
    scope.update(overrides)
    if overrides:  # later declarations may depend on overridden ones: re-declare in order
        scope, types = redeclare(path, top, overrides)
    elements = list(root.iter())
    visit = {elements[i] for i in template.needs}
    changed: list = []
    _substitute(path, root, scope, types, Catalogs(path, root), visit, changed)
    # every number the XSD types as one: finite, integral, in range (those written out in the file
    # were checked when it was read; catalog entries are checked as they are resolved)
    check_numbers(path, root, changed if template.numbers_ok else None)

    road_file = None
    logic = root.find("RoadNetwork/LogicFile")
    if logic is not None and logic.get("filepath"):
        road_file = _directory(str(path.parent), logic.get("filepath"))
        if not road_file.is_file():
            raise VeiInputError(path, f"line {logic.sourceline}", f"road network {logic.get('filepath')!r} not found")
        problem = _road_network_problem(str(road_file), content_key(road_file))
        if problem:
            raise VeiInputError(path, f"line {logic.sourceline}", f"road network {logic.get('filepath')!r} {problem}")
    return ScenarioDocument(path, root, minor, scope, types, road_file)
