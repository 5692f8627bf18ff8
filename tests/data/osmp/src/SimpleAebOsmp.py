"""OSMP traffic participant with a simple AEB.

Speed: taken once from the host's ground-truth velocity (projected on its heading) at the
first valid SensorView, then held internally.  Each doStep(t, dt), with the host pose read
from the SensorView's ground truth:
  gap = distance from the host's front bumper (centre + length/2 along the heading) to the
        nearest corner of any other moving object's box that is ahead (its centre ahead of
        the host's centre) and overlaps the corridor of total width host width + 0.5 m,
        centred on the host's heading line;
  brake iff gap exists and speed > 0 and gap / speed < 2.0 s
  braking: constant 6 m/s^2, exact kinematics within the step, never below 0:
        v' = max(0, v - 6 dt); distance = v dt - 3 dt^2 (or v^2/12 if it stops in the step)
  else: v' = v, distance = v dt.
Output: TrafficUpdate update[0] = host id, position + distance*(cos yaw, sin yaw), same yaw,
velocity v'*(cos yaw, sin yaw), acceleration -6 (along heading) while braking, timestamp t+dt.
"""
import math

import osmp_common as oc
from pythonfmu import DefaultExperiment

DECEL = 6.0
TTC_BRAKE_S = 2.0
LATERAL_MARGIN_M = 0.5


class SimpleAebOsmp(oc.OsmpTrafficParticipant):
    description = "OSMP traffic participant: hold speed, AEB 6 m/s^2 at TTC < 2 s"
    default_experiment = DefaultExperiment(start_time=0.0, step_size=0.02)
    with_traffic_command = False

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._speed = None

    def compute(self, sv, tc, t, dt):
        host, others = oc.find_host(sv) if sv is not None else (None, [])
        if host is None:
            return None
        if self._speed is None:
            self._speed = oc.host_speed(host)
        v = self._speed
        gap = oc.aeb_gap(host, others, LATERAL_MARGIN_M)
        brake = gap is not None and v > 0.0 and gap / v < TTC_BRAKE_S
        if brake:
            if v <= DECEL * dt:
                dist, v_new = v * v / (2.0 * DECEL), 0.0
            else:
                dist, v_new = v * dt - 0.5 * DECEL * dt * dt, v - DECEL * dt
        else:
            dist, v_new = v * dt, v
        self._speed = v_new
        yaw = host.base.orientation.yaw
        tu = oc.new_traffic_update(sv, t + dt)
        oc.fill_pose(tu.update.add(), host,
                     host.base.position.x + dist * math.cos(yaw),
                     host.base.position.y + dist * math.sin(yaw),
                     yaw, v_new, -DECEL if brake else 0.0)
        return tu
