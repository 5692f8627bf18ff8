"""The parameter values an OSMP participant is given for one run (or one variant of a sweep).

Any participant is given the entity's controller properties by the names it declares, with the
aliases of :data:`~vei_scenario.sut.fmu.PROPERTY_ALIASES` (a compiled scenario's ``cruiseSpeed`` is
the planner's ``cruise_speed_mps``, its ``riderType`` the rider's ``rider_type``); ``--controller-param``
goes over them (:meth:`~vei_scenario.sut.spec.ControllerSpec.instantiate`).

A participant whose modelDescription carries a build record (:class:`~vei_scenario.sut.osmp.BuildRecord`:
vei's ``vei fmu build sfm cap --osmp`` writes one) names the function that gives its declared
parameters for a run, ``MODULE:FUNCTION``, loaded by name as ``--controller MODULE:CLASS`` is (vei's:
:func:`vei_scenario.fmu.osmp_parameters.run_values`, which resolves the scenario's closed loop for the
run, the built-in models' values, and refuses a run that would change what the participant holds
fixed). Only functions of vei_scenario are loaded so.
"""

from __future__ import annotations

import importlib
from pathlib import Path

from vei_scenario.sut.contract import ControllerFault


def participant_properties(ports, props: dict[str, str], ctx, label: str) -> dict[str, str]:
    """What the participant of ``ports`` (:class:`~vei_scenario.sut.osmp.OsmpPorts`) is given in the
    run of ``ctx``, from its entity's controller properties ``props`` (see the module's text)."""
    from vei_scenario.sut.fmu import fmu_properties

    out = fmu_properties({k: v for k, v in props.items() if k})
    record = ports.record
    module, _, function = (record.resolver if record is not None else "").partition(":")
    if not module.startswith("vei_scenario.") or not function:
        return out
    name = ports.path.name
    if not ctx.path or not Path(str(ctx.path)).is_file():
        raise ControllerFault(label, f"{name} was built by vei from a scenario file; this run has none to check it by")
    try:
        resolve = getattr(importlib.import_module(module), function)
    except (ImportError, AttributeError):
        why = f"{name} names {record.resolver} for its parameters, which this vei has not"
        raise ControllerFault(label, why) from None
    values = {k: str(v) for k, v in ctx.parameters.items()}
    out.update(resolve(name, record, Path(str(ctx.path)), values, label))
    return out
