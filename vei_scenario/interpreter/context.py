"""What conditions, actions and controllers see of a running simulation: time, entities, parameters and
variables, the storyboard's elements, collisions, the road network (loaded on first use)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from vei_scenario.errors import VeiInputError


@dataclass
class Context:
    """What conditions and actions see of the simulation."""

    path: object  # the scenario file, for error messages
    t: float
    dt: float
    step: int
    entities: dict
    parameters: dict[str, str]
    elements: dict[tuple[str, str], object] = field(default_factory=dict)  # (kind, name) -> storyboard Element
    colliding: set[frozenset[str]] = field(default_factory=set)
    trajectories: dict = field(default_factory=dict)  # Trajectory name -> Polyline
    signals: dict[str, str] = field(default_factory=dict)  # traffic signal name -> state
    #: Running actions stepped before the entities move (they read the state all triggers saw).
    stepping: list = field(default_factory=list)
    #: Under Jacobi coupling: every entity as it was at the start of the step (see engine.COUPLINGS).
    snapshot: dict | None = None
    #: True while the Init actions start (before the first record at t = 0).
    initializing: bool = False
    #: the storyboard's first evaluation at t = 0, before t = 0 is logged: no time passes in it
    settling: bool = False
    road_file: object = None  # the scenario's OpenDRIVE file, loaded on first use
    #: OpenSCENARIO 1.2 variables: name -> current value (text), and their declared types
    variables: dict[str, str] = field(default_factory=dict)
    variable_types: dict[str, str] = field(default_factory=dict)
    #: the declared types of the top-level parameters (ParameterAction checks what it sets against them)
    parameter_types: dict[str, str] = field(default_factory=dict)
    #: storyboard transitions so far (a step without any leaves the triggers it evaluated in place)
    transitions: int = 0
    #: Where in the storyboard's order the trigger being evaluated stands (its element's place in the
    #: document; inf after the trigger pass): a transition is seen by the triggers after it in the
    #: step it happens, by those before it in the next (storyboard.Element.mark).
    position: float = math.inf
    #: The document place of the storyboard action starting now (0: an Init action): esmini steps running
    #: actions in that order, so a lane change sees the speed a SpeedAction before it has set this step.
    acting: float = 0.0
    #: What the run played differently from what the file asks, in the words of :meth:`warn` (a
    #: controller vei has no model for, played as the default controller as esmini plays it).
    warnings: list[str] = field(default_factory=list)
    #: the scenario's threat (the entity the ego's controllers see as one), once the roles are known
    threat: str | None = None

    @property
    def roads(self):
        """The scenario's road network (None without one), loaded when a position first needs it."""
        net = self.__dict__.get("_roads")
        if net is None and self.road_file is not None:
            from vei_scenario.roads.road_model import RoadNetwork

            net = self.__dict__["_roads"] = RoadNetwork.load(self.road_file)
        return net

    def observed(self, name: str):
        """Entity ``name`` as other entities' controllers see it now: its current state under
        sequential coupling, its state at the start of the step under Jacobi coupling."""
        if self.snapshot is not None:
            return self.snapshot.get(name)
        return self.entities.get(name)

    def error(self, el, reason: str) -> VeiInputError:
        """A refusal naming ``el``'s file and line (the catalog file for what came from a catalog)."""
        from vei_scenario.interpreter.document import source_of

        return VeiInputError(source_of(el, self.path), f"line {el.sourceline}", reason)

    def warn(self, el, reason: str) -> None:
        """Note, once, something the run plays in its own way, naming ``el``'s file and line as
        :meth:`error` does."""
        line = str(self.error(el, reason))  # (file: line N: reason, as a refusal reads)
        if line not in self.warnings:
            self.warnings.append(line)
