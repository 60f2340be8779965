"""Model.kinematics and Model.export: Hamner's markers along its IK motion match OpenSim's
(the bound of KinematicsCliTest), a simulated pendulum's body poses follow the closed form, and
export writes what `sinew export` writes, byte for byte."""
import os
import subprocess

import numpy as np
import pytest

import sinew
from conftest import DATA, RESOURCES, read_sto

HAMNER = DATA / "opensim-org/opensim-models/Pipelines/Hamner/outputReference"


def test_hamner_markers_match_opensim():
    model = sinew.load(HAMNER / "subject02_registered.osim")
    kinematics = model.kinematics(HAMNER / "ResultsIK/subject02_running_ik.mot")
    labels, time, values = read_sto(HAMNER / "ResultsIK/ik_model_marker_locations.sto")
    assert np.allclose(kinematics["time"], time, rtol=0, atol=1e-12)
    worst, compared = 0.0, 0
    for k, marker in enumerate(kinematics["markers"]):
        if marker + "_tx" not in labels:  # OpenSim's file holds the markers IK used
            continue
        compared += 1
        for axis, suffix in enumerate(("_tx", "_ty", "_tz")):
            column = labels.index(marker + suffix)
            worst = max(worst, np.max(np.abs(kinematics["marker_positions"][:, k, axis] -
                                             values[:, column])))
    print(f"Hamner markers: {compared} compared, max |error| = {worst:.3g} m")
    assert compared == len(labels) // 3
    assert worst < 1e-6  # README: 6.9e-7 m over 599 frames


def test_pendulum_poses_follow_the_closed_form():
    # SinglePin's rod1 frame is 0.5 m below the pin, turned by q about z: p = 0.5 (sin q,
    # -cos q, 0), R = Rz(q).
    model = sinew.load(RESOURCES / "SinglePin.osim")
    result = model.simulate(0.5)
    kinematics = model.kinematics(result)
    q = result.q[:, 0]
    rod = kinematics["bodies"].index("rod1")
    p, R = kinematics["p_GB"][:, rod], kinematics["R_GB"][:, rod]
    assert np.allclose(p[:, 0], 0.5 * np.sin(q), rtol=0, atol=1e-12)
    assert np.allclose(p[:, 1], -0.5 * np.cos(q), rtol=0, atol=1e-12)
    assert np.allclose(R[:, 0, 0], np.cos(q), rtol=0, atol=1e-12)
    assert np.allclose(R[:, 1, 0], np.sin(q), rtol=0, atol=1e-12)
    default = model.kinematics()
    assert default["p_GB"].shape == (1, 2, 3)


def test_export_equals_cli(tmp_path):
    model_file = RESOURCES / "DoublePendulum3D.osim"
    result = sinew.load(model_file).simulate(0.3)
    result.to_sto(tmp_path / "states.sto")
    sinew.load(model_file).export(tmp_path / "python.glb", tmp_path / "states.sto",
                                  visualization="primitives")
    program = os.environ.get("SINEW_CLI")
    if program:
        subprocess.run([program, "export", model_file, "--states", tmp_path / "states.sto",
                        "--vis", "primitives", "--out", tmp_path / "cli.glb"],
                       check=True, capture_output=True)
        assert (tmp_path / "python.glb").read_bytes() == (tmp_path / "cli.glb").read_bytes()
    # A Result exports the same motion as its states file.
    sinew.load(model_file).export(tmp_path / "result.glb", result, visualization="primitives")
    assert (tmp_path / "result.glb").read_bytes() == (tmp_path / "python.glb").read_bytes()
    assert (tmp_path / "python.glb").read_bytes()[:4] == b"glTF"


def test_render_equals_cli(tmp_path):
    model_file = RESOURCES / "DoublePendulum3D.osim"
    result = sinew.load(model_file).simulate(0.3)
    result.to_sto(tmp_path / "states.sto")
    model = sinew.load(model_file)
    model.render(tmp_path / "python.png", result, time=0.2, visualization="primitives",
                 width=160, height=120, view="front")
    png = (tmp_path / "python.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    program = os.environ.get("SINEW_CLI")
    if program:
        subprocess.run([program, "render", model_file, "--states", tmp_path / "states.sto",
                        "--time", "0.2", "--vis", "primitives", "--width", "160", "--height",
                        "120", "--view", "front", "--out", tmp_path / "cli.png"],
                       check=True, capture_output=True)
        assert png == (tmp_path / "cli.png").read_bytes()
    with pytest.raises(sinew.Error):
        model.render(tmp_path / "bad.png", width=0)
