"""Hostile inputs and faults across the commands: each ends as one line ``vei: error: ...`` and exit
2 (or a correct result), nothing half-written, no traceback, no hang, no process left behind."""

from __future__ import annotations

import csv
import errno
import os
import re
import signal
import subprocess
import sys
import time
import uuid
from pathlib import Path

import numpy as np
import pytest

from conftest import EXAMPLES
from vei_scenario.cli import main


def _refused(capsys, argv, *needles) -> str:
    code = main(argv)
    err = capsys.readouterr().err
    assert code == 2, err
    assert err.count("\n") == 1 and err.startswith("vei: error: ") and "Traceback" not in err, err
    for n in needles:
        assert n in err, err
    return err


@pytest.fixture(scope="module")
def scenario(compiled):
    return str(compiled["case_study"].written[0])


def test_non_finite_parameter_values_are_refused(scenario, capsys, tmp_path):
    _refused(capsys, ["run", scenario, "--param", "TimeShift=inf"], "TimeShift", "not a finite number")
    _refused(capsys, ["run", scenario, "--param", "TimeShift=nan", "-o", str(tmp_path / "r")], "not a finite number")
    assert not (tmp_path / "r").exists()
    _refused(capsys, ["fmu", "system", scenario, "--param", "EgoCruiseSpeed=inf", "-o", str(tmp_path / "l.ssp")])
    _refused(capsys, ["fmu", "build", "sfm", "--scenario", scenario, "--param", "TimeShift=nan", "-o", str(tmp_path)])
    _refused(capsys, ["sweep", scenario, "--vary", "TimeShift=nan,1", "-o", str(tmp_path / "s")])
    assert not any(tmp_path.iterdir())


@pytest.mark.parametrize(
    "expression, reason",
    [
        ("${1e400 % 1}", "number 1e400 is out of range"),  # (found by the fuzz suite: a math domain error)
        ("${1e300 * 1e300 % 2}", "has no remainder"),
        ("${1e300 * 1e300}", "is not finite"),
        ("${5 % (2 - 2)}", "division by zero"),
    ],
)
def test_expressions_beyond_a_double_are_one_line(tmp_path, capsys, expression, reason):
    """A literal or an intermediate that overflows a double is refused where the expression stands."""
    from xosc_parts import one_car

    path = tmp_path / "s.xosc"
    path.write_text(one_car(expression))
    err = _refused(capsys, ["run", str(path), "-o", str(tmp_path / "out")], reason, "s.xosc: line ")
    assert "Traceback" not in err and not (tmp_path / "out").exists()


def test_a_distance_kept_to_the_actor_itself(tmp_path, capsys):
    """A LongitudinalDistanceAction whose reference is its own actor plays as esmini plays it (its gap
    is 0, so it brakes to a standstill at its deceleration; before, the core's quiet stretch refused it
    with a ValueError); a LateralDistanceAction to itself has no side to be on and is refused in one line.
    (Both found by a mutation fuzz of esmini's examples.)"""
    from xosc_parts import one_car

    from vei_scenario.interpreter import run_scenario

    keep = (
        '<PrivateAction><LongitudinalAction><LongitudinalDistanceAction entityRef="Ego" timeGap="2" '
        'freespace="true" continuous="true" coordinateSystem="entity" displacement="any"><DynamicConstraints '
        'maxAcceleration="3" maxDeceleration="3" maxSpeed="30"/></LongitudinalDistanceAction></LongitudinalAction>'
        "</PrivateAction>"
    )
    path = tmp_path / "keep.xosc"
    path.write_text(one_car("10", end=8.0, action=keep))
    ego = run_scenario(path).traces["Ego"]
    assert ego.speed[0] == 10.0 and ego.speed[100] == pytest.approx(10.0 - 3.0, abs=0.01)  # (at maxDeceleration)
    assert 0.0 <= ego.speed[-1] < 1e-3  # (the spring's tail: stopped)
    # a speed relative to its own (a factor of 0.99 each step, continuously): 10 * 0.99^(k + 1) at sample k
    # (the storyboard's pass before t = 0 is logged takes the first); before, the same ValueError
    own = (
        '<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" '
        'dynamicsDimension="time"/><SpeedActionTarget><RelativeTargetSpeed entityRef="Ego" value="0.99" '
        'speedTargetValueType="factor" continuous="true"/></SpeedActionTarget></SpeedAction></LongitudinalAction>'
        "</PrivateAction>"
    )
    path.write_text(one_car("10", end=3.0, action=own))
    speed = run_scenario(path).traces["Ego"].speed
    assert speed == pytest.approx(10.0 * 0.99 ** np.arange(1, speed.size + 1), rel=1e-12)
    lateral = keep.replace("LongitudinalAction><LongitudinalDistanceAction", "LateralAction><LateralDistanceAction")
    lateral = lateral.replace('timeGap="2"', 'distance="1"').replace(
        "LongitudinalDistanceAction></Longitudinal", "LateralDistanceAction></Lateral"
    )
    lateral = lateral.replace('displacement="any"', 'displacement="leftToReferencedEntity"')
    path.write_text(one_car("10", end=8.0, action=lateral))
    _refused(capsys, ["run", str(path)], "line ", "LateralDistanceAction: the reference entity is the actor itself")


@pytest.mark.parametrize(
    "argv",
    [
        ["sweep", "S", "--vary", "TimeShift=0:1:1", "-o", "O", "--dt", "0"],
        ["sweep", "S", "--vary", "TimeShift=0:1:1", "-o", "O", "--dt", "-0.01"],
        ["sweep", "S", "--vary", "TimeShift=0:1:1", "-o", "O", "--dt", "1e-9"],
        ["sweep", "S", "--vary", "TimeShift=0:1:1", "-o", "O", "--workers", "-2"],
        ["sweep", "S", "--dist", "D", "-o", "O", "--seed", "-1"],
        ["study", "S", "-o", "O", "--dt", "0"],
        ["risk", "S", "--dt", "nan"],
        ["risk", "S", "--band", "nan:nan"],
        ["fmu", "system", "S", "-o", "O", "--dt", "0"],
        ["fmu", "cosim", "S", "--dt", "inf"],
        ["view", "S", "--dt", "0"],
        ["run", "S", "--dt", "1e400"],
    ],
)
def test_absurd_arguments_are_refused_before_anything_runs(argv, scenario, tmp_path, capsys):
    argv = [scenario if a == "S" else str(tmp_path / "o") if a == "O" else a for a in argv]
    _refused(capsys, argv)
    assert not any(tmp_path.iterdir())


def test_library_entry_points_check_the_step_too(scenario, tmp_path):
    from vei_scenario.errors import VeiInputError
    from vei_scenario.interpreter import run_scenario
    from vei_scenario.sweep import run_sweep

    with pytest.raises(VeiInputError, match="outside"):
        run_scenario(scenario, dt=0.0)
    with pytest.raises(VeiInputError, match="not a finite number"):
        run_sweep(scenario, tmp_path / "s", ["TimeShift=0:1:1"], dt=float("nan"))


def test_output_errors_are_one_line(scenario, tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    _refused(capsys, ["run", scenario, "--no-plots", "-o", str(blocker)], "a file is in the way")
    _refused(capsys, ["run", scenario, "--no-plots", "-o", str(blocker / "sub")], "is a file, not a folder")
    _refused(capsys, ["run", scenario, "--no-plots", "-o", str(tmp_path / ("n" * 300))], "file name too long")
    _refused(capsys, ["compile", str(EXAMPLES / "no_map" / "clip.json"), "-o", str(tmp_path)], ".xosc file")
    (tmp_path / "dir.xosc").mkdir()
    _refused(
        capsys, ["compile", str(EXAMPLES / "no_map" / "clip.json"), "-o", str(tmp_path / "dir.xosc")], "is a folder"
    )
    (tmp_path / "dir.xosc").rmdir()
    _refused(capsys, ["check", str(EXAMPLES / "ci" / "suite.toml"), "--junit", str(blocker / "j.xml")])
    assert blocker.read_text() == "x" and sorted(p.name for p in tmp_path.iterdir()) == ["file"]


@pytest.mark.parametrize("code", [errno.EROFS, errno.ENOSPC, errno.EACCES])
def test_refused_writes_leave_nothing_behind(scenario, tmp_path, capsys, monkeypatch, code):
    """A read-only or full file system refuses the write itself (mocked here; the tmpfs test below
    does it for real where mounting is allowed)."""
    real_fdopen = os.fdopen

    class Refusing:
        def __init__(self, fh):
            self.fh = fh

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.fh.close()

        def write(self, data):
            raise OSError(code, os.strerror(code), str(tmp_path / "run" / "metrics.json"))

    def refusing(fd, mode="r", *args, **kwargs):
        fh = real_fdopen(fd, mode, *args, **kwargs)
        return Refusing(fh) if "w" in mode else fh

    monkeypatch.setattr(os, "fdopen", refusing)
    reason = {errno.EROFS: "read-only", errno.ENOSPC: "no space left", errno.EACCES: "permission denied"}[code]
    _refused(capsys, ["run", scenario, "--no-plots", "-o", str(tmp_path / "run")], reason)
    left = [p for p in (tmp_path / "run").rglob("*")] if (tmp_path / "run").exists() else []
    assert left == []


def _tmpfs(path: Path, options: str) -> bool:
    path.mkdir(parents=True, exist_ok=True)
    if os.geteuid() != 0:
        return False
    return (
        subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(path)], capture_output=True).returncode == 0
    )


def test_a_full_disk_for_real(scenario, tmp_path):
    disk = tmp_path / "disk"
    if not _tmpfs(disk, "size=64k"):
        pytest.skip("cannot mount a small tmpfs here (needs root and mount rights)")
    try:
        proc = subprocess.run(
            [sys.executable, "-m", "vei_scenario", "run", scenario, "-o", str(disk / "run")],
            capture_output=True, text=True,
        )  # fmt: skip
        assert proc.returncode == 2 and proc.stderr.count("\n") == 1, proc.stderr
        assert "no space left" in proc.stderr
        assert not list(disk.rglob("*.tmp")) and not (disk / "run" / "metrics.json").exists()
    finally:
        subprocess.run(["umount", str(disk)], capture_output=True)


def test_a_stale_temporary_of_a_killed_run_is_removed(scenario, tmp_path):
    out = tmp_path / "run"
    out.mkdir()
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    stale = out / f".metrics.json.{dead.pid}.abcd.tmp"
    stale.write_text("half")
    mine = out / f".metrics.json.{os.getpid()}.efgh.tmp"  # a live writer's: kept
    mine.write_text("busy")
    assert main(["run", scenario, "--no-plots", "-o", str(out)]) == 0
    assert not stale.exists() and mine.exists()


def test_killing_a_sweep_leaves_no_plot_worker(scenario, tmp_path):
    marker = f"VEI_TEST_{uuid.uuid4().hex}"
    env = dict(os.environ, VEI_TEST_MARKER=marker, CI="1")
    args = [sys.executable, "-m", "vei_scenario", "sweep", scenario, "--vary", "TimeShift=-1:5:0.001"]
    proc = subprocess.Popen(args + ["--vary", "RiderType=normal,aggressive", "-o", str(tmp_path / "s")], env=env)
    time.sleep(2.5)
    proc.send_signal(signal.SIGKILL)
    proc.wait()

    def survivors() -> list[int]:
        pids = []
        for d in Path("/proc").iterdir():
            if d.name.isdigit():
                try:
                    if marker.encode() in (d / "environ").read_bytes():
                        pids.append(int(d.name))
                except OSError:
                    pass
        return pids

    deadline = time.time() + 5
    while survivors() and time.time() < deadline:
        time.sleep(0.1)
    assert survivors() == []


def test_trajectories_csv_survives_entity_names_with_commas_and_quotes(tmp_path):
    xosc = tmp_path / "names.xosc"
    name = 'Car, "the red one"'
    xosc.write_text(
        f"""<?xml version="1.0"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork/>
<Entities><ScenarioObject name="{name.replace('"', "&quot;")}">
<MiscObject name="x" mass="1" miscObjectCategory="obstacle">
<BoundingBox><Center x="0" y="0" z="0"/><Dimensions width="1" length="1" height="1"/></BoundingBox><Properties/>
</MiscObject></ScenarioObject></Entities>
<Storyboard><Init><Actions/></Init><StopTrigger><ConditionGroup><Condition name="e" delay="0" conditionEdge="none">
<ByValueCondition><SimulationTimeCondition value="0.05" rule="greaterThan"/></ByValueCondition></Condition>
</ConditionGroup></StopTrigger></Storyboard></OpenSCENARIO>"""
    )
    assert main(["run", str(xosc), "--no-plots", "-o", str(tmp_path / "r")]) == 0
    with open(tmp_path / "r" / "trajectories.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert rows and {r["entity"] for r in rows} == {name} and all(len(r) == 8 for r in rows)


def test_suites_with_bad_values_are_refused(tmp_path, capsys, scenario):
    cases = {
        'expect = ["min_ttc_s >= abc"]': "needs a number",
        'expect = ["ttc_zones_s >= 1"]': "is a table",
        'expect = ["safety_index >= nan"]': "not a finite number",
    }
    for expect, needle in cases.items():
        suite = tmp_path / "s.toml"
        suite.write_text(f'[[case]]\nname = "x"\nscenario = "{scenario}"\n{expect}\n')
        _refused(capsys, ["check", str(suite)], needle)
    for head, needle in (("defaults = 3\n", "must be a table"), ('[defaults]\ndt = "fast"\n', "defaults.dt")):
        suite.write_text(head + f'[[case]]\nname = "x"\nscenario = "{scenario}"\nexpect = ["collision == false"]\n')
        _refused(capsys, ["check", str(suite)], needle)
    suite.write_text(f'[[case]]\nname = "a\\u0007b"\nscenario = "{scenario}"\nexpect = ["collision == false"]\n')
    _refused(capsys, ["check", str(suite)], "control characters")
    suite.write_text("a = " + "[" * 5000 + "]" * 5000 + "\n")
    _refused(capsys, ["check", str(suite)])


def test_describe_on_an_ordinary_sentence_finishes(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "vei_scenario", "describe", "The ego vehicle drives on a straight road.", "-o",
         str(tmp_path / "d"), "--count", "4"],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert proc.returncode in (0, 2) and "Traceback" not in proc.stderr


@pytest.mark.parametrize("text", ["a" * 20000, " ," * 50000 + " a van", "A van cut in. " * 1000])
def test_describe_refuses_a_description_longer_than_it_reads(capsys, tmp_path, text):
    """A whole document pasted as a description is refused at once, naming its length and the most read:
    the reader's time and memory grow faster than a text's length (20 000 letters took gigabytes)."""
    _refused(capsys, ["describe", text, "-o", str(tmp_path / "d"), "--count", "1"], "characters long", "10000")
    assert not (tmp_path / "d").exists()


def test_worker_errors_cross_process_boundaries_intact():
    import pickle

    from vei_scenario.errors import VeiInputError

    err = pickle.loads(pickle.dumps(VeiInputError("f.xosc", "line 3", "bad")))
    assert (err.file, err.where, err.reason, str(err)) == ("f.xosc", "line 3", "bad", "f.xosc: line 3: bad")


# --- cases of an independent hostile-input corpus (written without reading vei's code) -------------------


def _clip_text() -> str:
    return (EXAMPLES / "case_study" / "clip.json").read_text()


def _stationary_ego() -> bytes:
    import json

    d = json.loads(_clip_text())
    s0 = d["ego"]["samples"][0]
    for smp in d["ego"]["samples"]:
        smp["lat"], smp["lon"], smp["heading_deg"], smp["speed_mps"] = s0["lat"], s0["lon"], s0["heading_deg"], 0.0
    return json.dumps(d).encode()


def _samples_object() -> bytes:
    import json

    d = json.loads(_clip_text())
    d["ego"]["samples"] = {str(i): s for i, s in enumerate(d["ego"]["samples"])}
    return json.dumps(d).encode()


#: (id, clip bytes, extra arguments, exit code, words the one line must hold)
CORPUS_CLIPS = [
    ("compile_bom", lambda: b"\xef\xbb\xbf" + _clip_text().encode(), 0, ()),
    (
        "compile_huge_int_time",
        lambda: _clip_text().replace('"t": 1715706180.0', '"t": ' + "9" * 5000, 1).encode(),
        2,
        ("invalid JSON", "digits"),
    ),
    ("compile_samples_is_object", _samples_object, 2, ("ego.samples", "must be an array, not an object")),
    ("compile_ego_stationary", _stationary_ego, 2, ("ego.samples", "does not drive")),
]


@pytest.mark.parametrize("case, make, code, needles", CORPUS_CLIPS, ids=[c[0] for c in CORPUS_CLIPS])
def test_corpus_clips(tmp_path, capsys, case, make, code, needles):
    clip = tmp_path / "clip.json"
    clip.write_bytes(make())
    out = tmp_path / "out" / "scenario.xosc"
    argv = ["compile", str(clip), "--no-map", "-o", str(out)]
    if code:
        err = _refused(capsys, argv, *needles)
        assert len(err) < 400 and not (tmp_path / "out").exists()
    else:
        assert main(argv) == 0 and out.is_file()


def test_corpus_clip_convert_onto_its_input(tmp_path, capsys):
    clip = tmp_path / "clip.json"
    clip.write_text(_clip_text())
    before = clip.read_bytes()
    _refused(capsys, ["clip", "convert", str(clip), "-o", str(clip)], "is the input clip")
    assert clip.read_bytes() == before and [p.name for p in tmp_path.iterdir()] == ["clip.json"]


@pytest.mark.parametrize(
    "expect, why",
    [
        ("collision === maybe", "is not a number, true, false or null"),
        ("collision == maybe", "is not a number, true, false or null"),
        ("safety_index >= high", "needs a number"),
    ],
)
def test_corpus_check_with_an_expectation_that_is_no_value(tmp_path, capsys, expect, why):
    (tmp_path / "suite.toml").write_text(f'[[case]]\nname = "x"\nclip = "clip.json"\nexpect = ["{expect}"]\n')
    (tmp_path / "clip.json").write_text(_clip_text())
    _refused(capsys, ["check", str(tmp_path / "suite.toml")], "expect[0]", why)


def test_corpus_untimed_trajectory_whose_times_go_back_plays_with_a_warning(scenario, tmp_path, capsys):
    """No Timing: the vertex times are not read (esmini 3.6 plays the file); vei says they go back."""
    text = Path(scenario).read_text()
    i = text.index("<Polyline>", text.index("EgoFollowTrajectory"))
    j = text.index("</Polyline>", i)
    counter = iter(range(10**6))
    poly = re.sub(r'time="[^"]*"', lambda m: f'time="{max(0, 5 - next(counter))}"', text[i:j])
    path = Path(scenario).parent / "ego_times_back.xosc"  # (beside its road network)
    path.write_text(text[:i] + poly + text[j:])
    try:
        assert main(["run", str(path), "--no-plots", "-o", str(tmp_path / "r")]) == 0
        err = capsys.readouterr().err
        assert "vei: warning:" in err and "'Ego_route': vertex times go back" in err and "Traceback" not in err
    finally:
        path.unlink()
