# ruff: noqa: E501  (the hand-written scenario keeps its XML lines whole)
"""What a first user hits: a file given to the wrong command, a misspelt enumeration value in a sweep,
an error naming an internal temporary file, descriptions with nothing to read or with terminal
escapes, trajectories that repeat a time, a sweep of a scenario that cannot be played at all, a run
that would be silent for minutes, and an animation drawn without a word. Each ends as one line and
exit 2, or plays as esmini plays it, and says what it is doing."""

from __future__ import annotations

import errno
import io
import json
import os
import re
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
def case_xosc(compiled) -> Path:
    return compiled["case_study"].written[0]


def _tree(path: Path) -> list[Path]:
    return sorted(p for p in path.rglob("*")) if path.exists() else []


# --- a file given to the other command ---------------------------------------------------------------


def test_a_clip_given_to_vei_run_suggests_vei_compile(capsys, tmp_path):
    clip = EXAMPLES / "case_study" / "clip.json"
    err = _refused(capsys, ["run", str(clip), "-o", str(tmp_path / "r")], "vei compile", "clip")
    assert str(clip) in err and not (tmp_path / "r").exists()


def test_a_scenario_given_to_vei_compile_suggests_vei_run(capsys, tmp_path, case_xosc):
    _refused(capsys, ["compile", str(case_xosc), "-o", str(tmp_path / "s.xosc")], "vei run", "OpenSCENARIO")
    assert not any(tmp_path.iterdir())


# --- --vary values known to be wrong before the sweep ---------------------------------------------------


def test_a_misspelt_rider_type_is_refused_before_the_sweep(capsys, tmp_path, case_xosc):
    out = tmp_path / "sweep"
    err = _refused(
        capsys,
        ["sweep", str(case_xosc), "--vary", "RiderType=normal,agressive", "--vary", "TimeShift=0,1", "-o", str(out)],
        "RiderType='agressive'",
        "replay, normal, aggressive",
    )
    assert "--vary" in err and not out.exists()


def test_a_value_of_the_wrong_type_is_refused_before_the_sweep(capsys, tmp_path, case_xosc):
    _refused(capsys, ["sweep", str(case_xosc), "--vary", "CapEnabled=yes", "-o", str(tmp_path / "s")], "CapEnabled")
    assert not (tmp_path / "s").exists()


def test_a_value_outside_declared_value_constraints_is_refused(capsys, tmp_path, case_xosc):
    """OpenSCENARIO 1.2 ConstraintGroups: a value must meet every constraint of one group."""
    text = case_xosc.read_text()
    text = text.replace(
        '<ParameterDeclaration name="RiderType" parameterType="string" value="replay"/>',
        '<ParameterDeclaration name="RiderType" parameterType="string" value="replay">'
        + "".join(
            f'<ConstraintGroup><ValueConstraint rule="equalTo" value="{v}"/></ConstraintGroup>'
            for v in ("replay", "normal")
        )
        + "</ParameterDeclaration>",
    )
    text = text.replace(
        '<ParameterDeclaration name="EgoCruiseSpeed" parameterType="double" value="5.61"/>',
        '<ParameterDeclaration name="EgoCruiseSpeed" parameterType="double" value="5.61"><ConstraintGroup>'
        '<ValueConstraint rule="greaterThan" value="0"/><ValueConstraint rule="lessOrEqual" value="20"/>'
        "</ConstraintGroup></ParameterDeclaration>",
    )
    assert text.count("ConstraintGroup>") == 6
    path = case_xosc.parent / "constrained.xosc"  # (beside its road network)
    path.write_text(text)
    try:
        out = str(tmp_path / "s")
        _refused(capsys, ["sweep", str(path), "--vary", "RiderType=aggressive", "-o", out], "one of replay, normal")
        _refused(
            capsys,
            ["sweep", str(path), "--vary", "EgoCruiseSpeed=10,25", "-o", out],
            "EgoCruiseSpeed='25'",
            "greaterThan 0 and lessOrEqual 20",
        )
        assert not (tmp_path / "s").exists()
        assert main(["sweep", str(path), "--vary", "EgoCruiseSpeed=10,20", "-o", out, "--quiet"]) == 0
    finally:
        path.unlink()


# --- errors name the user's file --------------------------------------------------------------------


@pytest.mark.parametrize("code", [errno.EROFS, errno.EACCES])
def test_a_refused_write_names_the_file_asked_for_not_the_temporary(case_xosc, tmp_path, capsys, monkeypatch, code):
    import tempfile

    def refusing(prefix="", suffix="", dir=None, **kwargs):
        raise OSError(code, os.strerror(code), os.path.join(dir, f"{prefix}abc123{suffix}"))

    monkeypatch.setattr(tempfile, "mkstemp", refusing)
    err = _refused(capsys, ["run", str(case_xosc), "--no-plots", "-o", str(tmp_path / "run")])
    assert ".tmp" not in err and str(tmp_path / "run" / "trajectories.csv") in err, err
    err = _refused(capsys, ["compile", str(EXAMPLES / "no_map" / "clip.json"), "-o", str(tmp_path / "new.xosc")])
    assert ".tmp" not in err and "new.xosc" in err, err


def test_a_failed_rename_names_the_target(tmp_path, monkeypatch):
    from vei_scenario.atomic_io import OutputSet, write_bytes_atomic

    def refusing(src, dst):
        raise OSError(errno.EACCES, "Permission denied", src, dst)

    monkeypatch.setattr(os, "replace", refusing)
    with pytest.raises(PermissionError) as info:
        write_bytes_atomic(tmp_path / "a.txt", b"x")
    assert info.value.filename == str(tmp_path / "a.txt") and info.value.filename2 is None
    files = OutputSet()
    files.add(tmp_path / "b.txt", "y")
    with pytest.raises(PermissionError) as info:
        files.commit()
    assert info.value.filename == str(tmp_path / "b.txt")
    assert not [p for p in tmp_path.iterdir()]


# --- descriptions -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "text, needle",
    [
        ("", "empty"),
        ("   \t ", "empty"),
        ("\x1b[2J\x07", "empty"),
        ("?!.,;:-- ...", "no words"),
        ("🛴💨 ➡️ 🚗💥", "no words"),
    ],
    ids=["empty", "blank", "escapes-only", "punctuation", "emoji"],
)
def test_a_description_with_nothing_to_read_is_refused(capsys, tmp_path, text, needle):
    _refused(capsys, ["describe", text, "-o", str(tmp_path / "d"), "--count", "2", "--jobs", "1"], needle)
    assert not (tmp_path / "d").exists()


def test_terminal_escapes_and_control_characters_are_taken_out_of_a_description(capsys, tmp_path):
    text = "\x1b[2J\x1b]0;owned\x07an e-scooter \x1b[31mcrosses\x1b[0m in front of\x00 the car\r"
    assert main(["describe", text, "-o", str(tmp_path / "d"), "--count", "2", "--jobs", "1"]) == 0
    out, err = capsys.readouterr()
    assert "\x1b" not in out + err and "Traceback" not in err
    for f in (tmp_path / "d").rglob("*"):
        if f.is_file() and f.suffix in (".xosc", ".html", ".json", ".csv"):
            body = f.read_text(encoding="utf-8")
            assert "\x1b" not in body and "\x00" not in body and "\x07" not in body, f
    header = next((tmp_path / "d").rglob("*.xosc")).read_text()
    assert 'description="an e-scooter crosses in front of the car"' in header


# --- trajectories that repeat a time ----------------------------------------------------------------


def _one_car(verts: list[tuple[float, float]], stop: float = 5.0) -> str:
    from xosc_parts import ABSOLUTE_TIMING, CAR

    v = "".join(
        f'<Vertex time="{t}"><Position><WorldPosition x="{x}" y="0" h="0"/></Position></Vertex>' for t, x in verts
    )
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO><FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="t" author="t"/>
<ParameterDeclarations/><CatalogLocations/><RoadNetwork/>
<Entities><ScenarioObject name="A">{CAR}</ScenarioObject></Entities>
<Storyboard><Init><Actions><Private entityRef="A">
<PrivateAction><TeleportAction><Position><WorldPosition x="0" y="0" h="0"/></Position></TeleportAction></PrivateAction>
</Private></Actions></Init>
<Story name="s"><Act name="a"><ManeuverGroup maximumExecutionCount="1" name="g"><Actors selectTriggeringEntities="false">
<EntityRef entityRef="A"/></Actors><Maneuver name="m"><Event name="e" priority="override"><Action name="f">
<PrivateAction><RoutingAction><FollowTrajectoryAction>
<TrajectoryRef><Trajectory name="t" closed="false"><Shape><Polyline>{v}</Polyline></Shape></Trajectory></TrajectoryRef>
<TimeReference>{ABSOLUTE_TIMING}</TimeReference>
<TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction>
</Action><StartTrigger><ConditionGroup><Condition name="c" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition>
</Condition></ConditionGroup></StartTrigger></Event></Maneuver></ManeuverGroup>
<StartTrigger><ConditionGroup><Condition name="go" delay="0" conditionEdge="none"><ByValueCondition>
<SimulationTimeCondition value="0" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger>
</Act></Story>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="rising"><ByValueCondition>
<SimulationTimeCondition value="{stop}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard></OpenSCENARIO>"""


@pytest.mark.parametrize(
    "verts",
    [[(0, 0), (2, 10), (2, 10)], [(0, 0), (2, 10), (2, 20)], [(0, 0), (1, 10), (1, 20), (2, 30)]],
    ids=["repeated-last-vertex", "jump-at-the-end", "jump-in-the-middle"],
)
def test_vertices_that_repeat_a_time_play_as_in_esmini(tmp_path, capsys, esmini_if_here, verts):
    """A repeated time is a jump (esmini 3.6 plays it so): positions stay numbers after the end, the
    plots are drawn, and esmini agrees up to the end of the trajectory."""
    from vei_scenario.interpreter import run_scenario

    path = tmp_path / "repeat.xosc"
    path.write_text(_one_car(verts))
    assert main(["run", str(path), "-o", str(tmp_path / "run")]) == 0, capsys.readouterr().err
    assert (tmp_path / "run" / "trajectories.png").is_file()
    result = run_scenario(path, {}, 0.01)
    tr = result.traces["A"]
    assert np.all(np.isfinite(tr.x)) and np.all(np.isfinite(tr.speed))
    end = float(verts[-1][0])
    k = int(np.searchsorted(result.t, end + 1e-9))
    assert tr.x[k] == pytest.approx(verts[-1][1], abs=0.2)  # (at the last vertex once its time is reached)
    if esmini_if_here is not None:
        from vei_scenario.conformance.esmini import compare_runs, run_esmini

        (e,) = compare_runs(result, run_esmini(esmini_if_here, path, 0.01), {"A": end - 0.01}).entities
        assert e.max_deviation_m <= 1e-6, e


def test_a_run_whose_positions_are_not_numbers_is_one_line(tmp_path, capsys, monkeypatch):
    """The last line of defence: a defect vei cannot play ends in one line naming the entity."""
    import vei_scenario.runner as runner
    from vei_scenario.interpreter import run_scenario

    path = tmp_path / "a.xosc"
    path.write_text(_one_car([(0, 0), (2, 10)]))

    def broken(*args, **kwargs):
        result = run_scenario(*args, **kwargs)
        result.traces["A"].x[100:] = np.nan
        return result

    monkeypatch.setattr(runner, "run_scenario", broken)
    _refused(capsys, ["run", str(path), "-o", str(tmp_path / "r")], "A", "t = 1 s")
    assert not (tmp_path / "r").exists()


# --- a sweep of a scenario that cannot be played ------------------------------------------------------


def _broken_copies(case_xosc: Path) -> dict[str, str]:
    base = case_xosc.read_text()
    i = base.index("<Polyline>", base.index("scooter_1FollowTrajectory"))
    j = base.index("</Polyline>", i)
    verts = re.findall(r'<Vertex time="[^"]*">.*?</Vertex>', base[i:j], re.S)

    def poly(vs: list[str]) -> str:
        return base[:i] + "<Polyline>" + "".join(vs) + base[j:]

    decreasing = [re.sub(r'time="[^"]*"', f'time="{100 - k}"', v, count=1) for k, v in enumerate(verts)]
    return {
        "unknown_action": base.replace("<TeleportAction>", "<FooAction>", 1).replace(
            "</TeleportAction>", "</FooAction>", 1
        ),
        "no_vertex": poly([]),
        "one_vertex": poly(verts[:1]),
        "decreasing_times": poly(decreasing),
        "logic_file_outside": base.replace('filepath="scenario.xodr"', 'filepath="/etc/passwd"'),
        "logic_file_not_a_road": base.replace('filepath="scenario.xodr"', 'filepath="not_a_road.xodr"'),
    }


@pytest.mark.parametrize(
    "defect, needle",
    [
        ("unknown_action", "FooAction"),
        ("no_vertex", "at least two vertices"),
        ("one_vertex", "at least two vertices"),
        ("decreasing_times", "vertex times must not decrease"),
        ("logic_file_outside", "not an OpenDRIVE file"),
        ("logic_file_not_a_road", "its root element is <html>"),
    ],
)
def test_a_sweep_of_an_unplayable_scenario_is_one_line_before_any_variant(case_xosc, tmp_path, capsys, defect, needle):
    folder = tmp_path / "in"
    folder.mkdir()
    (folder / "scenario.xodr").write_bytes(case_xosc.with_suffix(".xodr").read_bytes())
    (folder / "not_a_road.xodr").write_text('<?xml version="1.0"?><html><body>not a road</body></html>')
    path = folder / f"{defect}.xosc"
    path.write_text(_broken_copies(case_xosc)[defect])
    out = tmp_path / "sweep"
    _refused(capsys, ["sweep", str(path), "--vary", "TimeShift=0,1,2", "-o", str(out)], needle)
    assert not out.exists()
    _refused(capsys, ["run", str(path), "-o", str(tmp_path / "run")], needle)
    assert not (tmp_path / "run").exists()


def test_per_variant_failures_stay_rows(case_xosc, tmp_path, capsys):
    """A value that fails only its own variants (a negative cruise speed, which the planner refuses)
    is a row of the catalog, and the sweep says so with exit 1."""
    out = tmp_path / "s"
    assert main(["sweep", str(case_xosc), "--vary", "EgoCruiseSpeed=5,-5", "-o", str(out), "--quiet"]) == 1
    rows = json.loads((out / "catalog.json").read_text())["variants"]
    assert [r["status"] for r in rows] == ["ok", "error"]
    assert "non-negative property cruiseSpeed" in rows[1]["error"]


# --- a long run says so -------------------------------------------------------------------------------


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def _no_stop_trigger(case_xosc: Path, folder: Path) -> Path:
    text = case_xosc.read_text()
    i = text.rindex("<StopTrigger>")
    j = text.index("</StopTrigger>", i) + len("</StopTrigger>")
    path = folder / "no_stop.xosc"
    (folder / "scenario.xodr").write_bytes(case_xosc.with_suffix(".xodr").read_bytes())
    path.write_text(text[:i] + "<StopTrigger/>" + text[j:])
    return path


def test_a_run_without_a_stop_trigger_says_how_long_it_may_run_and_shows_progress(case_xosc, tmp_path, monkeypatch):
    from vei_scenario.interpreter import Simulation, load_scenario
    from vei_scenario.reports.run_progress import RunProgress

    monkeypatch.delenv("CI", raising=False)
    path = _no_stop_trigger(case_xosc, tmp_path)
    stream = _Terminal()
    shown = RunProgress(path.name, stream)
    sim = Simulation(load_scenario(path), 1e-4, max_time_s=2.0)  # (the note for a 600 s limit, run 2 s)
    sim.max_time = 600.0
    tick = shown.on_start(sim)
    sim.max_time = 2.0
    result = sim.run(tick)
    shown.close()
    text = stream.getvalue()
    first = text.splitlines()[0]
    assert first == (
        "vei: note: no_stop.xosc has no stop trigger: it runs until its stories complete or the 600 s time "
        "limit, up to 6,000,000 steps at dt 0.0001 s"
    )
    assert "simulated" in text and "/600" in text  # the bar moved
    assert result.t[-1] == pytest.approx(2.0)


def test_the_note_comes_before_the_run_and_no_bar_off_a_terminal(case_xosc, tmp_path):
    import subprocess
    import sys
    import time

    path = _no_stop_trigger(case_xosc, tmp_path)
    proc = subprocess.Popen(
        [sys.executable, "-m", "vei_scenario.cli", "run", str(path), "--no-plots", "--dt", "1e-4", "-o", "r"],
        cwd=tmp_path,
        stderr=subprocess.PIPE,
        stdout=subprocess.DEVNULL,
    )
    try:
        t0 = time.monotonic()
        line = proc.stderr.readline().decode()
        assert time.monotonic() - t0 < 15
        assert line.startswith("vei: note: no_stop.xosc has no stop trigger") and "6,000,000 steps" in line
    finally:
        proc.kill()
        proc.wait()
        proc.stderr.close()


def test_a_short_run_says_nothing(case_xosc, tmp_path, capsys):
    assert main(["run", str(case_xosc), "--no-plots", "-o", str(tmp_path / "r")]) == 0
    assert capsys.readouterr().err == ""


# --- an animation shows its frames on a terminal ---------------------------------------------------------


def test_writing_an_animation_shows_progress_on_a_terminal_only(case_xosc, tmp_path, monkeypatch):
    import sys

    from vei_scenario.reports.viewer import view_scenario, write_animation

    monkeypatch.delenv("CI", raising=False)
    view = view_scenario(case_xosc, {}, 0.05)
    terminal = _Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    write_animation(view, tmp_path / "a.gif", fps=2, progress=True, size_px=160)
    assert "frame" in terminal.getvalue() and "drawing" in terminal.getvalue()
    piped = io.StringIO()
    monkeypatch.setattr(sys, "stderr", piped)
    write_animation(view, tmp_path / "b.gif", fps=2, progress=True, size_px=160)
    assert piped.getvalue() == ""
    assert (tmp_path / "a.gif").read_bytes() == (tmp_path / "b.gif").read_bytes()
