"""Model.simulate runs what `sinew simulate` runs: the same arrays bit for bit, and the same
states.sto byte for byte (Result.to_sto), with initial states, excitations, and the rk45, cvode
and euler integrators."""
import os
import re
import subprocess

import numpy as np
import pytest

import sinew
from conftest import CHRONO, DATA, RESOURCES, read_sto

CASES = {
    "rk45 from initial states": (
        RESOURCES / "DoublePendulum3D.osim",
        ["--duration", 1, "--accuracy", 1e-8, "--initial-states",
         RESOURCES / "DoublePendulum3D_InitialStates.sto"],
        dict(duration=1.0, accuracy=1e-8,
             initial_states=RESOURCES / "DoublePendulum3D_InitialStates.sto")),
    "euler with a report interval": (
        RESOURCES / "SinglePin.osim",
        ["--duration", 0.5, "--integrator", "euler", "--step", 1e-3, "--report-interval", 0.05],
        dict(duration=0.5, integrator="euler", step=1e-3, report_interval=0.05)),
    "cvode (implicit BDF) with dense output": (
        RESOURCES / "DoublePendulum3D.osim",
        ["--duration", 0.5, "--integrator", "cvode", "--accuracy", 1e-7,
         "--report-interval", 0.02],
        dict(duration=0.5, integrator="cvode", accuracy=1e-7, report_interval=0.02)),
    "excitations": (
        CHRONO / "double_pendulum.osim",
        ["--duration", 0.5, "--excitation", "Torq1=sine:0.5,2,0.1", "--excitation",
         "Torq2=ramp:0.1,2"],
        dict(duration=0.5, excitations={"Torq1": sinew.Sine(0.5, 2, 0.1),
                                        "Torq2": sinew.Ramp(0.1, 2)})),
}


@pytest.mark.parametrize("case", list(CASES))
def test_simulate_equals_cli_bit_for_bit(case, cli, tmp_path):
    model_file, args, options = CASES[case]
    states = cli([model_file, *args], tmp_path / "cli")
    options = dict(options)
    result = sinew.load(model_file).simulate(options.pop("duration"), **options)
    labels, time, values = read_sto(states)
    assert labels == result.labels
    assert np.array_equal(time, result.time)
    assert np.array_equal(values, result.states)
    for c, coordinate in enumerate(result.coordinates):
        column = [i for i, label in enumerate(labels) if label.endswith(f"/{coordinate}/value")]
        assert np.array_equal(values[:, column[0]], result.q[:, c])
    result.to_sto(tmp_path / "python.sto")
    assert (tmp_path / "python.sto").read_bytes() == states.read_bytes()


def test_constant_excitation_equals_cli(cli, tmp_path):
    states = cli([CHRONO / "torque-actuator.osim", "--duration", 0.3, "--excitation",
                  "grav=constant:0.7"], tmp_path / "cli")
    result = sinew.load(CHRONO / "torque-actuator.osim").simulate(0.3, excitations={"grav": 0.7})
    assert np.array_equal(read_sto(states)[2], result.states)


def test_python_function_excitation_equals_the_library_function():
    # A Python callable is called at every evaluation; t -> t is Ramp(0, 1) to the last bit.
    model = sinew.load(CHRONO / "torque-actuator.osim")
    ramp = model.simulate(0.5, excitations={"grav": sinew.Ramp(0.0, 1.0)})
    function = model.simulate(0.5, excitations={"grav": lambda t: t})
    assert np.array_equal(ramp.states, function.states)

    def broken(t):
        raise ValueError("no excitation at this time")
    with pytest.raises(ValueError, match="no excitation"):
        model.simulate(0.5, excitations={"grav": broken})


@pytest.mark.parametrize("equilibrate", [False, True])
def test_initial_muscle_states_are_taken_as_the_cli_takes_them(cli, tmp_path, equilibrate):
    # A states table whose first row sets arm26's activations to 0.5 and its fibers to a run's:
    # simulate(initial_states=...) starts from those state variables (and, when asked, from
    # equilibrium at those activations), as `sinew simulate --initial-states` does.
    arm26 = DATA / "opensim-org/opensim-models/Models/Arm26/arm26.osim"
    model = sinew.load(arm26)
    model.simulate(0.02, equilibrate_muscles=True).to_sto(tmp_path / "run.sto")
    lines = (tmp_path / "run.sto").read_text().splitlines()
    end = lines.index("endheader")
    labels = lines[end + 1].split("\t")
    row = [("0.5" if label.endswith("/activation") else value)
           for label, value in zip(labels, lines[end + 2].split("\t"))]
    lines = [line for line in lines[:end] if not line.startswith("nRows")]
    start = tmp_path / "start.sto"
    start.write_text("\n".join([*lines, "endheader", "\t".join(labels),
                                "\t".join(row)]) + "\n")
    extra = ["--equilibrate-muscles"] if equilibrate else []
    states = cli([arm26, "--duration", 0.05, "--initial-states", start, *extra], tmp_path / "cli")
    result = model.simulate(0.05, initial_states=start, equilibrate_muscles=equilibrate)
    _, _, values = read_sto(states)
    assert np.array_equal(values, result.states)
    activations = [k for k, name in enumerate(result.state_variables)
                   if name.endswith("/activation")]
    assert np.all(result.z[0, activations] == 0.5)


def test_statistics_are_the_clis_summary_with_the_spline_breakpoints_crossed(tmp_path):
    # gait2354's right knee swung at -10 rad/s from -0.1 rad crosses knots of its splines (there
    # are knots at 0 to 2.1 rad); at accuracy 1e-8 rk45 ends a failing step at two of them.
    # Result.statistics counts what `sinew simulate` prints: steps, rejected trials,
    # evaluations, and those breakpoints.
    program = os.environ.get("SINEW_CLI")
    if not program:
        pytest.skip("SINEW_CLI is not set (ctest sets it to the built sinew program)")
    gait2354 = DATA / "opensim-org/opensim-core/OpenSim/Simulation/Test/gait2354_simbody.osim"
    start = tmp_path / "start.sto"
    start.write_text("start\nversion=1\nnRows=1\nnColumns=3\ninDegrees=no\nendheader\n"
                     "time\t/jointset/knee_r/knee_angle_r/value\t"
                     "/jointset/knee_r/knee_angle_r/speed\n0\t-0.1\t-10\n")
    run = subprocess.run([program, "simulate", str(gait2354), "--duration", "0.05", "--accuracy",
                          "1e-8", "--initial-states", str(start), "--out", str(tmp_path / "cli")],
                         check=True, capture_output=True, text=True)
    summary = re.search(r"(\d+) steps \((\d+) rejected\), (\d+) evaluations, (\d+) spline "
                        r"breakpoints? crossed", run.stdout)
    assert summary, run.stdout
    steps, rejected, evaluations, crossed = map(int, summary.groups())
    assert crossed > 0
    statistics = sinew.load(gait2354).simulate(0.05, accuracy=1e-8,
                                               initial_states=start).statistics
    assert statistics["steps"] == steps
    assert statistics["rejected"] == rejected
    assert statistics["evaluations"] == evaluations
    assert statistics["breakpoints_crossed"] == crossed
