"""BAD partner: behaves exactly like StraightLine, but build.py declares the MIME type of
OSMPSensorViewIn as type=SensorData (instead of SensorView) in its osmp-binary-variable
annotations.  A correct host must refuse it at load time (before any doStep)."""
import osmp_common as oc
from pythonfmu import DefaultExperiment


class WrongMime(oc.OsmpTrafficParticipant):
    description = "BAD OSMP partner: SensorView input annotated as type=SensorData"
    default_experiment = DefaultExperiment(start_time=0.0, step_size=0.02)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        oc.speed_param(self, "speed_mps", 10.0, "constant speed along the current heading [m/s]")

    def compute(self, sv, tc, t, dt):
        return oc.straight_line_update(sv, t, dt, float(self.speed_mps))
