"""The storyboard: elements with states (standby, running, complete), triggers with edges and delays,
and the stepping of the whole tree once per simulation step, as OpenSCENARIO's state machine has it.

Knows nothing of how entities move: conditions (:mod:`vei_scenario.interpreter.conditions`) read the
:class:`~vei_scenario.interpreter.context.Context`, and actions are started, updated and stopped
through the small interface of :mod:`vei_scenario.interpreter.action_base`.
"""

from __future__ import annotations

import bisect
import math
from collections import deque

from vei_scenario.interpreter.actions import SignalState, StoreAction, global_actions, private_actions
from vei_scenario.interpreter.clock import count_at_or_before, step_time, step_times
from vei_scenario.interpreter.conditions import ENTITY_CONDITIONS, RULES, VALUE_CONDITIONS, known_entity
from vei_scenario.interpreter.context import Context
from vei_scenario.safe_xml import first_element

STANDBY, RUNNING, COMPLETE = "standby", "running", "complete"

#: Actions that only set values: an event of them starts at once, so what follows in the step sees them.
VALUE_ACTIONS = (SignalState, StoreAction)


class ConditionRunner:
    """A ``<Condition>``: its raw test, the edge it fires on and its delay."""

    def __init__(self, el, ctx: Context) -> None:
        self.el = el
        self.edge = el.get("conditionEdge", "none")
        self.delay = float(el.get("delay", "0") or 0)
        self.prev: bool | None = None
        #: the edged values not yet due, oldest first, as runs of steps [first, stop, value] (a quiet
        #: stretch of the core adds one run, not one entry per step)
        self.history: deque[list] = deque()
        by_value, by_entity = el.find("ByValueCondition"), el.find("ByEntityCondition")
        if by_value is not None and first_element(by_value) is not None:
            kind = first_element(by_value)
            cls = VALUE_CONDITIONS.get(kind.tag)
            if cls is None:
                raise ctx.error(kind, f"<{kind.tag}> is not supported by vei run")
            self.condition = cls(kind, ctx)
        elif by_entity is not None:
            trig = by_entity.find("TriggeringEntities")
            kind_parent = by_entity.find("EntityCondition")
            kind = first_element(kind_parent) if kind_parent is not None else None
            if trig is None or kind is None:
                raise ctx.error(by_entity, "ByEntityCondition needs TriggeringEntities and an EntityCondition")
            cls = ENTITY_CONDITIONS.get(kind.tag)
            if cls is None:
                raise ctx.error(kind, f"<{kind.tag}> is not supported by vei run")
            names = [r.get("entityRef") for r in trig.iterfind("EntityRef")]
            if not names:
                raise ctx.error(trig, "TriggeringEntities names no entity")
            for n in names:
                known_entity(ctx, trig, n)
            rule = trig.get("triggeringEntitiesRule", "any")
            if rule not in ("any", "all"):
                raise ctx.error(trig, f"triggeringEntitiesRule {rule!r} is neither 'any' nor 'all'")
            self.condition = cls(kind, ctx, names, rule)
        else:
            raise ctx.error(el, "condition without ByValueCondition or ByEntityCondition")
        if kind.get("rule") is not None and kind.get("rule") not in RULES:
            raise ctx.error(kind, f"rule {kind.get('rule')!r} is not one of {', '.join(RULES)}")
        if self.edge != "none" and self.edge not in self.EDGES:
            raise ctx.error(el, f"conditionEdge {self.edge!r} is not one of none, {', '.join(self.EDGES)}")
        self._test = self.condition.test  # (looked up once: edges test every step)
        #: the condition's value with its edge applied (the test itself without an edge)
        self.edged = getattr(self, self.EDGES[self.edge]) if self.edge in self.EDGES else self._test
        if self.delay <= 0:  # no delay: evaluating is the edged test (one call less each step)
            self.evaluate = self.edged

    EDGES = {"rising": "_rising", "falling": "_falling", "risingOrFalling": "_rising_or_falling"}

    def _rising(self, ctx: Context) -> bool:
        raw = self._test(ctx)
        prev, self.prev = self.prev, raw
        return raw and prev is False

    def _falling(self, ctx: Context) -> bool:
        raw = self._test(ctx)
        prev, self.prev = self.prev, raw
        return (not raw) and prev is True

    def _rising_or_falling(self, ctx: Context) -> bool:
        raw = self._test(ctx)
        prev, self.prev = self.prev, raw
        return prev is not None and raw != prev

    def evaluate(self, ctx: Context) -> bool:
        """The edged value, delayed: what it was ``delay`` seconds ago."""
        value = self.edged(ctx)
        self._append(ctx.step, ctx.step + 1, value)
        return self._pop(self._due(ctx.t), ctx.dt)

    def _append(self, first: int, stop: int, value: bool) -> None:
        """Values ``value`` evaluated at steps ``first`` to ``stop`` (exclusive), after the others."""
        history = self.history
        if history:
            last = history[-1]
            if last[1] == first and last[2] == value:
                last[1] = stop
                return
        history.append([first, stop, value])

    def _pop(self, limit: float, dt: float) -> bool:
        """Forget the values evaluated at or before ``limit``; the last of them (False when none)."""
        history, result = self.history, False
        while history:
            run = history[0]
            if step_time(run[0], dt) > limit:
                break
            result = run[2]
            due = count_at_or_before(run[0], run[1], dt, limit)
            if run[0] + due < run[1]:
                run[0] += due
                break
            history.popleft()
        return result

    def _due(self, t: float) -> float:
        """The latest time whose value has come due at ``t`` (``delay`` ago, within rounding)."""
        return t - self.delay + 1e-9

    # --- quiet steps (interpreter.cruise): what the next evaluations give while the raw test holds ---
    def held(self, ctx: Context) -> bool:
        """The edged value of the evaluations to come while the raw test keeps the value it had in
        this step's evaluation (an edge has passed by then)."""
        if self.edge != "none":
            return False
        if self.delay > 0 and self.history:  # (a delay shorter than rounding pops at once: none held)
            return self.history[-1][2]
        return self.condition.test(ctx)

    def pending(self) -> bool:
        """Whether a true value is still to come due."""
        return any(run[2] for run in self.history)

    def delayed(self, times, held: bool):
        """The delayed values of evaluations at ``times`` whose edged value is ``held`` (lazily)."""
        dt = times.dt
        old = [(t, run[2]) for run in self.history for t in step_times(run[0], run[1], dt)]
        k, first_new = 0, 0
        for i, t in enumerate(times):
            limit, result = self._due(t), False
            while k < len(old) and old[k][0] <= limit:
                result, k = old[k][1], k + 1
            if k == len(old):
                while first_new <= i and times[first_new] <= limit:
                    result, first_new = held, first_new + 1
            yield result

    def first_true(self, times, held: bool) -> int:
        """The index in ``times`` of the first evaluation whose delayed value is true (len(times) if
        none), given the edged value ``held`` throughout: what walking :meth:`delayed` finds, worked
        out from the runs' first times (a run's values come due in order, one bisection each)."""
        dt, n = times.dt, len(times)
        if not n:
            return 0
        runs = [(step_time(r[0], dt), r[2]) for r in self.history]  # (time of its first value, value)
        runs.append((times[0], held))  # (the evaluations to come)

        def due(i: int) -> float:
            return self._due(times[i])

        for j, (first, value) in enumerate(runs):
            if not value:
                continue
            i = bisect.bisect_left(range(n), first, key=due)  # (the evaluation at which it starts to come due)
            if i == n:
                return n
            limit, last = due(i), value
            for later, v in runs[j + 1 :]:  # (it gives the value of the last run come due by then)
                if later > limit:
                    break
                last = v
            if last:
                return i
        return n

    def skip(self, times, held: bool) -> None:
        """Account for evaluations at ``times`` (steps after ``times.step0``) that were not run (their
        edged value: ``held``)."""
        if self.delay > 0 and len(times):
            first = times.step0 + 1
            self._append(first, first + len(times), held)
            self._pop(self._due(times[-1]), times.dt)


class Trigger:
    """OR over condition groups, AND within a group; every condition is evaluated every step so that
    edges and delays see an unbroken history."""

    def __init__(self, el, ctx: Context) -> None:
        self.groups = [
            [ConditionRunner(c, ctx) for c in g.iterfind("Condition")] for g in el.iterfind("ConditionGroup")
        ]
        if len(self.groups) == 1 and len(self.groups[0]) == 1:  # the common trigger: its one condition
            self.evaluate = self.groups[0][0].evaluate

    def evaluate(self, ctx: Context) -> bool:
        fired = False
        for g in self.groups:
            ok = bool(g)
            for c in g:  # (each one: edges and delays need every step's value)
                if not c.evaluate(ctx):
                    ok = False
            fired = fired or ok
        return fired

    def conditions(self) -> list[ConditionRunner]:
        return [c for g in self.groups for c in g]

    def first_firing(self, held: dict, times) -> int:
        """The index in ``times`` of the first evaluation that would fire, len(times) if none would,
        given each condition's ``held`` edged value (its raw test unchanged throughout)."""
        first = len(times)
        for g in self.groups:
            if not g:
                continue
            steady = [c for c in g if c.delay <= 0 or not (held[c] or c.pending())]
            if any(not held[c] for c in steady):  # one member stays false: the group cannot fire
                continue
            moving = [c for c in g if c not in steady]
            if not moving:
                return 0
            # after its delay, a member gives what it holds: one holding false ends the search there
            settled = max(c.delay for c in moving) / times.dt + 2
            ends = not all(held[c] for c in moving)
            if len(moving) == 1:  # (one member: where its values come true, without walking them)
                i = moving[0].first_true(times, held[moving[0]])
                if i < first and not (ends and i > settled):
                    first = i
                continue
            for i, values in enumerate(zip(*(c.delayed(times, held[c]) for c in moving))):
                if i >= first or (ends and i > settled):
                    break
                if all(values):
                    first = i
                    break
        return first

    def reset(self) -> None:
        """Forget what the conditions saw (an element run again waits its delays afresh, as esmini)."""
        for g in self.groups:
            for c in g:
                c.prev = None
                c.history.clear()


# --- elements ---------------------------------------------------------------------------------------


class Element:
    def __init__(self, kind: str, el, ctx: Context, children: list[Element] | None = None) -> None:
        self.kind, self.name, self.el = kind, el.get("name", ""), el
        self.state = STANDBY
        self.children = children or []
        #: transition -> (step, storyboard position) of its last happening (Context.position)
        self.transitions: dict[str, tuple[int, float]] = {}
        self.order = 0  # its place in the document (Storyboard numbers its elements)
        self.max_executions = int(el.get("maximumExecutionCount", "1"))
        self.executions = 0
        start, stop = el.find("StartTrigger"), el.find("StopTrigger")
        # an empty <StartTrigger/> starts the element at once, as no trigger does (esmini's reading)
        has_start = start is not None and start.find("ConditionGroup") is not None
        self.start_trigger = Trigger(start, ctx) if has_start else None
        self.stop_trigger = Trigger(stop, ctx) if stop is not None else None
        self.actions: list = []  # runtime actions of an Action element
        ctx.elements.setdefault((kind, self.name), self)
        # esmini's qualified references "Event::Action", "Maneuver::Event::Action", ...: every
        # descendant is also known by its path from each of its ancestors
        self.descendants: list[tuple[str, str, Element]] = []
        for c in self.children:
            self.descendants.append((c.kind, c.name, c))
            self.descendants += [(k, f"{c.name}::{q}", d) for k, q, d in c.descendants]
        for k, q, d in self.descendants:
            ctx.elements.setdefault((k, f"{self.name}::{q}"), d)

    def mark(self, transition: str, ctx: Context) -> None:
        self.transitions[transition] = (ctx.step, ctx.position)
        ctx.transitions += 1

    def start(self, ctx: Context) -> None:
        self.state = RUNNING
        self.executions += 1
        self.mark("startTransition", ctx)

    def complete(self, ctx: Context, transition: str = "endTransition") -> None:
        """Move to complete: ``endTransition`` when done, ``stopTransition`` when stopped (the
        children are stopped too)."""
        if transition == "stopTransition":
            for c in self.children:
                if c.state != COMPLETE:
                    c.complete(ctx, transition)
            for a in self.actions:
                a.stop(ctx)
        self.state = COMPLETE
        self.mark(transition, ctx)


class Storyboard:
    """The storyboard's tree of elements built from the XML, and its stepping: each step, triggers
    are evaluated on the state every one of them sees, elements started and completed."""

    def __init__(self, board, ctx: Context) -> None:
        self.ctx = ctx
        stop = board.find("StopTrigger")
        self.stop_trigger = Trigger(stop, ctx) if stop is not None else None
        self.stories = [self._story(s) for s in board.iterfind("Story")]
        order = 0
        pending = list(reversed(self.stories))
        while pending:  # (numbered in document order: a story, its first act, ..., its first event ...)
            element = pending.pop()
            order += 1
            element.order = order
            pending.extend(reversed(element.children))

    @property
    def complete(self) -> bool:
        return _all_complete(self.stories)

    def watching(self) -> list[Trigger] | None:
        """The triggers the next step evaluates, or None when something would act in it regardless of
        them (an event running an action the core's quiet stretch does not carry, a story or an element
        without a trigger about to start)."""
        out = [self.stop_trigger] if self.stop_trigger is not None else []
        for story in self.stories:
            if story.state == STANDBY:
                return None
            if story.state != RUNNING:
                continue
            for act in story.children:
                if act.state == STANDBY:
                    if act.start_trigger is None:
                        return None
                    out.append(act.start_trigger)
                if act.state != RUNNING:
                    continue
                if act.stop_trigger is not None:
                    out.append(act.stop_trigger)
                for g in act.children:
                    for m in g.children:
                        if m.state != RUNNING:
                            continue
                        for ev in m.children:
                            if ev.state == RUNNING:
                                if not self._carried(ev):
                                    return None
                                continue
                            if ev.state == STANDBY:
                                if ev.start_trigger is None:
                                    return None
                                out.append(ev.start_trigger)
        return out

    def _carried(self, ev: Element) -> bool:
        """Whether every running action of a running event lets a quiet stretch of the core run."""
        ctx = self.ctx
        for a in ev.children:
            if a.state == RUNNING:
                for x in a.actions:
                    if not (x.done or x.carried(ctx)):
                        return False
        return True

    # --- building -----------------------------------------------------------------------------------
    def _story(self, el) -> Element:
        ctx = self.ctx
        return Element("Story", el, ctx, [self._act(a) for a in el.iterfind("Act")])

    def _act(self, el) -> Element:
        return Element("Act", el, self.ctx, [self._group(g) for g in el.iterfind("ManeuverGroup")])

    def _group(self, el) -> Element:
        ctx = self.ctx
        actors = [r.get("entityRef") for r in el.iterfind("Actors/EntityRef")]
        for a in actors:
            if a not in ctx.entities:
                raise ctx.error(el, f"ManeuverGroup {el.get('name')!r}: no entity named {a!r}")
        if el.find("CatalogReference") is not None:
            raise ctx.error(el.find("CatalogReference"), "maneuver catalogs are not supported by vei run")
        if el.find("Actors").get("selectTriggeringEntities", "false") == "true":
            raise ctx.error(el.find("Actors"), "selectTriggeringEntities=true is not supported by vei run")
        return Element("ManeuverGroup", el, ctx, [self._maneuver(m, actors) for m in el.iterfind("Maneuver")])

    def _maneuver(self, el, actors) -> Element:
        return Element("Maneuver", el, self.ctx, [self._event(e, actors) for e in el.iterfind("Event")])

    def _event(self, el, actors) -> Element:
        ctx = self.ctx
        event = Element("Event", el, ctx, [self._action(a, actors) for a in el.iterfind("Action")])
        event.priority = el.get("priority", "overwrite")
        return event

    def _action(self, el, actors) -> Element:
        ctx = self.ctx
        action = Element("Action", el, ctx)
        pa, ga = el.find("PrivateAction"), el.find("GlobalAction")
        if pa is not None:
            if not actors:
                raise ctx.error(el, "a private action needs actors")
            for a in actors:
                action.actions.extend(private_actions(pa, a, ctx))
        elif ga is not None:
            action.actions.extend(global_actions(ga, ctx))
        else:
            kind = el[0].tag if len(el) else "nothing"
            raise ctx.error(el, f"action <{kind}> is not supported by vei run")
        return action

    # --- running ------------------------------------------------------------------------------------
    def _start_event(self, ev: Element, running: list[Element]) -> bool:
        """The event's start as storyboard states (the transitions happen here, where the event
        stands); False when it is skipped. Its actions act when :meth:`_act_event` starts them."""
        ctx = self.ctx
        if ev.priority == "skip" and running:
            ev.mark("skipTransition", ctx)
            return False
        if ev.priority in ("override", "overwrite"):
            for r in running:
                r.complete(ctx, "stopTransition")
        ev.start(ctx)
        for a in ev.children:
            a.start(ctx)
        return True

    def _act_event(self, ev: Element) -> None:
        for a in ev.children:
            self.ctx.acting = a.order
            for act in a.actions:
                act.start(self.ctx)
        self.ctx.acting = 0.0

    def step(self) -> bool:
        """Advance states; False when the storyboard has ended."""
        ctx = self.ctx
        ctx.position = -1.0  # (the storyboard's own stop trigger is evaluated first)
        if self.stop_trigger is not None and self.stop_trigger.evaluate(ctx):
            ctx.position = math.inf
            return False
        starting: list[Element] = []
        for story in self.stories:
            if story.state == STANDBY:
                ctx.position = story.order
                story.start(ctx)
            if story.state != RUNNING:
                continue
            for act in story.children:
                ctx.position = act.order
                if act.state == STANDBY and (act.start_trigger is None or act.start_trigger.evaluate(ctx)):
                    act.start(ctx)
                    for g in act.children:
                        g.start(ctx)
                        for m in g.children:
                            m.start(ctx)
                if act.state != RUNNING:
                    continue
                if act.stop_trigger is not None and act.stop_trigger.evaluate(ctx):
                    act.complete(ctx, "stopTransition")
                    continue
                for g in act.children:
                    for m in g.children:
                        if m.state != RUNNING:
                            continue
                        running = None  # the maneuver's running events before any of its events starts
                        for ev in m.children:
                            ctx.position = ev.order
                            if ev.state == STANDBY and (ev.start_trigger is None or ev.start_trigger.evaluate(ctx)):
                                if running is None:
                                    running = [e for e in m.children if e.state == RUNNING]
                                others = [r for r in running if r is not ev]
                                # the states change at once (a trigger after it in this step sees the
                                # event start, as in esmini); its actions act after all triggers
                                if not self._start_event(ev, others):
                                    continue
                                if all(isinstance(x, VALUE_ACTIONS) for a in ev.children for x in a.actions):
                                    self._act_event(ev)  # a value set is seen by what follows
                                else:
                                    starting.append(ev)
        ctx.position = math.inf
        # every trigger sees the same world: actions act after all were evaluated (a teleport started
        # by one event must not hide the condition that starts another)
        for ev in starting:
            self._act_event(ev)
        return True

    def complete_finished(self) -> None:
        """Update the running actions after the entities moved; complete what has finished."""
        ctx = self.ctx
        done = _all_complete
        for story in self.stories:
            if story.state != RUNNING:
                continue
            for act in story.children:
                if act.state != RUNNING:
                    continue
                for g in act.children:
                    if g.state != RUNNING:  # (nothing runs inside a group that does not)
                        continue
                    for m in g.children:
                        if m.state != RUNNING:
                            continue
                        for ev in m.children:
                            if ev.state != RUNNING:
                                continue
                            for a in ev.children:
                                if a.state == RUNNING:
                                    for act_rt in a.actions:
                                        act_rt.update(ctx)
                                    if all(x.done for x in a.actions):
                                        a.complete(ctx)
                            if done(ev.children):
                                ev.complete(ctx)
                                if ev.executions < ev.max_executions:
                                    ev.state = STANDBY
                        if done(m.children):
                            m.complete(ctx)
                    if done(g.children):
                        g.complete(ctx)
                        if g.executions < g.max_executions:
                            self._restart_group(g)
                if done(act.children):
                    act.complete(ctx)
            if done(story.children):
                story.complete(ctx)

    def _restart_group(self, g: Element) -> None:
        """A ManeuverGroup whose maneuvers are all complete runs again while it has executions left
        (maximumExecutionCount): its maneuvers, events and actions start over from standby."""
        ctx = self.ctx

        def reset(el: Element) -> None:
            el.state, el.executions = STANDBY, 0
            if el.start_trigger is not None:
                el.start_trigger.reset()
            for a in el.actions:
                a.done = False
            for c in el.children:
                reset(c)

        for m in g.children:
            reset(m)
        g.start(ctx)
        for m in g.children:
            m.start(ctx)


def _all_complete(elements: list[Element]) -> bool:
    """Whether every element is complete (a plain loop: the storyboard asks it many times a step)."""
    for el in elements:
        if el.state != COMPLETE:
            return False
    return True
