"""BAD partner: reads its inputs like StraightLine but never sets its output;
OSMPTrafficUpdateOut.base.lo/.base.hi/.size stay 0 (their start values) for the whole run.
A correct host must report that no TrafficUpdate was produced (null buffer / size 0) and
must not dereference address 0 or silently keep the host where it was."""
import osmp_common as oc
from pythonfmu import DefaultExperiment


class NeverWrites(oc.OsmpTrafficParticipant):
    description = "BAD OSMP partner: never writes OSMPTrafficUpdateOut"
    default_experiment = DefaultExperiment(start_time=0.0, step_size=0.02)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        oc.speed_param(self, "speed_mps", 10.0, "unused [m/s]")

    def compute(self, sv, tc, t, dt):
        oc.straight_line_update(sv, t, dt, float(self.speed_mps))  # computed, never published
        return None
