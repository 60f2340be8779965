"""Model.analyze gives the tables `sinew analyze` writes (opensim::MuscleAnalysis under both):
path lengths that match OpenSim's own over a walking motion, the CLI's files bit for bit, the
muscle tables of a states table or of a Result, and clear errors and warnings."""
import os
import subprocess

import numpy as np
import pytest

import sinew
from conftest import DATA, read_sto

OPENSIM = DATA / "opensim-org/opensim-core/OpenSim"
GAIT1018 = OPENSIM / "Moco/Test/walk_gait1018_subject01.osim"
GAIT1018_MOTION = OPENSIM / "Moco/Test/walk_gait1018_state_reference.mot"
GAIT1018_LENGTHS = OPENSIM / "Tests/Wrapping/std_testGeometryPathWrapping_walk_gait1018_muscle_lengths.sto"
ARM26 = DATA / "opensim-org/opensim-models/Models/Arm26/arm26.osim"


def run_cli_analyze(model, motion, out, *args):
    program = os.environ.get("SINEW_CLI")
    if not program:
        pytest.skip("SINEW_CLI is not set (ctest sets it to the built sinew program)")
    subprocess.run([program, "analyze", str(model), "--motion", str(motion), "--out", str(out),
                    *args], check=True, capture_output=True)


def test_lengths_match_opensim_over_the_walking_motion():
    tables = sinew.load(GAIT1018).analyze(GAIT1018_MOTION)
    labels, time, expected = read_sto(GAIT1018_LENGTHS)
    assert tables["length"].shape == (151, len(tables["paths"]))
    np.testing.assert_allclose(tables["time"], time, atol=1e-8)
    for k, label in enumerate(labels):  # "/forceset/<muscle>|length"
        column = tables["paths"].index(label[len("/forceset/"):label.index("|")])
        np.testing.assert_allclose(tables["length"][:, column], expected[:, k], rtol=0, atol=1e-6)
    # One table per coordinate that moves on its own: all ten here.
    assert len(tables["moment_arm"]) == 10
    assert tables["muscles"] == []  # a motion, not a states table


def test_tables_equal_the_cli_files(tmp_path):
    tables = sinew.load(GAIT1018).analyze(GAIT1018_MOTION,
                                          coordinates=["knee_angle_r", "hip_flexion_l"])
    run_cli_analyze(GAIT1018, GAIT1018_MOTION, tmp_path,
                    "--coordinates", "knee_angle_r,hip_flexion_l")
    assert list(tables["moment_arm"]) == ["knee_angle_r", "hip_flexion_l"]
    for name, values in [("Length", tables["length"]),
                         ("LengtheningSpeed", tables["lengthening_speed"]),
                         ("MomentArm_knee_angle_r", tables["moment_arm"]["knee_angle_r"]),
                         ("MomentArm_hip_flexion_l", tables["moment_arm"]["hip_flexion_l"])]:
        labels, time, expected = read_sto(tmp_path / f"{name}.sto")
        assert labels == tables["paths"]
        np.testing.assert_array_equal(time, tables["time"])
        np.testing.assert_array_equal(expected, values, err_msg=name)


def test_muscle_tables_of_a_result_equal_those_of_its_states_file(tmp_path):
    model = sinew.load(ARM26)
    result = model.simulate(0.05, equilibrate_muscles=True, report_interval=0.01)
    result.to_sto(tmp_path / "states.sto")
    from_result = model.analyze(result, coordinates=["r_elbow_flex"])
    from_file = model.analyze(tmp_path / "states.sto", coordinates=["r_elbow_flex"])
    run_cli_analyze(ARM26, tmp_path / "states.sto", tmp_path / "out",
                    "--coordinates", "r_elbow_flex")
    assert len(from_result["muscles"]) == 6
    for key, name in [("fiber_length", "FiberLength"), ("tendon_length", "TendonLength"),
                      ("active_fiber_force", "ActiveFiberForce"),
                      ("passive_fiber_force", "PassiveFiberForce"),
                      ("tendon_force", "TendonForce")]:
        labels, _, expected = read_sto(tmp_path / "out" / f"{name}.sto")
        assert labels == from_result["muscles"]
        np.testing.assert_array_equal(from_file[key], from_result[key], err_msg=key)
        np.testing.assert_array_equal(expected, from_result[key], err_msg=key)
    # The fiber lengths are the run's own fiber_length states.
    for k, muscle in enumerate(from_result["muscles"]):
        z = result.state_variables.index(f"{muscle}/fiber_length")
        np.testing.assert_array_equal(from_result["fiber_length"][:, k], result.z[:, z])
    # The path lengths are fiber along the tendon plus tendon: positive, and the tendons pull.
    assert np.all(from_result["tendon_force"] > 0.0)


def test_unknown_coordinate_is_an_error_and_a_short_motion_a_warning(tmp_path):
    model = sinew.load(ARM26)
    with pytest.raises(sinew.Error, match="coordinates: the model has no coordinate 'elbow'"):
        model.analyze(GAIT1018_MOTION, coordinates=["elbow"])
    motion = tmp_path / "pose.mot"
    motion.write_text("pose\nversion=1\nnRows=1\nnColumns=2\ninDegrees=yes\nendheader\n"
                      "time\tr_elbow_flex\n0\t30\n")
    with pytest.warns(UserWarning, match="lengthening speeds are written as NaN"):
        tables = model.analyze(motion)
    assert tables["length"].shape == (1, 6)
    assert np.all(np.isnan(tables["lengthening_speed"]))
    assert np.all(np.isfinite(tables["length"]))
