"""Model parameters from OpenSCENARIO controller properties."""

from __future__ import annotations

import math
from dataclasses import fields
from typing import TypeVar

T = TypeVar("T")


#: Parameters that divide or bound the models: they must be above zero (the others at least zero).
POSITIVE = frozenset(
    {"mass_kg", "tau_s", "sigma_m", "repulsion_range_m", "max_speed_mps", "max_accel_mps2", "max_decel_mps2",
     "a_max_mps2", "horizon_s", "max_cruise_decel_mps2"}
)  # fmt: skip


def from_properties(cls: type[T], props: dict[str, str]) -> T:
    """An instance of the parameter dataclass ``cls`` from property strings: known names are read as
    numbers, unknown ones (riderType, route, ...) ignored, missing ones defaulted. A value that is not
    a finite number, is negative, or is zero where the model divides by it raises ValueError naming
    the property (the interpreter turns it into a one-line refusal with the line)."""
    names = {f.name for f in fields(cls)}
    values = {}
    for k, v in props.items():
        if k not in names:
            continue
        try:
            x = float(v)
        except (TypeError, ValueError):
            raise ValueError(f"property {k}={v!r} is not a number") from None
        if not math.isfinite(x) or x < 0 or (x == 0 and k in POSITIVE):
            bound = "above zero" if k in POSITIVE else "zero or more"
            raise ValueError(f"property {k}={v!r} must be a finite number {bound}")
        values[k] = x
    return cls(**values)
