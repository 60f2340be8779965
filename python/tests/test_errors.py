"""Bad input raises sinew.Error with the file, the line and the component, never a crash."""
import numpy as np
import pytest

import sinew
from conftest import CHRONO, RESOURCES


def test_malformed_model_names_file_and_line(tmp_path):
    text = (RESOURCES / "SinglePin.osim").read_text()
    mass = "0.75000000"
    broken = text.replace(mass, "heavy", 1)
    line = text[:text.index(mass)].count("\n") + 1
    path = tmp_path / "broken.osim"
    path.write_text(broken)
    with pytest.raises(sinew.Error) as error:
        sinew.load(path)
    assert error.value.file == str(path)
    assert error.value.line == line
    assert "rod1" in error.value.component
    assert str(error.value).startswith(f"{path}:{line}: ")


def test_missing_file():
    with pytest.raises(sinew.Error) as error:
        sinew.load(RESOURCES / "no_such_model.osim")
    assert error.value.file.endswith("no_such_model.osim")


def test_unknown_names_and_options():
    model = sinew.load(RESOURCES / "DoublePendulum3D.osim")
    state = model.default_state()
    with pytest.raises(sinew.Error) as error:
        state.value("no_such_coordinate")
    assert error.value.component == "no_such_coordinate"
    assert error.value.file == model.path
    with pytest.raises(sinew.Error, match="integrator"):
        model.simulate(0.1, integrator="leapfrog")
    with pytest.raises(sinew.Error):
        sinew.load(RESOURCES / "SinglePin.osim", contact="magic")
    with pytest.raises(sinew.Error, match="no_such_actuator|actuator"):
        sinew.load(CHRONO / "torque-actuator.osim").simulate(
            0.1, excitations={"no_such_actuator": 1.0})
    with pytest.raises(sinew.Error, match="2 values"):
        state.q = np.zeros(3)
    with pytest.raises(sinew.Error):
        model.simulate(0.1, initial_states=RESOURCES / "no_such_states.sto")


def test_bad_controls_and_batches():
    model = sinew.load(CHRONO / "double_pendulum.osim")
    simulator = model.simulator(1e-3)
    with pytest.raises(sinew.Error, match="controls"):
        simulator.step(np.zeros(3))
    batch = sinew.Batch(model, 4, step=1e-3)
    with pytest.raises(sinew.Error, match="controls"):
        batch.step(np.zeros((4, 1)))
    with pytest.raises(sinew.Error, match="actuators"):
        batch.step()
    with pytest.raises(sinew.Error, match="step"):
        sinew.Batch(model, 4, step=0.0)


def test_unused_initial_state_columns_warn_or_fail_when_strict(tmp_path):
    # SinglePin's initial states plus a column naming nothing in the model.
    lines = (RESOURCES / "SinglePin_InitialStates.sto").read_text().splitlines()
    end = [line.strip() for line in lines].index("endheader")
    lines[end + 1] += "\tnot_a_coordinate"
    for i in range(end + 2, len(lines)):
        if lines[i].strip():
            lines[i] += "\t1.0"
    states = tmp_path / "states.sto"
    states.write_text("\n".join(lines) + "\n")
    with pytest.warns(UserWarning, match="not_a_coordinate"):
        sinew.load(RESOURCES / "SinglePin.osim").simulate(0.01, initial_states=states)
    with pytest.raises(sinew.Error) as error:
        sinew.load(RESOURCES / "SinglePin.osim", strict=True).simulate(0.01, initial_states=states)
    assert error.value.file == str(states)
    assert error.value.component == "not_a_coordinate"


def test_what_the_table_reader_read_leniently_is_a_warning_with_file_and_line():
    # OpenSim's DoublePendulum3D_InitialStates.sto says nColumns=4 above 5 labels (the CLI
    # prints the same note).
    states = RESOURCES / "DoublePendulum3D_InitialStates.sto"
    with pytest.warns(UserWarning, match=f"{states}:3: nColumns=4"):
        sinew.load(RESOURCES / "DoublePendulum3D.osim").simulate(0.01, initial_states=states)



def _single_pin_states(tmp_path, edit):
    # SinglePin's initial states with `edit(header, rows)` applied to its column labels and rows.
    lines = (RESOURCES / "SinglePin_InitialStates.sto").read_text().splitlines()
    end = [line.strip() for line in lines].index("endheader")
    header = lines[end + 1].split("\t")
    rows = [line.split("\t") for line in lines[end + 2:] if line.strip()]
    edit(header, rows)
    states = tmp_path / "states.sto"
    states.write_text("\n".join(lines[: end + 1] + ["\t".join(header)] +
                                ["\t".join(row) for row in rows]) + "\n")
    return states, header


def test_unusable_initial_states_tables_are_errors_naming_file_column_and_row(tmp_path):
    # As the CLI checks every table: a coordinate's NaN (it would reach the integrator as a
    # "singular" body) and times that do not increase.
    def nan_value(header, rows):
        rows[0][1] = "nan"

    states, header = _single_pin_states(tmp_path, nan_value)
    with pytest.raises(sinew.Error, match=rf"column '{header[1]}', row 1 .*nan is not a finite "
                                          "number, and the column names a coordinate") as error:
        sinew.load(RESOURCES / "SinglePin.osim").simulate(0.01, initial_states=states)
    assert error.value.file == str(states)

    def repeated_time(header, rows):
        rows.append(list(rows[-1]))

    states, header = _single_pin_states(tmp_path, repeated_time)
    with pytest.raises(sinew.Error, match=f"column '{header[0]}' must increase"):
        sinew.load(RESOURCES / "SinglePin.osim").simulate(0.01, initial_states=states)


def test_radian_tables_whose_angles_look_like_degrees_warn(tmp_path):
    # No inDegrees line: radians, as OpenSim reads such a file, but 57.3 rad looks like degrees.
    def degrees(header, rows):
        rows[0][1] = "57.3"

    lines = (RESOURCES / "SinglePin_InitialStates.sto").read_text()
    assert "inDegrees" not in lines
    states, header = _single_pin_states(tmp_path, degrees)
    with pytest.warns(UserWarning, match=rf"no inDegrees line.*\({header[1]}\)"):
        sinew.load(RESOURCES / "SinglePin.osim").simulate(0.0, initial_states=states)
