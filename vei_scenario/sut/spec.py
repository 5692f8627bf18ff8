"""Which controller drives which entity: ``ENTITY=path/file.py:Class``, ``ENTITY=package.module:Class``
or ``ENTITY=NAME`` (an entry point of the group ``vei.controllers``), and loading it.

A :class:`ControllerSpec` is plain text (picklable: a worker process or a Dask worker loads the class
itself) and names its code by file and SHA-256, so every output can say what was tested and every
printed command can reproduce it. Loading refuses, before anything runs, a file that does not exist,
code that does not import, a missing class and a class without ``step``: one line each.
"""

from __future__ import annotations

import hashlib
import importlib
import importlib.util
import shlex
import sys
from dataclasses import dataclass, field
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.sut.contract import ControllerFault

#: The entry-point group a package registers its controllers in (``NAME = "package.module:Class"``).
ENTRY_POINT_GROUP = "vei.controllers"


@dataclass(frozen=True)
class ControllerSpec:
    """``entity`` driven by ``target`` (as the user wrote it); ``parameters``: extra properties
    (``--controller-param``) given to its constructor over the scenario's."""

    entity: str
    target: str
    parameters: tuple[tuple[str, str], ...] = ()
    #: the directory a relative file is found from (the scenario's, for a scenario's ``module`` property)
    base: str = ""
    #: the longest one ``step`` call may take (s, wall clock), or None: a hanging controller then fails
    #: its run with one line instead of holding up a sweep
    step_timeout_s: float | None = None
    _loaded: dict = field(default_factory=dict, compare=False, hash=False, repr=False)

    def __reduce__(self):
        """Pickled as its text: a worker process loads the class itself."""
        return (type(self), (self.entity, self.target, self.parameters, self.base, self.step_timeout_s))

    @property
    def label(self) -> str:
        """How messages name it: ``Ego=aeb.py:AEB``."""
        return f"{self.entity}={self.target}"

    @property
    def kind(self) -> str:
        """``fmu`` for an FMI co-simulation FMU (``.fmu``), else ``python``."""
        return "fmu" if self.target.lower().endswith(".fmu") else "python"

    def _fmu_path(self) -> Path:
        path = Path(self.target)
        return Path(self.base) / path if not path.is_absolute() and self.base else path

    def _file_and_class(self) -> tuple[Path | None, str, str]:
        """(file or None, module or entry point, class name) of the target."""
        where, sep, cls = self.target.rpartition(":")
        if not sep:
            return None, self.target, ""
        if where.endswith(".py") or "/" in where or "\\" in where:
            path = Path(where)
            if not path.is_absolute() and self.base:
                path = Path(self.base) / path
            return path, where, cls
        return None, where, cls

    def load(self) -> type:
        """The user's class (loaded once per process), checked to have a ``step`` method; for an FMU
        its ports (:class:`~vei_scenario.sut.fmu.FmuPorts`), checked against what vei provides."""
        if "class" not in self._loaded:
            if self.kind == "fmu":
                from vei_scenario.sut.fmu import check_parameters, read_ports
                from vei_scenario.sut.osmp import is_osmp, read_osmp_ports

                path = self._fmu_path()
                ports = read_osmp_ports(path, self.label) if is_osmp(path) else read_ports(path, self.label)
                check_parameters(ports, dict(self.parameters), self.label)
                self._loaded["class"], self._loaded["file"] = ports, ports.path
            else:
                self._loaded["class"], self._loaded["file"] = _load(self)
        return self._loaded["class"]

    def instantiate(self, label: str, properties: dict[str, str]):
        """A fresh instance for one run, constructed with ``properties`` (the spec's parameters over
        them): the user's class, or the FMU behind the same contract."""
        loaded = self.load()
        properties = {**properties, **dict(self.parameters)}
        if self.kind == "fmu":
            from vei_scenario.sut.isolated import IsolatedFmu
            from vei_scenario.sut.osmp import OsmpParticipant, OsmpPorts

            if isinstance(loaded, OsmpPorts):  # its messages are passed by address: it runs in this process
                return OsmpParticipant(loaded, label, properties)
            return IsolatedFmu(loaded, label, properties, self.step_timeout_s)
        try:
            return loaded(**properties)
        except Exception as exc:  # noqa: BLE001 (the user's code: any failure is theirs, said in one line)
            raise ControllerFault(label, f"constructing {loaded.__name__} raised {describe_exception(exc)}") from None

    @property
    def osmp(self) -> bool:
        """Whether it is an OSMP traffic participant (an FMU with OSMP's annotations): it moves its
        entity itself, from the ``osi3.TrafficUpdate`` it returns."""
        from vei_scenario.sut.osmp import OsmpPorts

        return self.kind == "fmu" and isinstance(self.load(), OsmpPorts)

    @property
    def file(self) -> Path | None:
        """The file the class is defined in (after :meth:`load`)."""
        self.load()
        return self._loaded["file"]

    def sha256(self) -> str:
        """SHA-256 of the file that holds the class (the module's file for a module)."""
        if "sha256" not in self._loaded:
            f = self.file
            self._loaded["sha256"] = hashlib.sha256(f.read_bytes()).hexdigest() if f is not None else ""
        return self._loaded["sha256"]

    def describe(self) -> dict:
        """The system under test as outputs name it."""
        f = self.file
        return {
            "entity": self.entity,
            "controller": self.target,
            "file": str(f) if f is not None else None,
            "sha256": self.sha256() or None,
            "parameters": dict(self.parameters),
            **({"step_timeout_s": self.step_timeout_s} if self.step_timeout_s is not None else {}),
        }


def _load(spec: ControllerSpec) -> tuple[type, Path | None]:
    path, where, cls_name = spec._file_and_class()
    label = spec.label
    if path is not None:
        if not path.is_file():
            raise ControllerFault(label, f"{path}: no such file")
        digest = hashlib.sha256(path.read_bytes()).hexdigest()
        name = f"vei_sut_{digest[:16]}"
        module = sys.modules.get(name)
        if module is None:
            loader_spec = importlib.util.spec_from_file_location(name, path)
            if loader_spec is None or loader_spec.loader is None:
                raise ControllerFault(label, f"{path}: not a Python file")
            module = importlib.util.module_from_spec(loader_spec)
            sys.path.insert(0, str(path.resolve().parent))  # (its own helper modules beside it)
            try:
                loader_spec.loader.exec_module(module)
            except Exception as exc:  # noqa: BLE001 (the user's code: any failure is theirs, said in one line)
                raise ControllerFault(label, f"importing {path} raised {describe_exception(exc)}") from None
            finally:
                sys.path.remove(str(path.resolve().parent))
            sys.modules[name] = module
        source = path
    elif cls_name:
        try:
            module = importlib.import_module(where)
        except ModuleNotFoundError as exc:
            raise ControllerFault(label, f"no module {exc.name!r} (a file needs .py or a /)") from None
        except Exception as exc:  # noqa: BLE001
            raise ControllerFault(label, f"importing {where} raised {describe_exception(exc)}") from None
        source = Path(module.__file__) if getattr(module, "__file__", None) else None
    else:
        from importlib.metadata import entry_points

        found = [ep for ep in entry_points(group=ENTRY_POINT_GROUP) if ep.name == where]
        if not found:
            raise ControllerFault(
                label, f"{where!r} is no FILE.py:CLASS, MODULE:CLASS or entry point of the group {ENTRY_POINT_GROUP}"
            )
        try:
            cls = found[0].load()
        except Exception as exc:  # noqa: BLE001
            raise ControllerFault(label, f"loading entry point {where} raised {describe_exception(exc)}") from None
        module = sys.modules.get(getattr(cls, "__module__", ""), None)
        source = Path(module.__file__) if module is not None and getattr(module, "__file__", None) else None
        return _checked(cls, label), source
    cls = getattr(module, cls_name, None)
    if cls is None:
        have = sorted(n for n, v in vars(module).items() if isinstance(v, type) and v.__module__ == module.__name__)
        raise ControllerFault(label, f"{where} has no class {cls_name!r} (it has: {', '.join(have) or 'none'})")
    return _checked(cls, label), source


def _checked(cls: object, label: str) -> type:
    if not isinstance(cls, type):
        raise ControllerFault(label, f"{getattr(cls, '__name__', cls)!r} is not a class")
    if not callable(getattr(cls, "step", None)):
        raise ControllerFault(label, f"class {cls.__name__} has no step(obs) method")
    return cls


def describe_exception(exc: BaseException) -> str:
    """``Type: message`` on one line, with the line of a syntax error."""
    text = " ".join(str(exc).split())
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def parse_controller_options(
    controllers: list[str], parameters: list[str] | None = None, step_timeout_s: float | None = None
) -> tuple[ControllerSpec, ...]:
    """``--controller ENTITY=TARGET``, ``--controller-param NAME=VALUE`` and ``--controller-timeout S``
    options into specs, each loaded and checked at once (before any run)."""
    if step_timeout_s is not None:
        from vei_scenario.checks import finite

        step_timeout_s = finite(step_timeout_s, "--controller-timeout", 1e-3, 1e6)
    params: list[tuple[str, str]] = []
    for item in parameters or []:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise VeiInputError(None, "--controller-param", f"{item!r} is not NAME=VALUE")
        params.append((name.strip(), value.strip()))
    if params and not controllers:
        raise VeiInputError(None, "--controller-param", "given without --controller")
    specs, seen = [], set()
    for item in controllers:
        entity, sep, target = item.partition("=")
        if not sep or not entity.strip() or not target.strip():
            raise VeiInputError(None, "--controller", f"{item!r} is not ENTITY=FILE.py:CLASS or ENTITY=MODULE:CLASS")
        if entity.strip() in seen:
            raise VeiInputError(None, "--controller", f"two controllers for {entity.strip()}")
        seen.add(entity.strip())
        spec = ControllerSpec(entity.strip(), target.strip(), tuple(params), step_timeout_s=step_timeout_s)
        spec.load()
        specs.append(spec)
    return tuple(specs)


def reproduce_options(described: list[dict]) -> str:
    """The command-line options that plug the systems under test in again (:func:`sut_document`'s
    entries; empty without any), with a leading space."""
    out = [f"--controller {shlex.quote(d['entity'] + '=' + d['controller'])}" for d in described]
    if described:
        out += [f"--controller-param {shlex.quote(f'{k}={v}')}" for k, v in described[0]["parameters"].items()]
        if described[0].get("step_timeout_s") is not None:
            out.append(f"--controller-timeout {described[0]['step_timeout_s']:g}")
    return (" " + " ".join(out)) if out else ""


def sut_document(specs: tuple[ControllerSpec, ...]) -> list[dict]:
    """The systems under test as outputs name them (file and hash)."""
    return [s.describe() for s in specs]
