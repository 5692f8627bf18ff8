"""pytest: the OSMP test partners against host_alone.py only (no other host involved).

    /work/main/.venv/bin/python -m pytest -q test_partners_alone.py
"""
import hashlib
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from fmpy.validation import validate_fmu

import host_alone as ha

HERE = Path(__file__).resolve().parent
ALL = ["StraightLine", "SimpleAebOsmp", "TrajectoryFollower", "WrongMime", "ZeroSize", "WrongId", "NeverWrites"]
NS = "http://xsd.pmsf.net/OSISensorModelPackaging"


@pytest.mark.parametrize("name", ALL)
def test_fmpy_validate(name):
    assert validate_fmu(str(ha.partner(f"{name}.fmu"))) == []


@pytest.mark.parametrize("name", ALL)
def test_annotation_text(name):
    md = zipfile.ZipFile(ha.partner(f"{name}.fmu")).read("modelDescription.xml").decode()
    assert ('<VendorAnnotations>\n    <Tool name="net.pmsf.osmp" xmlns:osmp="%s">'
            '<osmp:osmp version="1.5.0" osi-version="3.7.0"/></Tool>' % NS) in md
    sv_type = "SensorData" if name == "WrongMime" else "SensorView"
    for prefix, typ in (("OSMPSensorViewIn", sv_type), ("OSMPTrafficUpdateOut", "TrafficUpdate")):
        for role in ("base.lo", "base.hi", "size"):
            assert (f'<osmp:osmp-binary-variable name="{prefix}" role="{role}" mime-type='
                    f'"application/x-open-simulation-interface; type={typ}; version=3.7.0"/>') in md
    assert 'variableNamingConvention="structured"' in md
    assert '<DefaultExperiment startTime="0.0" stepSize="0.02"/>' in md


@pytest.mark.parametrize("name", ["StraightLine", "SimpleAebOsmp", "ZeroSize", "WrongId", "NeverWrites"])
def test_good_annotations_accepted(name):
    ann = ha.check_osmp(ha.partner(f"{name}.fmu"), ha.read_model_description(str(ha.partner(f"{name}.fmu"))))
    assert ann["osmp"] == {"version": "1.5.0", "osi-version": "3.7.0"}


def test_build_is_deterministic(tmp_path):
    before = {n: hashlib.sha256((ha.partner(f"{n}.fmu")).read_bytes()).hexdigest() for n in ALL}
    subprocess.run([sys.executable, str(HERE / "build.py")], check=True, capture_output=True)
    after = {n: hashlib.sha256((ha.partner(f"{n}.fmu")).read_bytes()).hexdigest() for n in ALL}
    assert before == after


def test_straight_line_default_speed():
    ha.check_straight_line()


def test_straight_line_param_dt_and_traffic_command():
    ha.check_straight_line(speed=7.5, dt=0.05, t_end=3.0, with_command=True)


@pytest.mark.parametrize("left", [3.5, 2.1, -2.1])
def test_aeb_ignores_objects_outside_corridor(left):
    ha.check_aeb_clear(left)


def test_aeb_corridor_edge():
    ha.check_aeb_corridor_edge()


def test_aeb_brakes_and_does_not_hit():
    ha.check_aeb_brakes_and_stops()


def test_aeb_too_fast_hits_with_analytic_speed():
    ha.check_aeb_too_fast()


def test_aeb_ignores_object_behind():
    host = ha.new_host(speed=20.0)
    behind = ha.place(host, -10.0, 0.0, id=2, speed=0.0)
    tr = ha.simulate("SimpleAebOsmp.fmu", host, [behind], 1.0, 0.02)
    assert ha.onset_index(tr) is None


def test_aeb_ttc_uses_own_speed_not_closing_speed():
    # TTC uses the host's own speed (not the closing speed): a lead car 30 m ahead at the
    # same speed gives TTC 1.5 s -> brakes at once, as specified
    tr = ha.aeb_run(20.0, 30.0, t_end=0.1, other_speed=20.0)
    assert ha.onset_index(tr) == 0


@pytest.mark.parametrize("fmu", ["StraightLine.fmu", "SimpleAebOsmp.fmu"])
def test_no_sensor_view_is_safe(fmu):
    ha.check_no_input_is_safe(fmu)


@pytest.mark.parametrize("fmu,kind", [(f, k) for f, k in ha.BAD.items()])
def test_bad_partner_detected(fmu, kind):
    ha.check_bad(fmu, *kind)


def test_wrong_mime_is_otherwise_a_straight_line(monkeypatch):
    """Only the annotation is wrong: a host that ignores MIME types would run it silently."""
    monkeypatch.setattr(ha, "check_osmp", lambda path, md: None)
    host = ha.new_host()
    x0 = host.x
    tr = ha.simulate("WrongMime.fmu", host, [ha.place(host, 30, 8, id=2, speed=0.0)], 1.0, 0.02)
    assert abs(tr[-1].x - (x0 + 10.0 * __import__("math").cos(ha.YAW))) < 1e-9


def test_zero_size_buffer_would_decode_as_empty_update():
    """Why ZeroSize is nasty: b'' parses as a valid, empty TrafficUpdate."""
    tu = ha.TrafficUpdate()
    tu.ParseFromString(b"")
    assert len(tu.update) == 0


def test_wrong_id_targets_the_other_object():
    host = ha.new_host()
    h = ha.OsmpHost(ha.partner("WrongId.fmu"))
    try:
        with pytest.raises(ha.OsmpError) as e:
            h.step(0.0, 0.02, host, [ha.place(host, 30, 8, id=7, speed=0.0)])
        assert "[7]" in str(e.value)
        with pytest.raises(ha.OsmpError) as e:  # no other object: host id + 1000
            h.step(0.02, 0.02, host, [])
        assert "[1001]" in str(e.value)
    finally:
        h.close()


def test_output_buffer_lifetime():
    """Output of doStep k is still intact after doStep k+1 (host_alone checks it before k+2)."""
    host = ha.new_host()
    h = ha.OsmpHost(ha.partner("StraightLine.fmu"))
    try:
        outs = []
        for k in range(6):
            h.step(k * 0.02, 0.02, host, [])
            outs.append(h._prev_out[-1])
            if k >= 1:
                _, addr, size, data = outs[k - 1]
                assert ha.ctypes.string_at(addr, size) == data
        assert len({o[1] for o in outs[-3:]}) == 3  # distinct buffers, not one overwritten
    finally:
        h.close()
