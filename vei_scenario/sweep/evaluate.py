"""Evaluate variants: one run and its metrics per variant, on local cores or a Dask cluster.

A variant that fails (a user error in its values, a model refusing its parameters) becomes a row with
status ``error`` and the message; it never stops the sweep. Results come back in variant order, so
the local and the Dask paths give identical catalogs.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Iterable
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from vei_scenario.errors import VeiError, VeiInputError
from vei_scenario.metrics import MetricConfig, PairSeries, compute_metrics
from vei_scenario.sweep import forked

#: The least work (s, on one core) worth forking worker processes for: below it they cost more than
#: they save (the fork, each one's first touch of the parent's memory: about 7 ms together on 2 cores).
#: Measured with Euro NCAP variation files on 2 cores: 9 variants of 4.5 ms ran 1.4x faster in two
#: workers, 3 variants of 6 ms slower. The work is estimated from the first variant, which also reads
#: the files (about twice a later variant's time; three times in some). The rest is forked only when
#: the rest is more than two variants a process: measured on 2 cores, the rest of 2, 3 and 4 variants
#: (CPTAfo, CCRb 2023, CA-FC Standard CBLA) ran 13 %, 21 % and 0 % slower forked than in one process.
POOL_WORTH_S = 0.03
#: The same where workers are spawned, not forked (macOS, Windows): each starts Python, imports vei
#: and reads the files again (0.2-0.4 s).
SPAWN_WORTH_S = 1.0
#: The longest a sweep waits for its worker processes (s) before it stops with one line.
WATCHDOG_S = 6 * 3600.0


def evaluate_variant(
    scenario: str, values: dict[str, str], dt: float, zone_ttc: str = "2d", controllers: tuple = ()
) -> dict:
    """Run one variant (``controllers``: the systems under test); a row: status, error and the metrics
    of ``vei run``. A fault of a user's controller is the variant's row, as any other error."""
    from vei_scenario.interpreter import run_scenario

    try:
        result = run_scenario(scenario, values, dt, controllers=controllers)
        cfg = MetricConfig(zone_ttc=zone_ttc)
        metrics = compute_metrics(PairSeries.from_run(result), cfg) if result.threat else {}
        return {"status": "ok", "error": "", "metrics": metrics}
    except VeiError as exc:
        return {"status": "error", "error": str(exc), "metrics": {}}
    except (ValueError, ArithmeticError) as exc:  # a model refusing the values (e.g. a negative mass)
        return {"status": "error", "error": f"{type(exc).__name__}: {exc}", "metrics": {}}


def default_controllers(scenario: str | Path, values: dict[str, str], dt: float, controllers: tuple = ()) -> list[str]:
    """What the scenario built with ``values`` plays as the default controller although it names another
    (a controller type vei has no model of, e.g. a misspelt planner): one sentence each. A search for
    failures of a system that is not there would report the scenario's, so falsify and probability
    refuse these (unless allowed). None when the scenario cannot be built (its runs will say why)."""
    from vei_scenario.interpreter import Simulation, load_scenario
    from vei_scenario.interpreter.controllers import DefaultController

    try:
        sim = Simulation(load_scenario(scenario, values), dt, controllers=controllers)
    except (VeiError, ValueError, ArithmeticError):
        return []
    return [
        f"{e.name}'s controller {c.name!r} names no model vei has (it would play as the default controller)"
        for e in sim.ctx.entities.values()
        for c in e.controllers.values()
        if isinstance(c, DefaultController)
    ]


def refuse_default_controllers(scenario, values: dict[str, str], dt: float, controllers: tuple, allow: bool) -> None:
    """One line for the first controller that would play as the default one, unless ``allow``."""
    if allow:
        return
    found = default_controllers(scenario, values, dt, controllers)
    if found:
        raise VeiInputError(
            scenario, "controller", f"{found[0]}; plug in the system with --controller ENTITY=FILE.py:CLASS, or "
            "give --allow-default-controller to search the scenario as it plays"
        )  # fmt: skip


_NATIVE: dict[tuple[str, float, str], object] = {}


def _native_engine(scenario: str, dt: float, zone_ttc: str = "2d", controllers: tuple = ()):
    """The sweep kernel for a vei-compiled closed loop (cached per process), or None for other files and
    wherever a user's controller drives (it runs in the interpreter)."""
    if controllers:
        return None
    return _loop_batch(scenario, dt, zone_ttc)


def _loop_batch(scenario: str, dt: float, zone_ttc: str = "2d"):
    from vei_scenario.batch import NativeBatch
    from vei_scenario.loop import LoopScene, NotALoop

    key = (scenario, dt, zone_ttc)
    if key not in _NATIVE:
        try:
            _NATIVE[key] = NativeBatch(LoopScene(scenario, dt), MetricConfig(zone_ttc=zone_ttc))
        except (NotALoop, VeiError):
            _NATIVE[key] = None
    return _NATIVE[key]


_KERNEL_FMU: dict[tuple, object] = {}


def _kernel_fmu(scenario: str, dt: float, zone_ttc: str, controllers: tuple):
    """The sweep kernel with the plugged native FMU on the ego (:func:`vei_scenario.batch.fmu_ego.kernel_fmu`),
    cached per process, or None (the variants then run in the interpreter)."""
    if not controllers or not forked.available():
        return None
    key = (scenario, dt, zone_ttc, controllers)
    if key not in _KERNEL_FMU:
        from vei_scenario.batch.fmu_ego import kernel_fmu

        _KERNEL_FMU[key] = kernel_fmu(_loop_batch(scenario, dt, zone_ttc), controllers)
    return _KERNEL_FMU[key]


def _evaluate_kernel_fmu(fmu, scenario, variants, dt, workers, progress, zone_ttc, controllers) -> list[dict]:
    """The kernel with the FMU on the ego, in forked children (:mod:`vei_scenario.sweep.contained`: a
    crash or a hang in the FMU fails its variant alone); values it cannot take through the interpreter."""
    from vei_scenario.sweep.contained import run_contained

    ok = [i for i, v in enumerate(variants) if fmu.scene.kernel_accepts(v)]
    groups = fmu.scene.model_groups(ok, variants, len(variants) or 1)

    def rows(indices: list[int], page) -> list[dict]:
        return fmu.rows([variants[i] for i in indices], page)

    def death_row(how: str, t: float, call: int, timed_out: bool) -> dict:
        return {"status": "error", "error": fmu.death_line(how, t, call, timed_out), "metrics": {}}

    got = run_contained(rows, groups, workers, death_row, fmu.call_bound_s, progress, WATCHDOG_S)
    out = []
    for i, v in enumerate(variants):
        if i not in got:
            got[i] = evaluate_variant(scenario, v, dt, zone_ttc, controllers)
            if progress:
                progress(1)
        out.append(got[i])
    return out


def runs_in_kernel(scenario: str, dt: float, zone_ttc: str = "2d") -> bool:
    """Whether the sweep kernel runs ``scenario`` (a vei-compiled closed loop), the interpreter else."""
    return _native_engine(scenario, dt, zone_ttc) is not None


def release_native(scenario: str, dt: float, zone_ttc: str = "2d") -> None:
    """Forget the sweep kernel's scene of ``scenario`` (and a native FMU's on it): a caller that runs
    many scenarios once each (a benchmark over a library) frees each one's arrays (1.6 MB for a
    generated clip) when done with it."""
    _NATIVE.pop((scenario, dt, zone_ttc), None)
    for key in [k for k in _KERNEL_FMU if k[:3] == (scenario, dt, zone_ttc)]:
        del _KERNEL_FMU[key]  # (it holds the scene too)


def _chunk(
    scenario: str, chunk: list[dict[str, str]], dt: float, zone_ttc: str = "2d", controllers: tuple = ()
) -> list[dict]:
    """Rows of a chunk: a vei-compiled loop's valid variants through the sweep kernel (rows identical
    to ``vei run``'s: tests/test_batch_native.py), everything else and invalid values through the
    interpreter, variant by variant; a native FMU on a loop's ego through the kernel in a forked child."""
    fmu = _kernel_fmu(scenario, dt, zone_ttc, controllers)
    if fmu is not None:
        return _evaluate_kernel_fmu(fmu, scenario, chunk, dt, 1, None, zone_ttc, controllers)
    native = _native_engine(scenario, dt, zone_ttc, controllers)
    rows: list[dict | None] = [None] * len(chunk)
    if native is not None:
        ok = [i for i, v in enumerate(chunk) if native.scene.kernel_accepts(v)]
        for i, m in zip(ok, native.metrics([chunk[i] for i in ok])):
            rows[i] = {"status": "ok", "error": "", "metrics": m}
    return [
        r if r is not None else evaluate_variant(scenario, v, dt, zone_ttc, controllers) for r, v in zip(rows, chunk)
    ]


def _chunks(variants: list[dict[str, str]], size: int) -> list[list[dict[str, str]]]:
    return [variants[i : i + size] for i in range(0, len(variants), size)]


def evaluate_local(
    scenario: str,
    variants: list[dict[str, str]],
    dt: float,
    workers: int | None = None,
    progress: Callable[[int], None] | None = None,
    zone_ttc: str = "2d",
    controllers: tuple = (),
) -> list[dict]:
    """Rows of ``variants`` in variant order on ``workers`` local cores (default: all): a vei-compiled
    loop through the sweep kernel on threads, any other scenario (and any with a user's controller,
    ``controllers``) through the interpreter, in this process or, when the work repays them, in forked
    workers beside it. A participant that can be instantiated only once per process has each variant
    run in a spawned process of its own (a script calling this then needs the usual
    ``if __name__ == "__main__":`` guard of spawned multiprocessing)."""
    workers = workers or os.cpu_count() or 1
    native = _native_engine(scenario, dt, zone_ttc, controllers)
    if native is not None:
        return _evaluate_native(native, scenario, variants, dt, workers, progress, zone_ttc)
    fmu = _kernel_fmu(scenario, dt, zone_ttc, controllers)
    if fmu is not None:
        return _evaluate_kernel_fmu(fmu, scenario, variants, dt, workers, progress, zone_ttc, controllers)
    if any(_once_per_process(c) for c in controllers):
        return _evaluate_one_per_process(scenario, variants, dt, workers, progress, zone_ttc, controllers)
    out: list[dict] = []
    if workers > 1 and len(variants) > 1:
        # The first variant here: it reads the scenario's files (the workers then inherit them read)
        # and says what the rest will cost. Work that would not repay the workers stays here.
        started = time.perf_counter()
        out.append(evaluate_variant(scenario, variants[0], dt, zone_ttc, controllers))
        if progress:
            progress(1)
        rest = len(variants) - 1
        worth = POOL_WORTH_S if forked.available() else SPAWN_WORTH_S
        if (time.perf_counter() - started) * rest < worth or rest <= 2 * workers:
            workers = 1  # (a process with two variants or fewer pays more for its first touch than it saves)
        variants = variants[1:]
    if workers == 1 or len(variants) <= 1:
        for v in variants:
            out.append(evaluate_variant(scenario, v, dt, zone_ttc, controllers))
            if progress:
                progress(1)
        return out
    if forked.available():

        def row(i: int) -> dict:
            return evaluate_variant(scenario, variants[i], dt, zone_ttc, controllers)

        return out + forked.run_forked(row, len(variants), workers, progress, WATCHDOG_S)
    return out + _evaluate_pool(scenario, variants, dt, workers, progress, zone_ttc, controllers)


def _evaluate_pool(scenario, variants, dt, workers, progress, zone_ttc: str = "2d", controllers=()) -> list[dict]:
    """Where processes cannot be forked (macOS, Windows): a pool of spawned workers, chunk by chunk."""
    from concurrent.futures.process import BrokenProcessPool

    from vei_scenario.errors import VeiInputError

    chunks = _chunks(variants, max(1, min(256, -(-len(variants) // workers))))
    out: list[dict] = []
    try:
        with ProcessPoolExecutor(max_workers=workers) as pool:
            n = len(chunks)
            # the watchdog: a chunk that does not come back in time stops the sweep with one line
            results = pool.map(
                _chunk, [scenario] * n, chunks, [dt] * n, [zone_ttc] * n, [controllers] * n, timeout=WATCHDOG_S
            )
            for c, rows in zip(chunks, results):
                out.extend(rows)
                if progress:
                    progress(len(c))
    except BrokenProcessPool:
        raise VeiInputError(None, "--workers", "a worker process died (out of memory, or killed)") from None
    except TimeoutError:
        raise VeiInputError(None, "sweep", f"no result from the workers within {WATCHDOG_S:g} s") from None
    return out


def _once_per_process(spec) -> bool:
    """Whether ``spec`` is an OSMP participant that declares it can be instantiated only once per process
    (a pythonfmu build): it runs in vei's process, so no second run may share that process with it."""
    try:
        return bool(spec.osmp and spec.load().once_per_process)
    except VeiError:  # (a controller that does not load: each variant's run says why)
        return False


def _evaluate_one_per_process(
    scenario, variants, dt, workers, progress, zone_ttc: str = "2d", controllers=()
) -> list[dict]:
    """Each variant in a fresh process of its own: a participant instantiable once per process is then
    instantiated once in each. The processes are spawned (a forked one would inherit this process's
    instance), ``workers`` at a time; rows come back in variant order. A process that ends without its
    row (the participant crashed it) makes that variant's row an error; no row within the watchdog
    stops the sweep with one line, and the processes still running are killed, not waited for."""
    import multiprocessing
    from multiprocessing.connection import wait

    context = multiprocessing.get_context("spawn")
    rows: list[dict] = [{}] * len(variants)
    running: dict = {}  # the end a row comes on -> (variant index, its process)
    deadline = time.monotonic() + WATCHDOG_S
    started = 0
    try:
        for _ in variants:
            while started < len(variants) and len(running) < max(1, workers):
                end, send = context.Pipe(duplex=False)
                args = (send, scenario, variants[started], dt, zone_ttc, controllers)
                process = context.Process(target=_evaluate_into, args=args, daemon=True)
                process.start()
                send.close()
                running[end], started = (started, process), started + 1
            ready = wait(list(running), timeout=max(0.0, deadline - time.monotonic()))
            if not ready:
                raise VeiInputError(None, "sweep", f"no result from the workers within {WATCHDOG_S:g} s")
            end = ready[0]
            i, process = running.pop(end)
            try:
                rows[i] = end.recv()
            except EOFError:
                process.join()
                died = f"the process running this variant ended without its row (exit code {process.exitcode})"
                rows[i] = {"status": "error", "error": died, "metrics": {}}
            end.close()
            process.join()
            if progress:
                progress(1)
    finally:
        for _, process in running.values():
            process.kill()
            process.join()
    return rows


def _evaluate_into(send, *args) -> None:
    """Run one variant (:func:`evaluate_variant` of ``args``) in a spawned process and send its row on
    ``send``; the process then ends without the finalisers of the native libraries it loaded."""
    from vei_scenario.process_end import end_process

    send.send(evaluate_variant(*args))
    send.close()
    end_process(0)


def _evaluate_native(native, scenario, variants, dt, workers, progress, zone_ttc: str = "2d") -> list[dict]:
    """The compiled kernel on ``workers`` threads, 500 variants a task; values it cannot take go
    through the interpreter, which reports what is wrong with them."""
    from concurrent.futures import ThreadPoolExecutor

    scene = native.scene
    rows: list[dict | None] = [None] * len(variants)
    ok = [i for i, v in enumerate(variants) if scene.kernel_accepts(v)]
    tasks = scene.model_groups(ok, variants, 500)  # (variants that share their model parameters)

    def task(t: list[int]):  # preparing (Python) overlaps with the other threads' kernel runs (no GIL)
        return native.run(native.prepare([variants[i] for i in t]))

    with ThreadPoolExecutor(max_workers=workers) as pool:
        for t, (out, _) in zip(tasks, pool.map(task, tasks)):
            for i, m in zip(t, native.rows(out)):
                rows[i] = {"status": "ok", "error": "", "metrics": m}
            if progress:
                progress(len(t))
    for i, r in enumerate(rows):
        if r is None:
            rows[i] = evaluate_variant(scenario, variants[i], dt, zone_ttc)
            if progress:
                progress(1)
    return rows


#: How long vei waits for a Dask scheduler to answer (s).


def evaluate_dask(
    scenario: str,
    variants: list[dict[str, str]],
    dt: float,
    scheduler: str | None,
    progress: Callable[[int], None] | None = None,
    zone_ttc: str = "2d",
    controllers: tuple = (),
) -> list[dict]:
    """The same evaluation on a Dask distributed cluster (``scheduler`` address, or a LocalCluster); a
    user's controller is loaded by each worker from its file (which the workers must see)."""
    from vei_scenario.dask_cluster import dask_client

    with dask_client(scheduler) as client:
        from dask.distributed import as_completed

        chunks = _chunks(variants, max(1, min(256, len(variants) // 8 or 1)))
        futures = [client.submit(_chunk, scenario, c, dt, zone_ttc, controllers, pure=False) for c in chunks]
        index = {f.key: i for i, f in enumerate(futures)}
        results: list[list[dict] | None] = [None] * len(futures)
        for fut in as_completed(futures):
            i = index[fut.key]
            results[i] = fut.result()
            if progress:
                progress(len(chunks[i]))
        return [row for rows in results for row in rows]


def iter_rows(variants: Iterable[dict[str, str]], outcomes: Iterable[dict]) -> list[dict]:
    return [{"variant": i, "parameters": v, **o} for i, (v, o) in enumerate(zip(variants, outcomes))]
