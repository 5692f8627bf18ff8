"""OSMP traffic participant: the host vehicle drives straight along its current heading at
constant speed `speed_mps` (parameter, default 10 m/s).

Each doStep(t, dt): read host_vehicle_id's MovingObject from OSMPSensorViewIn's ground
truth, output TrafficUpdate update[0] = same id, position + speed_mps*dt*(cos yaw, sin yaw),
same yaw, velocity = speed_mps*(cos yaw, sin yaw), timestamp t+dt.
No valid SensorView (null/size 0/undecodable/no host): output left unchanged.
OSMPTrafficCommandIn is accepted (decoded if present) but does not change the behaviour.
"""
import osmp_common as oc
from pythonfmu import DefaultExperiment


class StraightLine(oc.OsmpTrafficParticipant):
    description = "OSMP traffic participant: straight line at constant speed_mps"
    default_experiment = DefaultExperiment(start_time=0.0, step_size=0.02)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        oc.speed_param(self, "speed_mps", 10.0, "constant speed along the current heading [m/s]")

    def compute(self, sv, tc, t, dt):
        return oc.straight_line_update(sv, t, dt, float(self.speed_mps))
