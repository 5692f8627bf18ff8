"""FMU whose do_step raises RuntimeError('planner diverged') for every step
starting at simulated time >= 1.0 s (pythonfmu turns it into an fmi2Error
status).  Correct ports, a_cmd = 0.0 before the failure.
"""
from pythonfmu import Fmi2Causality, Fmi2Initial, Fmi2Variability, Fmi2Slave, Real


class RaisingFmu(Fmi2Slave):
    author = "vei-scenario test partners"
    description = "do_step raises from t >= 1.0 s"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.ego_x = 0.0
        self.ego_y = 0.0
        self.ego_yaw = 0.0
        self.ego_speed = 0.0
        # no threat by default: far away, standing
        self.threat_x = 1.0e9
        self.threat_y = 1.0e9
        self.threat_yaw = 0.0
        self.threat_speed = 0.0
        self.a_cmd = 0.0
        for name in ("ego_x", "ego_y", "ego_yaw", "ego_speed",
                     "threat_x", "threat_y", "threat_yaw", "threat_speed"):
            self.register_variable(Real(name, causality=Fmi2Causality.input))
        self.register_variable(Real("a_cmd", causality=Fmi2Causality.output, initial=Fmi2Initial.exact))

    def do_step(self, current_time, step_size):
        if current_time >= 1.0 - 1e-9:
            raise RuntimeError("planner diverged")
        self.a_cmd = 0.0
        return True
