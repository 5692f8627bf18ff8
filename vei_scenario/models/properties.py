"""Model parameters from OpenSCENARIO controller properties."""

from __future__ import annotations

from dataclasses import fields
from typing import TypeVar

T = TypeVar("T")


def from_properties(cls: type[T], props: dict[str, str]) -> T:
    """An instance of the parameter dataclass ``cls`` from property strings: known names are read as
    numbers, unknown ones (riderType, route, ...) ignored, missing ones defaulted."""
    names = {f.name for f in fields(cls)}
    return cls(**{k: float(v) for k, v in props.items() if k in names})
