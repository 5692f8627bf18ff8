#!/usr/bin/env python3
"""Per-step overhead of a user's Python controller (``--controller Ego=file.py:Class``) in ``vei run``.

The case study (replay rider, 2 501 steps) is run three ways, best of ``--repeat``:

* ``none``: the ego as the scenario drives it, at its cruise speed along its path (no controller);
* ``no-op``: a plugged class whose ``step`` returns 0.0: what plugging in costs per step (the
  observation built, ``step`` called, the command checked, the vehicle model and the path step);
* ``contract``: the observation built, a no-op ``step`` called and its command checked, timed alone;
* ``fmu``: vei's planner built as a native FMU (``vei fmu build cap``) on the ego through fmpy;
* ``planner``: vei's own planner through the contract against the built-in planner (CapEnabled=true):
  the cost of seeing the scene through the contract rather than through the interpreter's entities.

    python benchmarks/controller_overhead.py [--repeat N]
"""

from __future__ import annotations

import argparse
import tempfile
import timeit
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NOOP = (
    "class NoOp:\n    def __init__(self, **properties):\n        pass\n\n    def step(self, obs):\n        return 0.0\n"
)


def _best(fn, repeat: int) -> float:
    """The fastest of ``repeat`` calls of ``fn``, in s."""
    return min(timeit.repeat(fn, number=1, repeat=repeat))


def _contract_us(xosc: Path, values: dict, plugged: tuple, calls: int = 20000) -> float:
    """The contract's own cost per step (µs): the observation built, ``step`` called (a no-op), the
    command checked, timed alone on the case study's two road users."""
    from vei_scenario.interpreter import Simulation, load_scenario
    from vei_scenario.sut import command_from

    sim = Simulation(load_scenario(xosc, values), 0.01, controllers=plugged)
    ego = sim.ctx.entities["Ego"]
    ctrl = ego.sut
    ctrl.instance()

    def calls_():
        for _ in range(calls):
            command_from(ctrl._step(ctrl.observation(ego, sim.ctx), 0.0), ctrl.label, 0.0)

    return _best(calls_, 3) / calls * 1e6


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5, help="runs of each kind; the best counts (default 5)")
    args = ap.parse_args()
    from vei_scenario.compiler import compile_clip
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.sut import parse_controller_options

    with tempfile.TemporaryDirectory() as tmp:
        xosc = Path(tmp) / "scenario.xosc"
        compile_clip(ROOT / "examples" / "case_study" / "clip.json", xosc)
        noop = Path(tmp) / "noop.py"
        noop.write_text(NOOP)
        plugged = parse_controller_options([f"Ego={noop}:NoOp"])
        planner = parse_controller_options(["Ego=vei_scenario.sut.planner:CollisionAvoidancePlanner"])
        replay, cap = {"RiderType": "replay"}, {"RiderType": "replay", "CapEnabled": "true", "TimeShift": "2.197"}
        steps = len(run_scenario(xosc, replay).t) - 1
        t_none = _best(lambda: run_scenario(xosc, replay), args.repeat)
        t_noop = _best(lambda: run_scenario(xosc, replay, controllers=plugged), args.repeat)
        t_cap = _best(lambda: run_scenario(xosc, cap), args.repeat)
        t_wrap = _best(lambda: run_scenario(xosc, cap, controllers=planner), args.repeat)
        contract = _contract_us(xosc, replay, plugged)
        from vei_scenario.fmu import build_fmus

        fmu = build_fmus(["cap"], Path(tmp) / "fmus")["cap"]  # vei's planner as a native FMU (C, fmpy)
        as_fmu = parse_controller_options([f"Ego={fmu}"], ["cruise_speed_mps=5.61"])
        t_fmu = _best(lambda: run_scenario(xosc, cap, controllers=as_fmu), args.repeat)
        fmu_step = _contract_us(xosc, cap, as_fmu, 5000)
    us = 1e6 / steps
    print(f"case study, {steps} steps at dt 0.01 s, best of {args.repeat}")
    print(f"  no controller          {t_none * 1e3:8.1f} ms  {t_none * us:6.1f} us/step")
    print(f"  no-op Python class     {t_noop * 1e3:8.1f} ms  {t_noop * us:6.1f} us/step")
    print(f"  built-in planner       {t_cap * 1e3:8.1f} ms  {t_cap * us:6.1f} us/step")
    print(f"  planner via contract   {t_wrap * 1e3:8.1f} ms  {t_wrap * us:6.1f} us/step")
    print(f"  planner as native FMU  {t_fmu * 1e3:8.1f} ms  {t_fmu * us:6.1f} us/step (instance made per run)")
    print(f"the contract alone (observation, step call, command check): {contract:.1f} us/step; "
          f"a whole run with a no-op class against none: {(t_noop - t_none) * us:+.1f} us/step; "
          f"the planner through the contract against the built-in: {(t_wrap - t_cap) * us:+.1f} us/step; "
          f"a native FMU (vei_cap, through fmpy) per step: {fmu_step:.1f} us")  # fmt: skip


if __name__ == "__main__":
    main()
