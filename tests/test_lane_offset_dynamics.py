"""LaneOffsetAction's timing, as esmini 3.6 shapes it (measured there, and compared with it here when
esmini is beside the checkout): the transition takes the time at which its shape's lateral
acceleration peaks at maxLateralAcc; a linear one, whose acceleration has no peak to speak of, takes
the cubic's time; without maxLateralAcc, 0.5 m/s²."""

from __future__ import annotations

import math

import numpy as np
import pytest
from test_performance_limits import DT, _agrees_with_esmini, _event, _object, _scenario

from vei_scenario.interpreter import run_scenario


def _offset(value: float, shape: str, max_acc: float | None) -> str:
    acc = f'maxLateralAcc="{max_acc}" ' if max_acc is not None else ""
    return (
        '<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics '
        f'{acc}dynamicsShape="{shape}"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="{value}"/>'
        "</LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"
    )


def _moving_time(tmp_path, action: str) -> tuple[float, object]:
    path = _scenario(tmp_path, _object("A"), {"A": (20.0, 10.0, "")}, _event("o", "A", action, 1.0), 8.0)
    a = run_scenario(path, {}, DT).traces["A"]
    moving = a.t[1:][np.abs(np.diff(a.y)) > 1e-9]
    return moving[-1] - moving[0] + DT, path


@pytest.mark.parametrize(
    "shape, max_acc, seconds",
    [
        ("linear", 0.5, math.sqrt(6 * 1.0 / 0.5)),
        ("cubic", None, math.sqrt(6 * 1.0 / 0.5)),
        ("sinusoidal", None, math.pi * math.sqrt(1.0 / (2 * 0.5))),
        ("sinusoidal", 2.0, math.pi * math.sqrt(1.0 / (2 * 2.0))),
    ],
)
def test_a_lane_offset_takes_the_time_its_lateral_acceleration_allows(
    tmp_path, esmini_if_here, shape, max_acc, seconds
):
    took, path = _moving_time(tmp_path, _offset(1.0, shape, max_acc))
    assert took == pytest.approx(seconds, abs=2 * DT)
    _agrees_with_esmini(esmini_if_here, path, 0.01)


def test_a_linear_lane_offset_moves_across_at_one_speed(tmp_path):
    path = _scenario(
        tmp_path, _object("A"), {"A": (20.0, 10.0, "")}, _event("o", "A", _offset(1.0, "linear", 0.5), 1.0), 8.0
    )
    a = run_scenario(path, {}, DT).traces["A"]
    vy = np.diff(a.y) / DT
    across = vy[np.abs(vy) > 1e-6]
    assert across[1:-1] == pytest.approx(1.0 / math.sqrt(12.0), rel=1e-6)
