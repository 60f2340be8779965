"""sinew.load(..., parameters=...) overrides model properties before the model is built: the
overridden models follow their closed forms (a pendulum's large-amplitude period, a spring's
frequency), a muscle's override equals an edited copy of the file bit for bit, sweeps ship
per-case parameters to Dask workers, and bad overrides raise sinew.Error with file, line and
component."""
import math
import pathlib

import numpy as np
import pytest

import sinew
from conftest import DATA, RESOURCES
from sinew.sweep import run_case

SINGLE_PIN = RESOURCES / "SinglePin.osim"
SPRINGS = DATA / "sinew/springs.osim"
ARM26 = DATA / "opensim-org/opensim-core/Applications/Forward/tests/resources/arm26.osim"


def elliptic_k(k):
    """The complete elliptic integral of the first kind, K(k) = pi / (2 AGM(1, sqrt(1 - k^2)));
    the arithmetic-geometric mean converges quadratically: 8 rounds reach double precision for
    k < 0.99."""
    a, b = 1.0, math.sqrt(1.0 - k * k)
    for _ in range(8):
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return math.pi / (2.0 * a)


def full_period(time, speed):
    """The time at which `speed`, starting at rest and first going negative, crosses zero from
    positive to negative: one full period of a pendulum released from rest at a positive angle
    (linear interpolation between samples)."""
    down = np.nonzero((speed[1:-1] > 0) & (speed[2:] <= 0))[0] + 1
    i = down[0]
    return time[i] + (time[i + 1] - time[i]) * speed[i] / (speed[i] - speed[i + 1])


def line_of(path, text):
    """The 1-based line of the first line of `path` that contains `text`."""
    lines = pathlib.Path(path).read_text().splitlines()
    return next(n for n, line in enumerate(lines, 1) if text in line)


def test_single_pin_with_moved_mass_centre_has_the_exact_large_amplitude_period():
    # SinglePin's rod (m = 0.75 kg, I = 0.025 kg m^2 about its mass centre) hangs from a pin at
    # (0, 0.5, 0) in its body frame. Moving the mass centre to (0, 0.2, 0) puts it d = 0.3 m
    # below the pin; the release angle comes from the coordinate's default_value. The exact
    # period is T = 4 K(sin(a/2)) / w0, w0^2 = m g d / (I + m d^2).
    m, inertia, d, g, amplitude = 0.75, 0.025, 0.3, 9.80665, 2.0
    model = sinew.load(SINGLE_PIN, parameters={"rod1/mass_center": [0.0, 0.2, 0.0],
                                               "r1_z/default_value": amplitude})
    assert model.default_state().q[0] == amplitude
    w0 = math.sqrt(m * g * d / (inertia + m * d * d))
    exact = 4.0 * elliptic_k(math.sin(amplitude / 2.0)) / w0
    h = 1e-3
    result = model.simulate(1.1 * exact, accuracy=1e-10, report_interval=h)
    measured = full_period(result.time, result.u[:, 0])
    # At the turning point u = 0 and u'' = -w0^2 cos(q) u = 0, so linear interpolation of the
    # crossing errs by O(h^3) = 1e-9 s (6e-10 of T = 1.71 s); rk45 keeps each step's error
    # below accuracy 1e-10, and ~320 steps accumulate at most 3.2e-8 of phase. Bound: 5e-8
    # relative (measured 2.1e-11). The unmodified rod (d = 0.5) differs by more than 10%.
    assert abs(measured - exact) / exact < 5e-8, (measured, exact)
    d0 = 0.5
    original = 4.0 * elliptic_k(math.sin(amplitude / 2.0)) / math.sqrt(
        m * g * d0 / (inertia + m * d0 * d0))
    assert abs(original - exact) / exact > 0.1


def test_spring_stiffness_and_mass_overrides_give_sqrt_k_over_m():
    # springs.osim's block slides on ground x with SpringGeneralizedForce block_spring (rest
    # length 0.3 m, no viscosity), released at rest from block_x's default: with stiffness k and
    # mass m, block_x(t) = 0.3 + (x0 - 0.3) cos(sqrt(k / m) t).
    k, m, x0 = 72.0, 0.5, 0.45
    model = sinew.load(SPRINGS, parameters={"block_spring/stiffness": k, "block/mass": m,
                                            "/jointset/block_slide/block_x/default_value": x0})
    result = model.simulate(2.0, accuracy=1e-11, report_interval=0.01)
    column = result.coordinates.index("block_x")
    expected = 0.3 + (x0 - 0.3) * np.cos(math.sqrt(k / m) * result.time)
    # rk45 keeps each step's error below accuracy 1e-11 (the states are of order 1); the whole
    # model (its swinging arm too) takes ~1450 steps in 2 s, which accumulate at most 1.5e-8 m.
    # Bound: 2e-8 m (measured 4.4e-12 m).
    worst = np.max(np.abs(result.q[:, column] - expected))
    assert worst < 2e-8, worst


def test_muscle_override_equals_an_edited_copy_of_the_file_bit_for_bit(tmp_path):
    value = 901.25
    text = ARM26.read_text()
    start = text.index('<Thelen2003Muscle name="BIClong">')
    begin = text.index("<max_isometric_force>", start)
    end = text.index("</max_isometric_force>", begin)
    edited = tmp_path / "arm26_edited.osim"
    edited.write_text(text[:begin] + f"<max_isometric_force> {value} " + text[end:])
    excitations = {"BIClong": 0.8, "TRIlong": 0.1}
    overridden = sinew.load(ARM26, parameters={"BIClong/max_isometric_force": value})
    copy = sinew.load(edited)
    original = sinew.load(ARM26)
    runs = [model.simulate(0.2, accuracy=1e-6, excitations=excitations)
            for model in (overridden, copy, original)]
    assert np.array_equal(runs[0].states, runs[1].states)
    # The override does something: the unmodified file's elbow moves differently.
    assert not np.array_equal(runs[0].q, runs[2].q)


def test_sweep_ships_per_case_parameters():
    cases = [{"duration": 0.3, "parameters": {"block_spring/stiffness": k, "block/mass": m}}
             for k, m in ((20.0, 1.0), (50.0, 2.0), (80.0, 0.5))]
    cases.append({"duration": 0.3, "load": {"parameters": {"block_spring/rest_length": 0.5}}})
    results = sinew.sweep(SPRINGS, cases)
    column = results[0].coordinates.index("block_x")
    for case, result in zip(cases, results):
        local = run_case(str(SPRINGS), case)
        assert np.array_equal(result.time, local.time)
        assert np.array_equal(result.q, local.q)
        assert np.array_equal(result.u, local.u)
    # k / m = 20 and 25: different frequencies, different trajectories.
    assert not np.array_equal(results[0].q[:, column], results[1].q[:, column])
    with pytest.raises(ValueError):
        run_case(str(SPRINGS), {"duration": 0.1, "parameters": {"block/mass": 1.0},
                                "load": {"parameters": {"block/mass": 2.0}}})


def expect_error(parameters, line, component, words, path=SPRINGS):
    with pytest.raises(sinew.Error) as caught:
        sinew.load(path, parameters=parameters)
    error = caught.value
    assert error.file == str(path)
    assert error.line == line, str(error)
    assert error.component == component, str(error)
    assert words in error.message, str(error)


def test_bad_overrides_raise_errors_with_file_line_and_component():
    expect_error({"blok/mass": 1.0}, 0, "blok", "close names: block")
    expect_error({"block/mass_center": [1.0, 2.0]}, line_of(SPRINGS, '<Body name="block">'),
                 "/bodyset/block", "expects 3 numbers, given 2")
    expect_error({"block/mass": -2.0}, line_of(SPRINGS, '<Body name="block">'), "/bodyset/block",
                 "negative")
    expect_error({"block_spring/stiffness": math.nan}, line_of(SPRINGS, "<stiffness>50"),
                 "/forceset/block_spring", "NaN")
    expect_error({"block_spring/coordinate": 1.0}, line_of(SPRINGS, "<coordinate>block_x"),
                 "/forceset/block_spring", "not a numeric property")
    expect_error({"block_spring/damping": 1.0},
                 line_of(SPRINGS, '<SpringGeneralizedForce name="block_spring">'),
                 "/forceset/block_spring", "no such property")
    expect_error({"arm_pin/reverse": 1.0}, line_of(SPRINGS, '<PinJoint name="arm_pin">'),
                 "/jointset/arm_pin", "cannot be overridden yet")
    expect_error({"block/mass": "heavy"}, 0, "block/mass", "expects a number")
    expect_error({"block/mass": True}, 0, "block/mass", "expects a number")
    expect_error({"mass": 1.0}, 0, "mass", "<component>/<property>")


def test_overrides_survive_initial_states_and_numpy_values():
    # Model.simulate(initial_states=file) builds the model again from its file: the parameters
    # stay; the states row sets the coordinates' defaults over them.
    model = sinew.load(SINGLE_PIN, parameters={"rod1/mass": np.float64(1.5),
                                               "rod1/mass_center": np.array([0.0, 0.1, 0.0])})
    plain = sinew.load(SINGLE_PIN)
    initial = RESOURCES / "SinglePin_InitialStates.sto"
    a = model.simulate(0.2, initial_states=initial)
    b = plain.simulate(0.2, initial_states=initial)
    assert a.q[0, 0] == b.q[0, 0]
    assert not np.array_equal(a.q, b.q)


def test_cylinder_refinement_is_a_load_option_that_changes_arm26():
    # arm26's BRA crosses the elbow over one WrapCylinder. OpenSim 4.4's rule (the default)
    # does not refine the tangent points of a path with one wrap object; every earlier OpenSim
    # did ("always"): BRA's elbow moment arm differs by 2.2e-4 m at full extension
    # (docs/wrapping.md), and arm26's start is far from equilibrium (BRA pulls 7 kN), so the
    # accelerations differ by about 1.5% (docs/forward.md) and the runs part by far more than
    # the integration error at accuracy 1e-8.
    runs = {rule: sinew.load(ARM26, cylinder_refinement=rule).simulate(0.05, accuracy=1e-8)
            for rule in ("several-wraps", "opensim-4.4", "always")}
    default = sinew.load(ARM26).simulate(0.05, accuracy=1e-8)
    np.testing.assert_array_equal(default.u, runs["several-wraps"].u)
    assert np.max(np.abs(runs["always"].u - runs["several-wraps"].u)) > 1e-4
    # OpenSim 4.4.0's rule refines the same paths (not BRA's) and differs from 4.4.1's only in
    # how a refinement checks its second tangent point: much closer than "always".
    assert (np.max(np.abs(runs["opensim-4.4"].u - runs["several-wraps"].u))
            < 0.1 * np.max(np.abs(runs["always"].u - runs["several-wraps"].u)))
    # Anything else is refused by name.
    with pytest.raises(sinew.Error, match="cylinder_refinement"):
        sinew.load(ARM26, cylinder_refinement="sometimes")
