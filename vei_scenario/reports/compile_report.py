"""The short report ``vei compile`` prints: tracks, duration, conflict point, collision shift, threat."""

from __future__ import annotations

import math

from vei_scenario.compiler import CompileResult


def compile_report(result: CompileResult) -> str:
    m, rec = result.model, result.reconstruction
    road = "fitted to the ego track" if result.road_source == "fitted" else f"{result.road_source[4:]} via netconvert"
    lines = [
        f"clip {rec.clip.id}: {m.duration_s:.1f} s, ego + {len(rec.scooters)} e-scooter track(s)"
        + (f" + {len(rec.others)} other road user(s) replayed as recorded" if rec.others else "")
        + f", output at {rec.rate_hz:g} Hz",
        f"road network: {road}; ego GPS fixes on driving lanes: {100 * result.ego_on_lanes:.1f} %",
    ]
    for tid, c in sorted(m.conflicts.items()):
        track = rec.scooters[tid]
        head = "THREAT " if tid == m.threat else "       "
        if c.reaches_ego_path:
            where = "paths cross" if c.path_distance_m == 0 else f"paths {c.path_distance_m:.2f} m apart"
            coll = (
                f"collision for TimeShift {c.collision_shifts_s[0]:+.2f}..{c.collision_shifts_s[1]:+.2f} s"
                if c.collision_shifts_s
                else "no box contact for any shift"
            )
            lines.append(
                f"{head}{tid}: observed t={track.key_t[0]:.1f}..{track.key_t[-1]:.1f} s ({track.key_t.size} frames); "
                f"{where} at ({c.point_x:.1f}, {c.point_y:.1f}) m, ego there at {c.t_ego_s:.2f} s, scooter at "
                f"{c.t_scooter_s:.2f} s; conflict TimeShift {c.time_shift_s:+.2f} s; {coll}"
            )
        else:
            lines.append(
                f"{head}{tid}: observed t={track.key_t[0]:.1f}..{track.key_t[-1]:.1f} s ({track.key_t.size} frames); "
                f"path stays {c.path_distance_m:.2f} m from the ego's: no conflict"
            )
        lines.append(
            f"        at TimeShift 0: min centre distance {c.unshifted_min_distance_m:.2f} m, "
            f"{'COLLISION' if c.unshifted_collision else 'no collision'}"
        )
    if not math.isfinite(m.conflicts[m.threat].margin_s):
        lines.append("note: no scooter path reaches the ego's; the threat is the closest one")
    lines.extend(f"note: {n}" for n in result.notes)
    lines.extend(f"wrote {p}" for p in result.written if "variant_" not in p.name)
    nvar = sum(1 for p in result.written if p.name.startswith("variant_"))
    if nvar:
        lines.append(f"wrote {nvar} resolved variants")
    return "\n".join(lines)
