"""The system under test: the user's own driving function on an entity, in every simulating command.

The contract (:mod:`vei_scenario.sut.contract`): a Python class, constructed with the controller's
properties as ``str`` keyword arguments, whose ``step(obs)`` returns the longitudinal acceleration
command (m/s²) once per step; an optional ``reset(info)`` is called before a run. ``obs`` carries the
time, the step, the controlled entity, the scenario's threat and every other entity, each as box
centre, heading, speed, acceleration and size in the OpenDRIVE frame. The entity keeps its path or
lane; the command drives its speed through vei's vehicle model within its Performance.

Ways in (:mod:`vei_scenario.sut.spec`): ``--controller ENTITY=path/file.py:Class`` or
``ENTITY=package.module:Class`` on the command line, or a scenario ``Controller`` whose property
``module`` names one (CARLA ScenarioRunner's convention). vei's own planner is one implementation
(:mod:`vei_scenario.sut.planner`).

Why a package of its own: the contract, the loading of the user's code and the faults it can raise
are the user's interface and change for the user's reasons; the interpreter only drives it
(:mod:`vei_scenario.interpreter.plugged`).
"""

from vei_scenario.sut.contract import Command, ControllerFault, ObjectState, Observation, command_from
from vei_scenario.sut.spec import ControllerSpec, parse_controller_options, reproduce_options, sut_document

__all__ = [
    "Command",
    "ControllerFault",
    "ControllerSpec",
    "ObjectState",
    "Observation",
    "command_from",
    "parse_controller_options",
    "reproduce_options",
    "sut_document",
]
