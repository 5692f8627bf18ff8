"""The pythonfmu slave behind ``vei fmu build --backend python``: registers every variable of the
model's table with getters and setters on a :mod:`~vei_scenario.fmu.python_models` model.

The FMU's script subclasses :class:`VeiSlave` with the model identifier as class name (pythonfmu
takes the identifier from it). Running it needs Python with pythonfmu's runtime and vei-scenario.
"""

from __future__ import annotations

from pythonfmu import Boolean, Fmi2Causality, Fmi2Initial, Fmi2Slave, Fmi2Variability, Integer, Real, String
from pythonfmu.enums import Fmi2Status

from vei_scenario.fmu.python_models import MODEL_CLASSES, FmuModelError

_TYPES = {"Real": Real, "Integer": Integer, "Boolean": Boolean, "String": String}
_CAUSALITY = {
    "parameter": Fmi2Causality.parameter,
    "input": Fmi2Causality.input,
    "output": Fmi2Causality.output,
}
_VARIABILITY = {
    "fixed": Fmi2Variability.fixed,
    "continuous": Fmi2Variability.continuous,
    "discrete": Fmi2Variability.discrete,
}


class VeiSlave(Fmi2Slave):
    model_name = ""

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.model = MODEL_CLASSES[self.model_name]()
        self.description = self.model.spec.description
        values = self.model.values
        for s in self.model.spec.scalars():
            v = s.var
            extra = {"initial": Fmi2Initial.exact} if v.causality == "output" else {}
            self.register_variable(
                _TYPES[v.type](
                    s.name,
                    start=s.start,
                    causality=_CAUSALITY[v.causality],
                    variability=_VARIABILITY[v.variability],
                    description=v.description or None,
                    getter=lambda n=s.name: values[n],
                    setter=lambda value, n=s.name: self._refusing(self.model.set, n, value),
                    **extra,
                ),
                nested=False,
            )

    def _refusing(self, call, *args):
        """Log the model's refusal with error status before pythonfmu turns the exception into a
        fatal status (its runtime has no way to return fmi2Error from Python)."""
        try:
            return call(*args)
        except FmuModelError as exc:
            self.log(str(exc), Fmi2Status.error)
            raise

    def exit_initialization_mode(self) -> None:
        self._refusing(self.model.initialize)

    def do_step(self, current_time: float, step_size: float) -> bool:
        self._refusing(self.model.do_step, current_time, step_size)
        return True
