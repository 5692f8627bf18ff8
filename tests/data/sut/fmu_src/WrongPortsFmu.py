"""FMU with the wrong interface: Real inputs x, y and Real output throttle
only (no ego_*/threat_* inputs, no a_cmd).  vei must reject it at load time
with a message naming the missing output a_cmd (and/or the unmatched
inputs), before the simulation starts, and exit non-zero.
"""
from pythonfmu import Fmi2Causality, Fmi2Initial, Fmi2Variability, Fmi2Slave, Real


class WrongPortsFmu(Fmi2Slave):
    author = "vei-scenario test partners"
    description = "wrong ports: inputs x, y; output throttle"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.x = 0.0
        self.y = 0.0
        self.throttle = 0.0
        self.register_variable(Real("x", causality=Fmi2Causality.input))
        self.register_variable(Real("y", causality=Fmi2Causality.input))
        self.register_variable(Real("throttle", causality=Fmi2Causality.output, initial=Fmi2Initial.exact))

    def do_step(self, current_time, step_size):
        self.throttle = 0.1 * self.x
        return True
