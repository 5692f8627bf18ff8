"""OSMP traffic participant that does what its TrafficCommand tells it: speed, trajectory, path.

Written from the OSI messages (osi_trafficcommand.proto, osi_trafficupdate.proto) and the OSMP
specification, on the shared base of the other partners (osmp_common.py).

State: a speed v (m/s), at the first valid SensorView the host's speed along its heading; a
TrafficCommand's speed_action sets it to absolute_target_speed at once (whatever its shape).

Each doStep(t, dt), with the host's pose read from the SensorView's ground truth:
- follow_trajectory_action (the last one received): the pose at t + dt is the linear interpolation in
  time between its trajectory_point's (x and y; yaw along the shorter turn); before the first
  point's time the first point; after the last, on from the last point along its yaw at the speed of
  the last segment.
- follow_path_action (the last one received, if no trajectory): the host travels v*dt further along
  the polyline of its path_point's (yaw interpolated along the shorter turn by arc length) from where
  it entered it (arc length 0 at the first point); after the last point, straight on along its yaw.
- neither: straight on along its current heading at v.
The TrafficUpdate carries the new position (box centre, as the points are), yaw, velocity along the
yaw and the speed, timestamp t + dt.
"""
import math

import osmp_common as oc
from pythonfmu import DefaultExperiment


def _wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def _lerp_pose(p0, p1, f):
    """(x, y, yaw) a fraction f from pose p0 to pose p1."""
    return (p0[0] + f * (p1[0] - p0[0]), p0[1] + f * (p1[1] - p0[1]), _wrap(p0[2] + f * _wrap(p1[2] - p0[2])))


def _time(ts):
    return ts.seconds + ts.nanos * 1e-9


class TrajectoryFollower(oc.OsmpTrafficParticipant):
    description = "OSMP traffic participant: follows its TrafficCommand's speed, trajectory and path actions"
    default_experiment = DefaultExperiment(start_time=0.0, step_size=0.02)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self._v = None
        self._trajectory = None  # [(t, x, y, yaw)]
        self._path = None  # [(s, x, y, yaw)]
        self._s = 0.0

    def _command(self, tc):
        for a in tc.action:
            if a.HasField("speed_action"):
                self._v = a.speed_action.absolute_target_speed
            if a.HasField("follow_trajectory_action"):
                pts = a.follow_trajectory_action.trajectory_point
                self._trajectory = [(_time(p.timestamp), p.position.x, p.position.y, p.orientation.yaw) for p in pts]
            if a.HasField("follow_path_action"):
                path, s = [], 0.0
                for p in a.follow_path_action.path_point:
                    if path:
                        s += math.hypot(p.position.x - path[-1][1], p.position.y - path[-1][2])
                    path.append((s, p.position.x, p.position.y, p.orientation.yaw))
                self._path, self._s = path, 0.0

    def _on_trajectory(self, t):
        pts = self._trajectory
        if t <= pts[0][0]:
            return pts[0][1:], 0.0
        for p0, p1 in zip(pts, pts[1:]):
            if t <= p1[0]:
                seg = math.hypot(p1[1] - p0[1], p1[2] - p0[2]) / (p1[0] - p0[0])
                return _lerp_pose(p0[1:], p1[1:], (t - p0[0]) / (p1[0] - p0[0])), seg
        p0, p1 = pts[-2], pts[-1]
        v = math.hypot(p1[1] - p0[1], p1[2] - p0[2]) / (p1[0] - p0[0]) if len(pts) > 1 else 0.0
        d = v * (t - p1[0])
        return (p1[1] + d * math.cos(p1[3]), p1[2] + d * math.sin(p1[3]), p1[3]), v

    def _on_path(self, s):
        pts = self._path
        for p0, p1 in zip(pts, pts[1:]):
            if s <= p1[0] and p1[0] > p0[0]:
                return _lerp_pose(p0[1:], p1[1:], max(0.0, s - p0[0]) / (p1[0] - p0[0]))
        end = pts[-1]
        d = s - end[0]
        return end[1] + d * math.cos(end[3]), end[2] + d * math.sin(end[3]), end[3]

    def compute(self, sv, tc, t, dt):
        host, _ = oc.find_host(sv) if sv is not None else (None, [])
        if host is None:
            return None
        if self._v is None:
            self._v = oc.host_speed(host)
        if tc is not None:
            self._command(tc)
        if self._trajectory:
            (x, y, yaw), speed = self._on_trajectory(t + dt)
        elif self._path:
            self._s += self._v * dt
            (x, y, yaw), speed = self._on_path(self._s), self._v
        else:
            yaw, speed = host.base.orientation.yaw, self._v
            x = host.base.position.x + speed * dt * math.cos(yaw)
            y = host.base.position.y + speed * dt * math.sin(yaw)
        tu = oc.new_traffic_update(sv, t + dt)
        oc.fill_pose(tu.update.add(), host, x, y, yaw, speed)
        return tu
