"""BAD partner: computes the StraightLine TrafficUpdate and publishes a valid, non-null
buffer address in OSMPTrafficUpdateOut.base.lo/.base.hi, but OSMPTrafficUpdateOut.size = 0.
Per OSMP, size 0 means "no valid buffer": a correct host must not decode it (an empty
buffer would parse as an empty TrafficUpdate) and must report the missing update."""
import osmp_common as oc
from pythonfmu import DefaultExperiment


class ZeroSize(oc.OsmpTrafficParticipant):
    description = "BAD OSMP partner: OSMPTrafficUpdateOut.size is always 0"
    default_experiment = DefaultExperiment(start_time=0.0, step_size=0.02)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        oc.speed_param(self, "speed_mps", 10.0, "speed of the (unpublished) update [m/s]")

    def compute(self, sv, tc, t, dt):
        return oc.straight_line_update(sv, t, dt, float(self.speed_mps))

    def emit(self, tu):
        self.write_output(tu.SerializeToString(), size_override=0)
