"""Faulty ego controllers: each breaks the plug-in contract in one specific way.

vei must turn every one of these into a one-line error that names the
controller (entity + file:Class), the step time (where applicable) and the
reason, and exit non-zero -- never a hang, a Python traceback dump as the only
output, a silently "passed" run, or NaN/absurd values fed into the simulation.

Before the failure point every controller below behaves like a plain cruise
controller (returns 0.0 m/s^2), so the failure time is deterministic.
"""

import time


class RaisesAt2s:
    """Raises RuntimeError('sensor fusion lost track') from step at t_s >= 2.0.

    Expected: error naming the controller, t ~= 2.0 s (first step with
    t_s >= 2.0) and 'sensor fusion lost track'; non-zero exit.
    """

    def __init__(self, **kwargs):
        self.kwargs = kwargs

    def step(self, obs):
        if obs.t_s >= 2.0:
            raise RuntimeError("sensor fusion lost track")
        return 0.0


class ReturnsNaN:
    """Returns float('nan') from t_s >= 1.0 (0.0 before).

    Expected: error 'non-finite command' (or similar) at t ~= 1.0 s; the NaN
    must never reach the ego's state.
    """

    def __init__(self, **kwargs):
        pass

    def step(self, obs):
        if obs.t_s >= 1.0:
            return float("nan")
        return 0.0


class ReturnsAbsurd:
    """Returns 1e6 m/s^2 at every step (from t = 0).

    Expected: either a clear error (command out of any plausible range) at the
    first step, or -- if vei's contract is "clamp to vehicle performance" --
    the ego's acceleration limited to its vehicle performance (no 1e6 m/s^2
    and no speed jump in the trace).  Never an ego at ~1e6 m/s.
    """

    def __init__(self, **kwargs):
        pass

    def step(self, obs):
        return 1e6


class Hangs:
    """Sleeps for an hour (time.sleep(3600)) in step at t_s >= 1.0.

    Expected: vei's per-step / per-run timeout fires, the error names the
    controller, t ~= 1.0 s and a timeout; non-zero exit, well before 3600 s.
    """

    def __init__(self, **kwargs):
        pass

    def step(self, obs):
        if obs.t_s >= 1.0:
            time.sleep(3600)
        return 0.0


class NoStep:
    """Has no step method at all.

    Expected: rejected at load time (before the simulation starts, no step
    time) with a message saying the class has no step(obs) method.
    """

    def __init__(self, **kwargs):
        pass

    def reset(self, info):
        pass


class BadReturn:
    """Returns the string 'brake' instead of a float / mapping with accel_mps2.

    Expected: error at the first step (t = 0) naming the controller and the
    bad return type (str / 'brake').
    """

    def __init__(self, **kwargs):
        pass

    def step(self, obs):
        return "brake"


class WrongCtorArgs:
    """Its __init__ accepts no keyword arguments.

    Expected: if the controller is given any property, construction fails
    with TypeError (unexpected keyword argument); vei must report that as a
    load error naming the controller, not crash with a traceback.  With no
    properties at all it constructs fine and brakes mildly (-1 m/s^2).
    """

    def __init__(self):
        pass

    def step(self, obs):
        return -1.0
