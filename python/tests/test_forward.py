"""sinew.forward runs OpenSim ForwardTool setup files as `sinew forward` does: the same states
bit for bit, OpenSim's own stored results within its test's tolerance, and the setup's errors."""
import os
import subprocess
from xml.etree import ElementTree

import numpy as np
import pytest

import sinew
from conftest import DATA, read_sto

FORWARD = DATA / "opensim-org/opensim-core/Applications/Forward/tests/resources"
DEPRECATED = {"Thelen2003Muscle": "Thelen2003Muscle_Deprecated"}


def run_cli_forward(setup, out, *args):
    program = os.environ.get("SINEW_CLI")
    if not program:
        pytest.skip("SINEW_CLI is not set (ctest sets it to the built sinew program)")
    subprocess.run([program, "forward", str(setup), "--out", str(out), "--quiet", *args],
                   check=True, capture_output=True)


def test_arm26_reproduces_opensim_and_the_cli(tmp_path):
    # OpenSim's testForward: arm26's six deprecated Thelen muscles from its initial states under
    # its static-optimization controls, within 5e-3 of OpenSim 2.x's states (whose cylinders
    # refined their tangent points on every path: cylinder_refinement="always").
    setup = FORWARD / "arm26_Setup_Forward.xml"
    result = sinew.forward(setup, rename_force_classes=DEPRECATED, cylinder_refinement="always")
    run_cli_forward(setup, tmp_path, "--rename-force-class",
                    "Thelen2003Muscle=Thelen2003Muscle_Deprecated", "--cylinder-refinement",
                    "always")
    labels, time, values = read_sto(tmp_path / "arm26_states.sto")
    assert labels == result.labels
    np.testing.assert_array_equal(time, result.time)
    np.testing.assert_array_equal(values, result.states)
    for table, labels_of, values_of in (("forces", result.force_labels, result.forces),
                                        ("controls", result.control_labels, result.controls)):
        labels, time, values = read_sto(tmp_path / f"arm26_{table}.sto")
        assert labels == labels_of, table
        np.testing.assert_array_equal(time, result.time)
        np.testing.assert_array_equal(values, values_of, err_msg=table)
    assert len(result.force_labels) == 6 and len(result.control_labels) == 6

    # The controls are the setup's ControlSet: its nodes interpolated linearly (use_steps false).
    control_set = ElementTree.parse(FORWARD / "arm26_StaticOptimization_controls.xml").getroot()
    for control in control_set.iter("ControlLinear"):
        nodes = [(float(node.find("t").text), float(node.find("value").text))
                 for node in control.iter("ControlLinearNode")]
        t, value = np.array(nodes).T
        inside = (result.time >= t[0]) & (result.time <= t[-1])
        assert inside.sum() >= 100
        column = result.control_labels.index(control.get("name").split(".")[0])
        np.testing.assert_allclose(result.controls[inside, column],
                                   np.interp(result.time[inside], t, value), rtol=0, atol=1e-14,
                                   err_msg=control.get("name"))

    # At each of our rows, against the reference interpolated linearly between its own rows
    # (OpenSim wrote a row per integrator step).
    labels, time, expected = read_sto(FORWARD / "std_arm26_states.sto")
    rows = (result.time >= time[0]) & (result.time <= time[-1])
    assert rows.sum() == 101
    compared = 0
    for k, label in enumerate(labels):
        if label.endswith("_u"):
            ours = result.u[rows, result.coordinates.index(label[:-2])]
        elif "." in label:
            ours = result.z[rows, result.state_variables.index(label.replace(".", "/"))]
        else:
            ours = result.q[rows, result.coordinates.index(label)]
        reference = np.interp(result.time[rows], time, expected[:, k])
        np.testing.assert_allclose(ours, reference, rtol=0, atol=5e-3, err_msg=label)
        compared += 1
    assert compared == 16  # 2 coordinates, their speeds, 6 muscles' two states


def test_subject01_with_force_set_external_loads_and_controls_equals_the_cli(tmp_path):
    # gait2354 with the CMC actuators appended from a ForceSet file, ground reactions as external
    # loads, a ControlSet and the states file's row at the initial time.
    setup = FORWARD / "subject01_Setup_Forward.xml"
    result = sinew.forward(setup, rename_force_classes=DEPRECATED)
    run_cli_forward(setup, tmp_path, "--rename-force-class",
                    "Thelen2003Muscle=Thelen2003Muscle_Deprecated")
    labels, time, values = read_sto(tmp_path / "subject01_states.sto")
    assert labels == result.labels
    np.testing.assert_array_equal(time, result.time)
    np.testing.assert_array_equal(values, result.states)
    assert result.time[0] > 0.0  # the run starts at the setup's initial time
    # The CMC actuators' and muscles' forces and the ControlSet's controls, as the CLI writes them.
    for table, labels_of, values_of in (("forces", result.force_labels, result.forces),
                                        ("controls", result.control_labels, result.controls)):
        labels, time, values = read_sto(tmp_path / f"subject01_{table}.sto")
        assert labels == labels_of, table
        np.testing.assert_array_equal(values, values_of, err_msg=table)
        with_forces = tmp_path / f"python_{table}.sto"
        getattr(result, f"{table}_to_sto")(with_forces)
        assert with_forces.read_bytes() == (tmp_path / f"subject01_{table}.sto").read_bytes()


def test_a_setup_without_a_model_needs_one():
    setup = DATA / "opensim-org/opensim-core/Applications/Analyze/tests/resources/SinglePin_Setup_Forward.xml"
    with pytest.raises(sinew.Error, match=r"<model_file> is empty\): give one with model="):
        sinew.forward(setup)


def test_the_states_row_is_the_one_opensim_takes(tmp_path):
    # The last row at or before initial_time (the run starts at its time, with a warning), or the
    # first row when initial_time precedes them all; its coordinates start the run.
    states = tmp_path / "states.sto"
    states.write_text("states\nversion=1\nnRows=3\nnColumns=3\ninDegrees=no\nendheader\n"
                      "time\tr1_z\tr1_z_u\n0.2\t0.5\t0\n0.5\t1.0\t0.25\n0.9\t1.5\t0\n")
    single_pin = DATA / "opensim-org/opensim-core/Applications/Analyze/tests/resources/SinglePin.osim"

    def setup(name, t0):
        path = tmp_path / f"{name}.xml"
        path.write_text(f'<OpenSimDocument Version="40000"><ForwardTool name="{name}">'
                        f"<model_file>{single_pin}</model_file><initial_time>{t0}</initial_time>"
                        f"<final_time>1</final_time><states_file>{states}</states_file>"
                        "</ForwardTool></OpenSimDocument>")
        return path

    with pytest.warns(UserWarning, match="no row at the initial time 0.7; the run starts at 0.5 s"):
        between = sinew.forward(setup("between", 0.7))
    assert between.time[0] == 0.5
    assert between.q[0, 0] == 1.0 and between.u[0, 0] == 0.25
    with pytest.warns(UserWarning, match="the initial time 0 precedes the first row"):
        before = sinew.forward(setup("before", 0.0))
    assert before.time[0] == 0.2
    assert before.q[0, 0] == 0.5
