"""One way to get a Dask cluster for the commands that offer ``--executor dask`` (sweeps, libraries):
the scheduler the user names, reached within a bounded wait and refused in one line when nobody
answers, or a LocalCluster on this machine's cores; closed again whatever happens."""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager

from vei_scenario.errors import VeiInputError

#: How long to wait for a named scheduler before saying it cannot be reached (s).
SCHEDULER_TIMEOUT_S = 10


@contextmanager
def dask_client(scheduler: str | None) -> Iterator[object]:
    """A ``dask.distributed.Client`` on ``scheduler`` (an address), or on a LocalCluster when None."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise VeiInputError(
            None, "--executor dask", "needs dask.distributed: pip install 'vei-scenario[dask]'"
        ) from None
    cluster = None
    if scheduler:
        try:
            client = Client(scheduler, timeout=SCHEDULER_TIMEOUT_S)
        except (OSError, TimeoutError, ValueError) as exc:
            raise VeiInputError(
                None,
                "--scheduler",
                f"cannot reach a Dask scheduler at {scheduler!r} within {SCHEDULER_TIMEOUT_S} s ({exc})",
            ) from None
    else:
        cluster = LocalCluster(
            n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True, host="127.0.0.1",
            dashboard_address=None,
        )  # fmt: skip
        client = Client(cluster)
    try:
        yield client
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
