"""State getters and setters round-trip, by name and as arrays, and states are values."""
import numpy as np
import pytest

import sinew
from conftest import CHRONO, RESOURCES


def test_set_and_get_round_trip():
    model = sinew.load(RESOURCES / "DoublePendulum3D.osim")
    state = model.default_state()
    assert model.coordinates == ["r1_z", "r2_x"]
    state.q = [0.3, -0.2]
    state.u = np.array([1.5, 2.5])
    state.t = 0.25
    assert state.q.tolist() == [0.3, -0.2]
    assert state.u.tolist() == [1.5, 2.5]
    assert state.t == 0.25
    state.set_value("r2_x", 0.125)
    state.set_speed("r1_z", -4.0)
    assert state.value("r2_x") == 0.125
    assert state.speed("r1_z") == -4.0
    assert state.q.tolist() == [0.3, 0.125]


def test_states_are_values():
    model = sinew.load(RESOURCES / "SinglePin.osim")
    state = model.default_state()
    copy = state.copy()
    state.set_value("r1_z", 1.0)
    assert copy.value("r1_z") != 1.0
    array = state.q
    array[0] = 7.0  # a copy: the state does not change
    assert state.value("r1_z") == 1.0


def test_simulating_from_a_state_equals_simulating_from_its_values():
    # The bodies are placed from q and u when they are set, so a run from a state built in
    # Python equals a run from the same values given as an initial-states table.
    model = sinew.load(RESOURCES / "DoublePendulum3D.osim")
    from_file = model.simulate(0.2, initial_states=RESOURCES / "DoublePendulum3D_InitialStates.sto")
    state = model.default_state()
    state.q = from_file.q[0]
    state.u = from_file.u[0]
    from_state = model.simulate(0.2, initial_states=state)
    assert np.array_equal(from_state.q, from_file.q)
    assert np.array_equal(from_state.u, from_file.u)


def test_inputs_and_report():
    model = sinew.load(CHRONO / "double_pendulum.osim")
    assert model.actuators == ["Torq1", "Torq2"]
    state = model.default_state()
    state.inputs = [0.5, -0.5]
    assert state.inputs.tolist() == [0.5, -0.5]
    report = model.report
    assert {f["name"] for f in report["forces"] if f["actuator"]} == {"Torq1", "Torq2"}
    assert [b["name"] for b in report["bodies"]]
    assert report["stand_ins"] == []


def test_report_names_stand_ins_and_strict_refuses_them(tmp_path):
    # DoublePendulum3D with pin2 retyped as a joint class no one knows (as StandInTest does).
    text = (RESOURCES / "DoublePendulum3D.osim").read_text()
    text = text.replace('<CustomJoint name="pin2">', '<FancyJoint name="pin2">', 1)
    at = text.index('<FancyJoint name="pin2">')
    end = text.index("</CustomJoint>", at)
    text = text[:end] + "</FancyJoint>" + text[end + len("</CustomJoint>"):]
    path = tmp_path / "fancy.osim"
    path.write_text(text)
    report = sinew.load(path).report
    assert report["stand_ins"] == ["pin2"]
    assert any("FancyJoint" in w["message"] and w["component"].endswith("pin2")
               for w in report["warnings"])
    with pytest.raises(sinew.Error):
        sinew.load(path, strict=True)


def test_to_pandas_is_optional():
    result = sinew.load(RESOURCES / "SinglePin.osim").simulate(0.05)
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="pandas"):
            result.to_pandas()
    else:
        frame = result.to_pandas()
        assert list(frame.columns) == result.labels
        assert np.array_equal(frame.to_numpy(), result.states)
