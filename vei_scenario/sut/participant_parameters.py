"""The parameter values an OSMP participant is given for one run (or one variant of a sweep).

Any participant is given the entity's controller properties by the names it declares, with the
aliases of :data:`~vei_scenario.sut.fmu.PROPERTY_ALIASES` (a compiled scenario's ``cruiseSpeed`` is
the planner's ``cruise_speed_mps``, its ``riderType`` the rider's ``rider_type``); ``--controller-param``
goes over them (:meth:`~vei_scenario.sut.spec.ControllerSpec.instantiate`).

A participant vei built (``vei fmu build sfm cap --osmp``; its modelDescription carries the build's
record, :mod:`vei_scenario.fmu.osmp_parameters`) is given its declared parameters as the built-in
models get them in this run: from the scenario's closed loop resolved for the run's parameter values,
the same values its build would have fixed (the rider's ``time_shift_s`` from the TimeShift of its
track's timing, ``rider_type`` replay where the scenario does not activate the rider, ...). What it
holds fixed must be what this run would give it too; where the run's values change that (the ego's
Init speed, a track, a route) it is refused in one line naming the values that differ from the
build's, rather than run with the build's.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from vei_scenario.errors import VeiInputError
from vei_scenario.sut.contract import ControllerFault


@lru_cache(maxsize=8)
def _loop(scenario: str, stamp: int, values: tuple[tuple[str, str], ...]):
    """The scenario's closed loop as the participants carry it, for ``values`` (cached per file
    version: ``stamp``, its modification time, and values; a sweep's participants share one)."""
    from vei_scenario.fmu.osmp_rider import osmp_loop

    return osmp_loop(scenario, dict(values))


def participant_properties(ports, props: dict[str, str], ctx, label: str) -> dict[str, str]:
    """What the participant of ``ports`` (:class:`~vei_scenario.sut.osmp.OsmpPorts`) is given in the
    run of ``ctx``, from its entity's controller properties ``props`` (see the module's text)."""
    from vei_scenario.fmu.osmp_parameters import declared_values, fixed_digest
    from vei_scenario.sut.fmu import fmu_properties

    out = fmu_properties({k: v for k, v in props.items() if k})
    record = ports.record
    if record is None:
        return out
    name = ports.path.name
    if not ctx.path or not Path(str(ctx.path)).is_file():
        raise ControllerFault(label, f"{name} was built by vei from a scenario file; this run has none to check it by")
    scenario = Path(str(ctx.path))
    values = {k: str(v) for k, v in ctx.parameters.items()}
    try:
        loop = _loop(str(scenario.resolve()), scenario.stat().st_mtime_ns, tuple(sorted(values.items())))
    except VeiInputError as exc:
        raise ControllerFault(label, f"{name} was built by vei for a closed loop: {exc.reason}") from None
    if fixed_digest(record.model, loop) != record.digest:
        built = dict(record.parameters)
        changed = [k for k in values if k in built and values[k] != built[k]]
        if changed:
            run = ", ".join(f"{k}={values[k]}" for k in changed)
            then = ", ".join(f"{k}={built[k]}" for k in changed)
            fix = " ".join(f"--param {k}={values[k]}" for k in changed)
            raise ControllerFault(label, f"{name} was built for {then}; this run's {run} changes what it holds fixed "
                                  "(the ego's path, Init pose and speed; the rider's track, route and start): build it "
                                  f"for these values (vei fmu build {record.model} --osmp --scenario {scenario} "
                                  f"{fix})")  # fmt: skip
        raise ControllerFault(label, f"{name} was built from another scenario (what it holds fixed differs from "
                              f"{scenario.name}'s): build it from this one")  # fmt: skip
    out.update(declared_values(record.model, loop))
    return out
