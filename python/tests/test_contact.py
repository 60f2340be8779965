"""Collision from Python: load(collision=True, contact="smc"|"nsc") makes the seed's collision
shapes collide as `sinew simulate --collision --contact ...` does, and render/export draw its
contact forces as `sinew render|export --contacts` do (docs/contact.md)."""
import math
import os
import subprocess
import warnings

import numpy as np
import pytest

import sinew
from conftest import DATA, read_sto

BALL = DATA / "sinew" / "ball_on_floor.osim"
TABLE = DATA / "sinew" / "table_on_floor.osim"


def test_ball_rests_at_hertz_static_depth_with_smc():
    # A 1 kg ball of radius 0.1 m (ContactSphere) dropped 0.2 m on the ContactHalfSpace floor,
    # default material (E = 1e7 Pa, nu = 0.3 for both: E* = E / (2 (1 - nu^2))). At rest
    # the Hertz force 4/3 E* sqrt(R) d^(3/2) carries the weight m g, so the centre rests at
    # R - d with d = (3 m g / (4 E* sqrt(R)))^(2/3) = 0.26 mm. The bounces (restitution 0.4)
    # die out by 0.5 s and the damping's decay time is a few ms; rk45 at 1e-8 resolves d to
    # far better than the 1 um asserted.
    model = sinew.load(BALL, collision=True, contact="smc")
    result = model.simulate(1.5, accuracy=1e-8, report_interval=0.05)
    ty = result.q[:, result.coordinates.index("ty")]
    radius, mass, g = 0.1, 1.0, 9.80665
    e_star = 1e7 / (2.0 * (1.0 - 0.3 ** 2))
    depth = (3.0 * mass * g / (4.0 * e_star * math.sqrt(radius))) ** (2.0 / 3.0)
    assert abs(ty[0] - 0.3) < 1e-12
    assert abs(ty[-1] - (radius - depth)) < 1e-6, (ty[-1], radius - depth)
    assert abs(result.u[-1, result.coordinates.index("ty")]) < 1e-4


def test_nsc_simulate_equals_cli_bit_for_bit_and_rests_on_the_floor(cli, tmp_path):
    # contact="nsc" runs the NSC stepper (opensim::MakeRunIntegrator, fixed step 1 ms) as
    # `sinew simulate --collision --contact nsc` does. The ball comes to rest touching the floor
    # (docs/contact.md).
    states = cli([BALL, "--collision", "--contact", "nsc", "--duration", 1.0,
                  "--report-interval", 0.01], tmp_path / "cli")
    result = sinew.load(BALL, collision=True, contact="nsc").simulate(1.0, report_interval=0.01)
    labels, time, values = read_sto(states)
    assert labels == result.labels
    assert np.array_equal(time, result.time)
    assert np.array_equal(values, result.states)
    ty = result.q[:, result.coordinates.index("ty")]
    assert 0.1 - 2e-3 - 1e-9 <= ty[-1] <= 0.1 + 1e-9
    assert abs(result.u[-1, result.coordinates.index("ty")]) < 1e-6


def test_nsc_simulator_steps_as_simulate_does():
    # The same 1 ms NSC steps: the Simulator ends step k at exactly k h, the driver at its own
    # report grid, so the two agree to round-off rather than bit for bit.
    model = sinew.load(BALL, collision=True, contact="nsc")
    simulator = model.simulator(1e-3)
    simulator.reset()
    for _ in range(1000):
        simulator.step()
    result = model.simulate(1.0, step=1e-3, report_interval=0.5)
    assert np.allclose(simulator.state.q, result.q[-1], rtol=0.0, atol=1e-12)
    ty = simulator.state.q[model.coordinates.index("ty")]
    assert abs(ty - 0.1) < 1e-9  # resting on its radius (the envelope is exact for spheres)


def test_contacts_table_is_contacts_sto_and_carries_the_weight_at_rest(cli, tmp_path):
    # Result.contacts holds what `sinew simulate` writes to contacts.sto (same labels, times and
    # values, bit for bit, for SMC and NSC), and Result.contacts_to_sto writes that file byte
    # for byte. At rest the floor carries the 1 kg ball: its contact force is (0, m g, 0) with
    # no torque about its centre, and ground takes the opposite (SMC: to the 1 um Hertz depth's
    # settling, 1e-4 relative; NSC: to the solver's 1e-6 m/s tolerance on the ball's speed at
    # both ends of a step of h = 1 ms, m 2e-6 / 1e-3 = 2e-3 N).
    weight = 1.0 * 9.80665
    for contact, tolerance in (("smc", 1e-4 * weight), ("nsc", 2e-3)):
        states = cli([BALL, "--collision", "--contact", contact, "--duration", 1.5,
                      "--report-interval", 0.05], tmp_path / contact)
        result = sinew.load(BALL, collision=True, contact=contact).simulate(
            1.5, report_interval=0.05)
        labels, time, values = read_sto(states.parent / "contacts.sto")
        assert result.contact_labels == labels
        assert np.array_equal(result.time, time)
        assert np.array_equal(result.contacts, values)
        assert result.contacts.shape == (len(result.time), len(labels))
        name = "smc_contact" if contact == "smc" else "nsc_contact"
        column = {label: result.contacts[-1, k] for k, label in enumerate(labels)}
        assert abs(column[f"{name}.ball.force.Y"] - weight) < tolerance
        assert abs(column[f"{name}.ball.force.X"]) < tolerance
        assert abs(column[f"{name}.ball.force.Z"]) < tolerance
        assert abs(column[f"{name}.ground.force.Y"] + weight) < tolerance
        for axis in "XYZ":  # about the centre, where the contact force's line passes
            assert abs(column[f"{name}.ball.torque.{axis}"]) < 0.1 * tolerance
        assert column[f"{name}.active_contacts"] == 1
        assert column[f"{name}.ground-ball.active_contacts"] == 1
        written = tmp_path / f"{contact}_contacts.sto"
        result.contacts_to_sto(written)
        assert written.read_bytes() == (states.parent / "contacts.sto").read_bytes()


def test_nsc_solver_settings_act_as_the_cli_options_do(cli, tmp_path):
    # load(nsc_iterations=...) is `sinew simulate --nsc-iterations`: the table lands on four
    # legs at once (coupled contacts: one APGD iteration cannot solve the impact), so with one
    # iteration allowed steps end above the tolerance. Result.contacts (with the solver's
    # columns) equals the CLI's contacts.sto bit for bit; the statistics count the unconverged
    # steps as the table's last row does, with a UserWarning.
    contacts = cli([TABLE, "--collision", "--contact", "nsc", "--nsc-iterations", 1,
                    "--duration", 0.5, "--report-interval", 0.001], tmp_path / "cli")
    model = sinew.load(TABLE, collision=True, contact="nsc", nsc_iterations=1)
    with pytest.warns(UserWarning, match="did NOT reach its tolerance of 1e-06 m/s"):
        result = model.simulate(0.5, report_interval=0.001)
    labels, time, values = read_sto(contacts.parent / "contacts.sto")
    assert result.contact_labels == labels
    assert np.array_equal(result.contacts, values)
    column = {label: result.contacts[:, k] for k, label in enumerate(labels)}
    statistics = result.statistics
    assert column["nsc_contact.solver_iterations"].max() == 1
    assert statistics["nsc_most_iterations"] == 1
    assert statistics["nsc_unconverged_steps"] > 0
    assert statistics["nsc_unconverged_steps"] == column["nsc_contact.unconverged_steps"][-1]
    assert statistics["nsc_worst_residual"] > 1e-6
    assert statistics["nsc_worst_residual"] >= column["nsc_contact.solver_residual"].max()
    assert 0 < statistics["nsc_solves"] <= 500


def test_strict_refuses_nsc_steps_above_the_solver_tolerance():
    # strict=True makes the unconverged steps an error instead of a warning (as the CLI's
    # --strict); with the default settings every step converges and strict changes nothing.
    model = sinew.load(TABLE, collision=True, contact="nsc", nsc_iterations=1, strict=True)
    with pytest.raises(sinew.Error, match=r"did NOT reach its tolerance.*\(strict\)"):
        model.simulate(0.5, report_interval=0.01)
    strict = sinew.load(TABLE, collision=True, contact="nsc", strict=True).simulate(0.5)
    plain = sinew.load(TABLE, collision=True, contact="nsc").simulate(0.5)
    assert strict.statistics["nsc_unconverged_steps"] == 0
    assert np.array_equal(strict.q, plain.q)


def stepped_table(model, steps, h=1e-3):
    """A Simulator of `model` stepped `steps` times by h, and the warnings each step gave."""
    simulator = model.simulator(h)
    per_step = []
    for _ in range(steps):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            simulator.step()
        per_step.append([str(w.message) for w in caught if w.category is UserWarning])
    return simulator, per_step


def test_simulator_statistics_are_simulates_over_the_same_steps():
    # Simulator.statistics has Result.statistics' keys and meanings, counted since the last
    # reset. Stepped by NSC's 1 ms to 0.2 s (the table lands at about 0.1 s: a 5 cm fall),
    # the Simulator takes the steps simulate takes with report_interval = step (both end step
    # k at t0 + k h), so every figure, the worst residual too, is simulate's. One iteration
    # leaves landing steps unconverged (docs/contact.md); repeat= steps the same; reset() and
    # a new Simulator start from zero.
    model = sinew.load(TABLE, collision=True, contact="nsc", nsc_iterations=1)
    with pytest.warns(UserWarning, match="did NOT reach"):
        expected = model.simulate(0.2, step=1e-3, report_interval=1e-3).statistics
    assert expected["steps"] == 200 and expected["nsc_unconverged_steps"] > 0
    simulator, _ = stepped_table(model, 200)
    assert simulator.statistics == expected
    repeated = model.simulator(1e-3)
    assert all(value == 0 for value in repeated.statistics.values())
    with pytest.warns(UserWarning, match="did NOT reach"):
        repeated.step(repeat=200)
    assert repeated.statistics == expected
    simulator.reset()
    assert simulator.statistics.keys() == expected.keys()
    assert all(value == 0 for value in simulator.statistics.values())
    # At the defaults every solve converges, in simulate and the Simulator alike.
    plain = sinew.load(TABLE, collision=True, contact="nsc")
    expected = plain.simulate(0.2, step=1e-3, report_interval=1e-3).statistics
    simulator, messages = stepped_table(plain, 200)
    assert simulator.statistics == expected
    assert expected["nsc_unconverged_steps"] == 0 and expected["nsc_solves"] > 0
    assert not any(messages)


def test_simulator_warns_where_unconverged_steps_first_happen_and_strict_raises():
    # The Simulator's UserWarning comes from the step() in which its statistics first count an
    # unconverged NSC step, once per reset; with strict=True every step() that adds one raises
    # sinew.Error (after the step) and at the defaults none does.
    model = sinew.load(TABLE, collision=True, contact="nsc", nsc_iterations=1)
    simulator = model.simulator(1e-3)
    for _ in range(2):  # again after a reset
        counts, warned = [], []
        for _ in range(200):
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                simulator.step()
            counts.append(simulator.statistics["nsc_unconverged_steps"])
            warned.append([str(w.message) for w in caught])
        first = next(k for k, count in enumerate(counts) if count > 0)
        assert [k for k, messages in enumerate(warned) if messages] == [first]
        assert len(warned[first]) == 1
        assert warned[first][0].startswith(f"Simulator at t = {(first + 1) * 1e-3:g} s")
        assert f"tolerance of 1e-06 m/s in {counts[first]} of" in warned[first][0]
        simulator.reset()
    strict = sinew.load(TABLE, collision=True, contact="nsc", nsc_iterations=1,
                        strict=True).simulator(1e-3)
    raised = 0
    for _ in range(200):
        before = strict.statistics["nsc_unconverged_steps"]
        try:
            strict.step()
            failed = False
        except sinew.Error as error:
            assert "did NOT reach its tolerance" in str(error) and "(strict)" in str(error)
            failed = True
        raised += failed
        assert failed == (strict.statistics["nsc_unconverged_steps"] > before)
    assert raised == strict.statistics["nsc_unconverged_steps"] > 0
    defaults = sinew.load(TABLE, collision=True, contact="nsc", strict=True).simulator(1e-3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        defaults.step(repeat=200)
    assert defaults.statistics["nsc_unconverged_steps"] == 0


def test_batch_statistics_are_each_copys_simulator_statistics():
    # Batch.statistics: per key an array [n] (as Batch.t), entry i copy i's statistics, equal
    # to those of a Simulator stepped from the same state. The copies start 0, 1, 2, 3 cm
    # higher, so they land at different steps; the one UserWarning of a step() names the copies
    # whose first unconverged step it took (once per reset), strict=True raises instead.
    model = sinew.load(TABLE, collision=True, contact="nsc", nsc_iterations=1)
    n, steps = 4, 250
    states = []
    for i in range(n):
        state = model.default_state()
        state.set_value("ty", state.value("ty") + 0.01 * i)
        states.append(state)
    batch = sinew.Batch(model, n, step=1e-3, threads=2)
    batch.reset(states)
    first = [None] * n
    warned = []
    for k in range(steps):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            batch.step()
        unconverged = batch.statistics["nsc_unconverged_steps"]
        news = [i for i in range(n) if unconverged[i] > 0 and first[i] is None]
        for i in news:
            first[i] = k
        messages = [str(w.message) for w in caught]
        assert len(messages) == (1 if news else 0), (k, messages)
        if news:
            more = f" (and {len(news) - 1} more copies)" if len(news) > 1 else ""
            assert messages[0].startswith(f"Batch copy {news[0]}{more} at t = ")
            warned.append(k)
    assert None not in first and len(set(first)) > 1  # they landed at different steps
    assert warned == sorted(set(first))
    statistics = batch.statistics
    for key, values in statistics.items():
        assert values.shape == (n,), key
    for i in range(n):
        simulator = model.simulator(1e-3, initial_states=states[i])
        with pytest.warns(UserWarning):
            simulator.step(repeat=steps)
        assert {key: values[i] for key, values in statistics.items()} == simulator.statistics
    batch.reset()
    assert all(np.all(values == 0) for values in batch.statistics.values())
    strict = sinew.Batch(sinew.load(TABLE, collision=True, contact="nsc", nsc_iterations=1,
                                    strict=True), n, step=1e-3, threads=2)
    with pytest.raises(sinew.Error, match=r"Batch copy 0 \(and 3 more copies\).*\(strict\)"):
        for _ in range(steps):
            strict.step()


def test_nsc_solver_defaults_and_both_methods():
    # The defaults are the library's (APGD, 1000, 1e-6 m/s, 0.1 m/s, 0.01 m/s): naming them
    # changes nothing. Gauss-Seidel and APGD at 1e-12 m/s meet it in every step and give the
    # ball (launched sideways at 1 m/s by its initial speed: lands, rolls, bounces, rests) the
    # same speeds: each leaves the contact's velocity within the tolerance of the law's, 2 tol
    # apart per step, adding up at most linearly over the N steps with contacts (over the radius
    # 0.1 m for the spin).
    default = sinew.load(BALL, collision=True, contact="nsc").simulate(0.5)
    named = sinew.load(BALL, collision=True, contact="nsc", nsc_solver="apgd",
                       nsc_iterations=1000, nsc_tolerance=1e-6, nsc_max_recovery_speed=0.1,
                       nsc_min_bounce_speed=0.01).simulate(0.5)
    assert np.array_equal(default.q, named.q) and np.array_equal(default.u, named.u)
    assert np.array_equal(default.contacts, named.contacts)
    runs = {}
    for solver in ("apgd", "gauss-seidel"):
        model = sinew.load(BALL, collision=True, contact="nsc", nsc_solver=solver,
                           nsc_iterations=10000, nsc_tolerance=1e-12)
        state = model.default_state()
        state.set_speed("tx", 1.0)
        runs[solver] = model.simulate(1.5, initial_states=state)
        assert runs[solver].statistics["nsc_unconverged_steps"] == 0
        assert runs[solver].statistics["nsc_worst_residual"] <= 1e-12
    # One sweep solves a single sphere contact exactly (its normal and tangential rows are
    # decoupled and W_tt is isotropic); so does APGD's first step, scaled by 1 / W_nn on the
    # normal row and 1 / lambda_max(W_tt) on the tangential ones: the scaled W is the identity
    # and L = 1. (Scaled by 1 / W_nn on all three rows, as before 2026-11-28, it could not be
    # exact on both, W_tt / W_nn = 1 + m r^2 / I = 3.5, and the landing took more than one.)
    assert runs["gauss-seidel"].statistics["nsc_most_iterations"] == 1
    assert runs["apgd"].statistics["nsc_most_iterations"] == 1
    steps = max(run.statistics["nsc_solves"] for run in runs.values())
    bound = 2 * 1e-12 * steps
    apgd, gauss_seidel = runs["apgd"], runs["gauss-seidel"]
    assert apgd.coordinates == gauss_seidel.coordinates
    for k, name in enumerate(apgd.coordinates):
        difference = np.abs(apgd.u[:, k] - gauss_seidel.u[:, k]).max()
        assert difference <= (bound / 0.1 if name.startswith("r") else bound), (name, difference)


def test_bad_or_misplaced_nsc_settings_are_errors():
    for options, message in (
            (dict(nsc_iterations=0), "nsc_iterations must be >= 1"),
            (dict(nsc_tolerance=0.0), "nsc_tolerance must be a finite number > 0"),
            (dict(nsc_tolerance=float("nan")), "nsc_tolerance must be a finite number > 0"),
            (dict(nsc_max_recovery_speed=-1.0), "nsc_max_recovery_speed must be"),
            (dict(nsc_min_bounce_speed=-1.0), "nsc_min_bounce_speed must be"),
            (dict(nsc_solver="jacobi"), 'nsc_solver must be "apgd" or "gauss-seidel"')):
        with pytest.raises(sinew.Error, match=message):
            sinew.load(BALL, collision=True, contact="nsc", **options)
    for options in (dict(collision=True, contact="smc"), dict(collision=False)):
        with pytest.raises(sinew.Error, match="need collision=True and contact=\"nsc\""):
            sinew.load(BALL, nsc_iterations=5, **options)


def test_run_without_contact_has_an_empty_contacts_table():
    result = sinew.load(BALL).simulate(0.1, report_interval=0.05)
    assert result.contact_labels == []
    assert result.contacts.shape == (len(result.time), 0)


def test_contact_mesh_found_in_geometry_dirs_and_ball_rests_in_the_groove(tmp_path):
    # The ball model with a ground ContactMesh (tests/data/sinew/v_groove.obj: an open V groove
    # whose walls rise at slope 1/2) copied where the mesh is not: load finds the mesh only
    # through geometry_dirs (as --geometry-dir), and without it the error names the file, the
    # component and the folders searched. The ground mesh collides as its triangles: dropped
    # from 0.3 m, the ball (r = 0.1 m) comes to rest on both walls with its centre at
    # r / cos(a) = r sqrt(5) / 2, centred (NSC stops a shape where it meets another, to the
    # solver's 1e-6 m/s over a 1 ms step: 1e-9 m along each wall's normal, so 1e-9 / cos(a) m
    # in height and 1e-9 / sin(a) m sideways, with tan(a) = 1/2; measured 2e-11 m with
    # Gauss-Seidel, 1.9e-9 m sideways with APGD), where the groove's convex hull would have
    # buried it.
    text = BALL.read_text().replace(
        '<ContactSphere name="sphere">',
        '<ContactMesh name="groove"><socket_frame>/ground</socket_frame>'
        '<filename>v_groove.obj</filename></ContactMesh>\n<ContactSphere name="sphere">')
    model_file = tmp_path / "groove.osim"
    model_file.write_text(text)
    try:
        sinew.load(model_file, collision=True)
        raise AssertionError("the mesh should not be found")
    except sinew.Error as error:
        assert error.component == "/contactgeometryset/groove"
        assert "'v_groove.obj' not found" in error.message
        assert str(tmp_path / "Geometry") in error.message
    model = sinew.load(model_file, collision=True, contact="nsc",
                       geometry_dirs=[DATA / "sinew"])
    result = model.simulate(1.0, report_interval=0.5)
    ty = result.q[-1, result.coordinates.index("ty")]
    tx = result.q[-1, result.coordinates.index("tx")]
    assert abs(ty - 0.1 * math.sqrt(5.0) / 2.0) < 1e-9 * math.sqrt(5.0) / 2.0, ty
    assert abs(tx) < 1e-9 * math.sqrt(5.0), tx


def test_render_and_export_draw_contacts_as_the_cli_does(cli, tmp_path):
    # Model.render(contacts=) and Model.export(contacts=) are `sinew render --contacts` and
    # `sinew export --contacts` byte for byte, from a contacts.sto or from a Result (whose
    # tables are the CLI's bit for bit, above). The NSC ball at rest at 1 s: the arrow changes
    # the picture; in the air (0.1 s) the force is zero and the picture is the plain one.
    program = os.environ["SINEW_CLI"]
    states = cli([BALL, "--collision", "--contact", "nsc", "--duration", 1.0,
                  "--report-interval", 0.01], tmp_path / "run")
    contacts = states.parent / "contacts.sto"
    result = sinew.load(BALL, collision=True, contact="nsc").simulate(1.0, report_interval=0.01)
    model = sinew.load(BALL)
    picture = ["--vis", "primitives", "--view", "front", "--width", "400", "--height", "400"]
    for time in (1.0, 0.1):
        subprocess.run([program, "render", BALL, "--states", states, "--contacts", contacts,
                        "--time", str(time), *picture, "--out", tmp_path / "cli.png"],
                       check=True, capture_output=True)
        options = dict(time=time, visualization="primitives", view="front", width=400,
                       height=400)
        model.render(tmp_path / "path.png", states, contacts=contacts, **options)
        model.render(tmp_path / "result.png", result, contacts=result, **options)
        model.render(tmp_path / "plain.png", states, **options)
        cli_png = (tmp_path / "cli.png").read_bytes()
        assert (tmp_path / "path.png").read_bytes() == cli_png
        assert (tmp_path / "result.png").read_bytes() == cli_png
        assert ((tmp_path / "plain.png").read_bytes() == cli_png) == (time == 0.1)
    subprocess.run([program, "export", BALL, "--states", states, "--contacts", contacts,
                    "--vis", "primitives", "--out", tmp_path / "cli.glb"],
                   check=True, capture_output=True)
    model.export(tmp_path / "path.glb", states, visualization="primitives", contacts=contacts)
    model.export(tmp_path / "result.glb", result, visualization="primitives", contacts=result)
    model.export(tmp_path / "plain.glb", states, visualization="primitives")
    cli_glb = (tmp_path / "cli.glb").read_bytes()
    assert (tmp_path / "path.glb").read_bytes() == cli_glb
    assert (tmp_path / "result.glb").read_bytes() == cli_glb
    assert b"nsc_contact.ball" in cli_glb
    assert b"nsc_contact.ball" not in (tmp_path / "plain.glb").read_bytes()
    with pytest.raises(sinew.Error, match="contacts need a motion"):
        model.render(tmp_path / "x.png", contacts=contacts)
    with pytest.raises(sinew.Error, match="contacts need a motion"):
        model.export(tmp_path / "x.glb", contacts=contacts)
    with pytest.raises(sinew.Error, match="no contacts table"):
        still = sinew.load(BALL).simulate(0.1)
        model.render(tmp_path / "x.png", still, contacts=still)


def test_contact_material_and_slip_speed_act_as_the_cli_options_do(cli, tmp_path):
    # The ball on tangential springs (kt, gt) with a softer floor and another slip speed, as
    # `sinew simulate --kt ... --gt ... --young-modulus ... --slip-speed ...`: bit for bit.
    material = {"kt": 1e7, "gt": 100.0, "young_modulus": 5e6, "friction": 0.4}
    states = cli([BALL, "--collision", "--contact", "smc", "--kt", 1e7, "--gt", 100,
                  "--young-modulus", 5e6, "--friction", 0.4, "--slip-speed", 0.01,
                  "--integrator", "euler", "--step", 1e-4, "--duration", 0.5],
                 tmp_path / "cli")
    result = sinew.load(BALL, collision=True, contact="smc", contact_material=material,
                        slip_speed=0.01).simulate(0.5, integrator="euler", step=1e-4)
    assert np.array_equal(read_sto(states)[2], result.states)
    default = sinew.load(BALL, collision=True, contact="smc").simulate(
        0.5, integrator="euler", step=1e-4)
    assert not np.array_equal(default.states, result.states)


def test_bad_or_misplaced_contact_materials_are_errors():
    for options, message in (
            (dict(contact_material={"stiffness": 1.0}), "unknown key 'stiffness'"),
            (dict(contact_material={"friction": -0.1}), "friction"),
            (dict(contact_material={"kt": "soft"}), "'kt' must be a number"),
            (dict(slip_speed=0.0), "slip_speed must be a finite number > 0")):
        with pytest.raises(sinew.Error, match=message):
            sinew.load(BALL, collision=True, contact="smc", **options)
    with pytest.raises(sinew.Error, match="need collision=True"):
        sinew.load(BALL, contact_material={"kt": 1e7})
    with pytest.raises(sinew.Error, match="needs contact=\"smc\""):
        sinew.load(BALL, collision=True, contact="nsc", slip_speed=0.01)
