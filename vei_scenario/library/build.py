"""``vei compile CLIPS/ -o LIBRARY/``: every clip of a folder compiled into a scenario library.

Why a library and not a loop over ``vei compile``: a dataset has hundreds of clips, some of them bad
(malformed, hostile, without an e-scooter, two with one id); a loop stops at the first, and a rerun
after one new clip compiles everything again. Here:

* each clip (``*.json`` in the folder, sorted by name) compiles into ``scenarios/NAME/`` (its
  ``scenario.xosc``, ``.xodr``, ``.variations.xosc`` and a ``thumbnail.svg``), in worker processes
  on the local cores or on a Dask cluster; a clip that fails is a row with its reason and never
  stops the rest;
* a clip whose input is unchanged is not compiled again: its key (SHA-256 of the clip's bytes, its
  map's bytes, the compile options and vei's version) is kept in ``scenarios/NAME/row.json``, written
  last, and a rerun takes the row from there when the key and the files are still there;
* ``library.json`` (every row, ranked by closeness to a collision: :mod:`vei_scenario.library.rows`)
  and ``library.html`` are written at the end, the same bytes for the same inputs on any executor.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path

from vei_scenario import __version__
from vei_scenario.atomic_io import write_bytes_atomic
from vei_scenario.compiler import CompileOptions
from vei_scenario.errors import VeiError, VeiInputError
from vei_scenario.library.rows import error_row, ranked

#: The format of library.json and of each scenario's row.json (a change invalidates every kept row).
LIBRARY_FORMAT = "vei-library/1"
#: A clip file larger than this is refused unread (bytes): an interaction clip is kilobytes to a few MB.
MAX_CLIP_BYTES = 256 * 1024 * 1024
SCENARIO_FILES = ("scenario.xosc", "scenario.xodr", "scenario.variations.xosc", "thumbnail.svg")


@dataclass(frozen=True)
class Job:
    """One clip to compile: its file, the folder its outputs go to, its key (None: a row is known
    already, ``row``), and the options."""

    file: str  # the clip's file name within the input folder
    clip_path: str
    out_dir: str
    folder: str  # scenarios/NAME, relative to the library
    key: str | None
    row: dict | None
    options: CompileOptions


@dataclass
class LibraryResult:
    rows: list[dict]
    compiled: int  # compiled in this run
    kept: int  # taken from an earlier run
    written: list[Path]

    @property
    def failed(self) -> list[dict]:
        return [r for r in self.rows if r["status"] != "ok"]


def _folder_name(stem: str, taken: set[str]) -> str:
    """A safe, unique folder name for a clip file's stem."""
    name = re.sub(r"[^A-Za-z0-9_.-]", "_", stem)[:100] or "clip"
    if name.startswith("."):
        name = "_" + name
    base, k = name, 2
    while name.lower() in taken:
        name, k = f"{base}-{k}", k + 1
    taken.add(name.lower())
    return name


def _peek_id(doc) -> str | None:
    """The id a clip document declares (vei-clip ``id``, OpenLABEL ``metadata.name``), if any."""
    if not isinstance(doc, dict):
        return None
    if "openlabel" in doc:
        meta = doc["openlabel"].get("metadata") if isinstance(doc["openlabel"], dict) else None
        name = meta.get("name") if isinstance(meta, dict) else None
        return name if isinstance(name, str) else None
    return doc["id"] if isinstance(doc.get("id"), str) else None


def _map_reference(doc, clip_path: Path) -> Path | None:
    ref = doc.get("map", {}).get("osm") if isinstance(doc, dict) and isinstance(doc.get("map"), dict) else None
    if ref is None and isinstance(doc, dict) and isinstance(doc.get("openlabel"), dict):
        vei = (doc["openlabel"].get("metadata") or {}).get("vei_clip")
        ref = (vei.get("map") or {}).get("osm") if isinstance(vei, dict) and isinstance(vei.get("map"), dict) else None
    if not isinstance(ref, str):
        return None
    return (clip_path.parent / ref).resolve()


def _options_text(opts: CompileOptions) -> str:
    d = asdict(opts)
    d["osm"] = None  # (its bytes are hashed instead of its path)
    return json.dumps(d, sort_keys=True, default=str)


def plan(clips_dir: Path, out_dir: Path, opts: CompileOptions) -> list[Job]:
    """The jobs for every clip file of ``clips_dir``: read once to name it, find duplicate ids and
    hash it; a clip that cannot even be read is a row at once."""
    from vei_scenario.clip.loader import read_json

    files = sorted(p for p in clips_dir.iterdir() if p.suffix.lower() == ".json" and not p.name.startswith("."))
    map_digest: dict[Path, str] = {}
    ids: dict[str, str] = {}
    taken: set[str] = set()
    jobs = []
    options = _options_text(opts)
    for p in files:
        folder = "scenarios/" + _folder_name(p.stem, taken)
        row = None
        key = None
        try:
            if not p.is_file():
                raise VeiInputError(p.name, "", "not a regular file")
            if p.stat().st_size > MAX_CLIP_BYTES:
                raise VeiInputError(
                    p.name, "", f"{p.stat().st_size} bytes: larger than a clip ({MAX_CLIP_BYTES} at most)"
                )
            data = p.read_bytes()
            doc = read_json(p)
            cid = _peek_id(doc)
            if cid is not None:
                if cid in ids:
                    raise VeiInputError(p.name, "id", f"duplicate clip id {cid!r} (also in {ids[cid]}, compiled)")
                ids[cid] = p.name
            h = hashlib.sha256()
            h.update(f"{LIBRARY_FORMAT}\0{__version__}\0{options}\0".encode())
            h.update(data)
            osm = opts.osm or (None if opts.no_map else _map_reference(doc, p))
            if osm is not None and osm.is_file():
                if osm not in map_digest:
                    map_digest[osm] = hashlib.sha256(osm.read_bytes()).hexdigest()
                h.update(map_digest[osm].encode())
            key = h.hexdigest()
        except VeiInputError as exc:
            row = error_row(_relative_message(exc, clips_dir))
        except OSError as exc:
            row = error_row(f"{p.name}: cannot read: {exc.strerror or exc}")
        jobs.append(Job(p.name, str(p), str(out_dir / folder), folder, key, row, opts))
    return jobs


def _relative_message(exc: VeiError, clips_dir: Path) -> str:
    """The error's one line, naming the clip by its file name (the library is moved, not its paths)."""
    if isinstance(exc, VeiInputError) and exc.file is not None:
        file = Path(exc.file)
        try:
            file = file.resolve().relative_to(clips_dir.resolve())
        except ValueError:
            file = Path(file.name) if file.is_absolute() else file
        exc = VeiInputError(str(file), exc.where, exc.reason)
    return " ".join(str(exc).split())


def _kept_row(job: Job) -> dict | None:
    """The row of an earlier run, if it was compiled from the same input and its files are there."""
    if job.key is None:
        return None
    try:
        kept = json.loads((Path(job.out_dir) / "row.json").read_text("utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(kept, dict) or kept.get("key") != job.key or not isinstance(kept.get("row"), dict):
        return None
    row = kept["row"]
    if row.get("status") == "ok":
        lib = Path(job.out_dir).parent.parent
        if not all((lib / f).is_file() for f in (row.get("outputs") or {}).values()):
            return None
    return row


def compile_job(job: Job) -> dict:
    """Compile one clip into its folder (a worker's task): its row, never an exception."""
    if job.row is not None:
        return job.row
    clips_dir = Path(job.clip_path).parent
    try:
        return _compile(job, clips_dir)
    except VeiError as exc:
        row = error_row(_relative_message(exc, clips_dir))
    except RecursionError:
        row = error_row(f"{job.file}: nested too deeply to read")
    except OSError as exc:
        row = error_row(f"{job.file}: {exc.strerror or exc}")
    except Exception as exc:  # a bug in vei on this clip: its row says so, the rest go on
        row = error_row(f"{job.file}: internal error ({type(exc).__name__}: {' '.join(str(exc).split())[:300]})")
    _write_row(job, row)
    return row


def _write_row(job: Job, row: dict) -> None:
    if job.key is not None:
        text = json.dumps({"format": LIBRARY_FORMAT, "key": job.key, "row": row}, indent=1) + "\n"
        write_bytes_atomic(Path(job.out_dir) / "row.json", text.encode("utf-8"))


def _compile(job: Job, clips_dir: Path) -> dict:
    from vei_scenario.compiler import compile_clip
    from vei_scenario.library.rows import ok_row
    from vei_scenario.library.thumbnail import thumbnail_svg

    out = Path(job.out_dir)
    (out / "row.json").unlink(missing_ok=True)  # (a half-done folder is never taken for a done one)
    result = compile_clip(job.clip_path, out / "scenario.xosc", job.options)
    xodr = (out / "scenario.xodr").read_bytes()
    write_bytes_atomic(out / "thumbnail.svg", thumbnail_svg(result, xodr).encode("utf-8"))
    outputs = {
        "scenario": f"{job.folder}/scenario.xosc",
        "road": f"{job.folder}/scenario.xodr",
        "variations": f"{job.folder}/scenario.variations.xosc",
        "thumbnail": f"{job.folder}/thumbnail.svg",
    }
    row = ok_row(result, outputs)
    row["warnings"] = [" ".join(w.replace(str(clips_dir.resolve()) + os.sep, "").split()) for w in row["warnings"]]
    _write_row(job, row)
    return row


def _run_local(jobs: list[Job], workers: int, progress: Callable[[int], None] | None) -> list[dict]:
    from vei_scenario.sweep import forked

    if workers > 1 and len(jobs) > 1 and forked.available():
        return forked.run_forked(lambda i: compile_job(jobs[i]), len(jobs), workers, progress)
    out = []
    for job in jobs:
        out.append(compile_job(job))
        if progress:
            progress(1)
    return out


def _run_dask(jobs: list[Job], scheduler: str | None, progress: Callable[[int], None] | None) -> list[dict]:
    """The jobs on a Dask cluster (``scheduler``, or a LocalCluster on this machine's cores). The
    workers write the scenario files, so a remote cluster needs the library folder on a file system
    they share with this machine."""
    try:
        from dask.distributed import Client, LocalCluster, as_completed
    except ImportError:
        raise VeiInputError(
            None, "--executor dask", "needs dask.distributed: pip install 'vei-scenario[dask]'"
        ) from None
    from vei_scenario.sweep.evaluate import SCHEDULER_TIMEOUT_S

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
            n_workers=os.cpu_count() or 1,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address=None,
        )
        client = Client(cluster)
    try:
        futures = [client.submit(compile_job, j, pure=False) for j in jobs]
        index = {f.key: i for i, f in enumerate(futures)}
        rows: list[dict | None] = [None] * len(jobs)
        for fut in as_completed(futures):
            rows[index[fut.key]] = fut.result()
            if progress:
                progress(1)
        return rows  # type: ignore[return-value]
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def compile_library(
    clips_dir: str | Path,
    out_dir: str | Path,
    options: CompileOptions | None = None,
    executor: str = "local",
    scheduler: str | None = None,
    workers: int | None = None,
    progress: Callable[[int], None] | None = None,
) -> LibraryResult:
    """Compile every clip of ``clips_dir`` into the library ``out_dir`` (see the module's docstring)."""
    from vei_scenario.library.page import library_html

    clips_dir, out_dir = Path(clips_dir), Path(out_dir)
    opts = options or CompileOptions()
    if opts.threat is not None or opts.variants_dir is not None:
        flag = "--threat" if opts.threat is not None else "--variants"
        raise VeiInputError(None, flag, "applies to one clip, not to a folder of clips")
    if not clips_dir.is_dir():
        raise VeiInputError(clips_dir, "", "not a folder")
    if executor not in ("local", "dask"):
        raise VeiInputError(None, "--executor", f"{executor!r} is not local or dask")
    if out_dir.resolve() == clips_dir.resolve() or clips_dir.resolve() in out_dir.resolve().parents:
        raise VeiInputError(out_dir, "-o", "the library must not be inside the folder of clips")
    jobs = plan(clips_dir, out_dir, opts)
    if not jobs:
        raise VeiInputError(clips_dir, "", "no clip files (*.json) in the folder")
    rows: list[dict | None] = [None] * len(jobs)
    todo = []
    kept = 0
    for i, job in enumerate(jobs):
        row = job.row or _kept_row(job)
        if row is not None:
            rows[i] = row
            kept += job.row is None
            if progress:
                progress(1)
        else:
            todo.append(i)
    todo_jobs = [jobs[i] for i in todo]
    if todo_jobs:
        if executor == "dask":
            done = _run_dask(todo_jobs, scheduler, progress)
        else:
            done = _run_local(todo_jobs, workers or os.cpu_count() or 1, progress)
        for i, row in zip(todo, done):
            rows[i] = row
    full = [{"file": job.file, **row} for job, row in zip(jobs, rows)]  # type: ignore[arg-type]
    table = ranked(full)
    doc = {
        "format": LIBRARY_FORMAT,
        "generator": f"vei-scenario {__version__}",
        "clips": len(table),
        "compiled": sum(1 for r in table if r["status"] == "ok"),
        "failed": sum(1 for r in table if r["status"] != "ok"),
        "order": "closeness to a collision: collision_margin_s, then conflict_margin_s, then min_centre_distance_m",
        "scenarios": table,
    }
    json_path, html_path = out_dir / "library.json", out_dir / "library.html"
    write_bytes_atomic(json_path, (json.dumps(doc, indent=1, allow_nan=False) + "\n").encode("utf-8"))
    write_bytes_atomic(html_path, library_html(doc).encode("utf-8"))
    return LibraryResult(table, len(todo_jobs), kept, [json_path, html_path])
