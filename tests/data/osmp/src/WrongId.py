"""BAD partner: computes the StraightLine pose of the host, but update[0].id is NOT the host:
it is the id of the first other moving object in the SensorView's ground truth (in
moving_object order), or host id + 1000 if there is no other moving object.
A correct host must report that the participant updated an entity it does not control
(and must neither move the other object nor apply the pose to the host silently)."""
import osmp_common as oc
from pythonfmu import DefaultExperiment


class WrongId(oc.OsmpTrafficParticipant):
    description = "BAD OSMP partner: TrafficUpdate for an id that is not the host"
    default_experiment = DefaultExperiment(start_time=0.0, step_size=0.02)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        oc.speed_param(self, "speed_mps", 10.0, "constant speed along the current heading [m/s]")

    def compute(self, sv, tc, t, dt):
        host, others = oc.find_host(sv) if sv is not None else (None, [])
        if host is None:
            return None
        wrong = others[0].id.value if others else host.id.value + 1000
        return oc.straight_line_update(sv, t, dt, float(self.speed_mps), reported_id=wrong)
