"""What every action is: started, updated after the entities moved, stopped; the stepped kinds that act
on their entity each step before the move; the helpers actions share to read their XML."""

from __future__ import annotations

import math

from vei_scenario.safe_xml import float_attribute


class Action:
    done = False

    def start(self, ctx) -> None:
        pass

    def update(self, ctx) -> None:
        """Called after the entities moved: decide whether the action has completed."""

    def stop(self, ctx) -> None:
        pass

    def carried(self, ctx) -> bool:
        """Whether a quiet stretch of the core (interpreter/cruise.py) may run while this action runs:
        the core moves its entity as the action would, and its :meth:`update` would not end it in
        the stretch's steps (the core stops before a step that would)."""
        return False


class Stepped(Action):
    """An action that acts on its entity every step before the entities move (registered in
    ``ctx.stepping`` when it starts); it ends when done or when another action takes the entity's
    domain over (:meth:`taken_over`)."""

    entity: str

    def taken_over(self, ctx) -> bool:
        return False

    def update(self, ctx) -> None:
        if self.taken_over(ctx):
            self.done = True
        if self.done and self in ctx.stepping:
            ctx.stepping.remove(self)

    def stop(self, ctx) -> None:
        self.done = True
        if self in ctx.stepping:
            ctx.stepping.remove(self)


class SteppedLongitudinal(Stepped):
    """A stepped action that sets its entity's speed; another longitudinal action ends it."""

    def taken_over(self, ctx) -> bool:
        return ctx.entities[self.entity].longitudinal is not self


def entity_ref(ctx, el, attribute: str = "entityRef") -> str:
    """The entity an action's ``attribute`` names; one line naming the action and the line if none."""
    name = el.get(attribute)
    if name not in ctx.entities:
        raise ctx.error(el, f"{el.tag}: no entity named {name!r}")
    return name


def constraint(ctx, dyn, name: str) -> float:
    """A ``DynamicConstraints`` attribute; infinite when absent (an absent constraint does not
    constrain)."""
    value = dyn.get(name) if dyn is not None else None
    return float_attribute(ctx.path, dyn, name) if value not in (None, "") else math.inf
