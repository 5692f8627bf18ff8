"""``run_suite``: scenario expectations a CI system can gate on, with JUnit XML.

A suite (TOML) lists cases; each names a scenario (or a clip, compiled first), parameter values and
expectations on ``vei run`` metrics such as ``collision == false``, ``safety_index >= 0.9``,
``min_ttc_s >= 1.0``. Every case's files are validated, run and checked; a failed expectation is a
JUnit failure, a validation problem or a run error a JUnit error.

```toml
[defaults]
dt = 0.01

[[case]]
name = "planner avoids the aggressive rider"
scenario = "../../out/case_study/scenario.xosc"   # or: clip = "../case_study/clip.json"
parameters = { TimeShift = 2.2, RiderType = "aggressive", CapEnabled = true }
expect = ["collision == false", "safety_index >= 0.9"]
```
"""

from __future__ import annotations

import math
import operator
import re
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from vei_scenario.atomic_io import write_bytes_atomic
from vei_scenario.errors import VeiError, VeiInputError
from vei_scenario.metrics import METRICS
from vei_scenario.safe_xml import parse_xml

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

_EXPECT = re.compile(r"^\s*([A-Za-z_][\w.]*)\s*(==|!=|>=|<=|>|<)\s*(\S.*?)\s*$")
_ZONES = ("safe", "attention", "alert", "collision")
_OPS = {
    "==": operator.eq,
    "!=": operator.ne,
    ">=": operator.ge,
    "<=": operator.le,
    ">": operator.gt,
    "<": operator.lt,
}


@dataclass(frozen=True)
class Expectation:
    metric: str
    op: str
    value: object
    text: str

    def check(self, metrics: dict) -> tuple[bool, object]:
        if "." in self.metric:
            head, tail = self.metric.split(".", 1)
            actual = (metrics.get(head) or {}).get(tail)
        else:
            actual = metrics.get(self.metric)
        if actual is None or self.value is None:
            ok = (actual is None) == (self.value is None) if self.op in ("==", "!=") else False
            return (ok if self.op == "==" else not ok if self.op == "!=" else False), actual
        a, b = actual, self.value
        try:  # (only the one comparison asked for: a number and a boolean compare, a table does not)
            ok = _OPS[self.op](a, b)
        except TypeError:
            ok = False
        return bool(ok), actual


@dataclass
class Case:
    name: str
    scenario: Path | None
    clip: Path | None
    parameters: dict[str, str]
    expectations: list[Expectation]
    validate: bool = True
    #: the system under test on an entity (``controller = "Ego=aeb.py:AEB"``, a file relative to the suite)
    controllers: tuple = ()


@dataclass
class CaseResult:
    case: Case
    seconds: float
    failures: list[str] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)
    metrics: dict = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)  # checks that could not be made (said, not hidden)


#: Metrics whose value is a table or a list: an expectation names one of their fields.
TABLE_METRICS = frozenset({"ttc_zones_s", "collision_entities"})


def _value(text: str):
    t = text.strip().strip('"').strip("'")
    if t.lower() in ("true", "false"):
        return t.lower() == "true"
    if t.lower() in ("null", "none"):
        return None
    try:
        return float(t)
    except ValueError:
        return t


def _param_string(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    return str(v)


def load_suite(path: str | Path) -> tuple[list[Case], float]:
    path = Path(path)
    if not path.is_file():
        raise VeiInputError(path, "", "file not found")
    try:
        doc = tomllib.loads(path.read_text("utf-8"))
    except tomllib.TOMLDecodeError as exc:
        raise VeiInputError(path, "", f"malformed TOML: {exc}") from None
    except RecursionError:
        raise VeiInputError(path, "", "nested too deeply to read") from None
    except UnicodeDecodeError:
        raise VeiInputError(path, "", "not UTF-8 text") from None
    unknown = set(doc) - {"defaults", "case"}
    if unknown:
        raise VeiInputError(path, sorted(unknown)[0], "unknown table (expected [defaults] and [[case]])")
    defaults = doc.get("defaults", {})
    if not isinstance(defaults, dict):
        raise VeiInputError(path, "defaults", "must be a table ([defaults])")
    dt = defaults.get("dt", 0.01)
    if isinstance(dt, bool) or not isinstance(dt, (int, float)):
        raise VeiInputError(path, "defaults.dt", f"{dt!r} is not a number of seconds")
    from vei_scenario.checks import check_dt

    dt = check_dt(dt, "defaults.dt")
    unknown_defaults = set(defaults) - {"dt"}
    if unknown_defaults:
        raise VeiInputError(path, f"defaults.{sorted(unknown_defaults)[0]}", "unknown key (expected dt)")
    raw = doc.get("case")
    if not isinstance(raw, list) or not raw:
        raise VeiInputError(path, "case", "the suite has no [[case]] entries")
    cases = []
    for i, c in enumerate(raw):
        where = f"case[{i}]"
        if not isinstance(c, dict) or not isinstance(c.get("name"), str) or not c["name"].strip():
            raise VeiInputError(path, f"{where}.name", "every case needs a name")
        if any(ord(ch) < 32 or ord(ch) == 127 for ch in c["name"]) or len(c["name"]) > 200:
            raise VeiInputError(
                path, f"{where}.name", "a name of at most 200 printable characters (no control characters)"
            )
        for key in ("scenario", "clip"):
            if key in c and (not isinstance(c[key], str) or not c[key]):
                raise VeiInputError(path, f"{where}.{key}", "must be a file path (text)")
        extra = set(c) - {"name", "scenario", "clip", "parameters", "expect", "validate", "controller",
                          "controller_parameters"}  # fmt: skip
        if extra:
            raise VeiInputError(path, f"{where}.{sorted(extra)[0]}", "unknown key")
        if ("scenario" in c) == ("clip" in c):
            raise VeiInputError(path, where, "give exactly one of scenario or clip")
        params = c.get("parameters", {})
        if not isinstance(params, dict):
            raise VeiInputError(path, f"{where}.parameters", "must be a table")
        expects = c.get("expect")
        if not isinstance(expects, list) or not expects or not all(isinstance(e, str) for e in expects):
            raise VeiInputError(
                path, f"{where}.expect", "must be a non-empty list of strings like 'collision == false'"
            )
        parsed = []
        for j, e in enumerate(expects):
            m = _EXPECT.match(e)
            if not m:
                raise VeiInputError(path, f"{where}.expect[{j}]", f"{e!r} is not 'metric op value'")
            metric = m.group(1)
            head, _, tail = metric.partition(".")
            known = head in METRICS and (not tail or (head == "ttc_zones_s" and tail in _ZONES))
            if not known:
                raise VeiInputError(
                    path, f"{where}.expect[{j}]", f"unknown metric {metric!r} (known: {', '.join(METRICS)})"
                )
            value = _value(m.group(3))
            if head in TABLE_METRICS and not tail:
                fields = ", ".join(f"{head}.{z}" for z in _ZONES) if head == "ttc_zones_s" else "none"
                raise VeiInputError(
                    path, f"{where}.expect[{j}]", f"{metric!r} is a table, not a number; name a field ({fields})"
                )
            if m.group(2) not in ("==", "!=") and (isinstance(value, (bool, str)) or value is None):
                raise VeiInputError(
                    path, f"{where}.expect[{j}]", f"{e!r}: {m.group(2)} needs a number, not {m.group(3).strip()!r}"
                )
            if isinstance(value, str):
                raise VeiInputError(
                    path,
                    f"{where}.expect[{j}]",
                    f"{e!r}: the value {value!r} is not a number, true, false or null",
                )
            if isinstance(value, float) and not math.isfinite(value):
                raise VeiInputError(path, f"{where}.expect[{j}]", f"{e!r}: the value is not a finite number")
            parsed.append(Expectation(metric, m.group(2), value, e))
        base = path.parent
        controllers = _controllers(path, where, c, base)
        cases.append(
            Case(
                c["name"],
                base / c["scenario"] if "scenario" in c else None,
                base / c["clip"] if "clip" in c else None,
                {k: _param_string(v) for k, v in params.items()},
                parsed,
                bool(c.get("validate", True)),
                controllers,
            )
        )
    return cases, dt


def _controllers(path: Path, where: str, c: dict, base: Path) -> tuple:
    """A case's ``controller = "ENTITY=TARGET"`` (with ``controller_parameters``), loaded and checked."""
    from vei_scenario.sut import ControllerFault, ControllerSpec

    text, params = c.get("controller"), c.get("controller_parameters", {})
    if text is None:
        if params:
            raise VeiInputError(path, f"{where}.controller_parameters", "given without controller")
        return ()
    entity, sep, target = text.partition("=") if isinstance(text, str) else ("", "", "")
    if not sep or not entity.strip() or not target.strip():
        raise VeiInputError(path, f"{where}.controller", "must be 'ENTITY=FILE.py:CLASS' (or MODULE:CLASS, or a .fmu)")
    if not isinstance(params, dict):
        raise VeiInputError(path, f"{where}.controller_parameters", "must be a table")
    spec = ControllerSpec(entity.strip(), target.strip(), tuple((k, _param_string(v)) for k, v in params.items()),
                          base=str(base))  # fmt: skip
    try:
        spec.load()
    except ControllerFault as exc:
        raise VeiInputError(path, f"{where}.controller", str(exc)) from None
    return (spec,)


def _validate(scenario: Path, warnings: list[str]) -> list[str]:
    """Problems of the scenario and its road file; ``warnings`` learns of checks that were skipped."""
    from vei_scenario.openscenario.validation import validate_files

    files = [scenario]
    logic = parse_xml(scenario).find(".//LogicFile")
    if logic is not None and logic.get("filepath") and (scenario.parent / logic.get("filepath")).is_file():
        files.append(scenario.parent / logic.get("filepath"))
    try:
        problems = validate_files(files)
    except VeiInputError as exc:
        if "ASAM XSD" not in str(exc):
            raise
        problems = validate_files(files, xsd=False)  # no schemas installed: VEI rules only
        warnings.append(f"XSD validation skipped, VEI rules only: {exc}")
    return [str(p) for p in problems]


def run_case(case: Case, dt: float, workdir: Path) -> CaseResult:
    from vei_scenario.runner import run_to

    t0 = time.perf_counter()
    res = CaseResult(case, 0.0)
    try:
        scenario = case.scenario
        if case.clip is not None:
            from vei_scenario.compiler import compile_clip

            scenario = workdir / re.sub(r"\W+", "_", case.name) / "scenario.xosc"
            compile_clip(case.clip, scenario)
        if case.validate:
            res.errors += [f"validation: {p}" for p in _validate(scenario, res.warnings)]
        if not res.errors:
            report = run_to(scenario, None, case.parameters, dt, plots=False, controllers=case.controllers)
            res.metrics = report.metrics["metrics"]
            for e in case.expectations:
                ok, actual = e.check(res.metrics)
                if not ok:
                    res.failures.append(f"expected {e.text}, got {e.metric} = {actual}")
    except VeiError as exc:
        res.errors.append(str(exc))
    res.seconds = time.perf_counter() - t0
    return res


def junit_xml(suite: Path, results: list[CaseResult]) -> bytes:
    root = etree.Element("testsuites")
    ts = etree.SubElement(
        root,
        "testsuite",
        name=f"vei check {suite.name}",
        tests=str(len(results)),
        failures=str(sum(1 for r in results if r.failures and not r.errors)),
        errors=str(sum(1 for r in results if r.errors)),
        time=f"{sum(r.seconds for r in results):.3f}",
    )
    for r in results:
        tc = etree.SubElement(ts, "testcase", classname=suite.stem, name=r.case.name, time=f"{r.seconds:.3f}")
        if r.case.controllers:  # the system under test, by file and hash
            props = etree.SubElement(tc, "properties")
            for s in r.case.controllers:
                d = s.describe()
                etree.SubElement(props, "property", name=f"system_under_test.{d['entity']}",
                                 value=f"{d['controller']} sha256={d['sha256']}")  # fmt: skip
        if r.errors:
            etree.SubElement(tc, "error", message=r.errors[0]).text = "\n".join(r.errors)
        elif r.failures:
            etree.SubElement(tc, "failure", message=r.failures[0]).text = "\n".join(r.failures)
        if r.warnings:  # a CI reader sees what was not checked
            etree.SubElement(tc, "system-err").text = "\n".join(f"warning: {w}" for w in r.warnings)
        if r.metrics:
            shown = {k: v for k, v in r.metrics.items() if not isinstance(v, (dict, list))}
            etree.SubElement(tc, "system-out").text = ", ".join(
                f"{k}={'null' if v is None else v}"
                for k, v in shown.items()
                if not (isinstance(v, float) and math.isnan(v))
            )
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


def run_suite(path: str | Path, junit: str | Path | None = None) -> list[CaseResult]:
    path = Path(path)
    cases, dt = load_suite(path)
    with tempfile.TemporaryDirectory(prefix="vei-check-") as tmp:
        results = [run_case(c, dt, Path(tmp)) for c in cases]
    if junit is not None:
        write_bytes_atomic(Path(junit), junit_xml(path, results))
    return results
