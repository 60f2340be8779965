"""Type stubs of the compiled module sinew._sinew (re-exported by `sinew`)."""
import os
from typing import Callable, Dict, List, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

from .result import Result

PathLike = Union[str, "os.PathLike[str]"]
ArrayLike = npt.ArrayLike


class Error(Exception):
    """Bad input or an impossible request: str(error) is 'file:line: component: message'."""
    file: str
    """The file the error is about ("" when none)."""
    line: int
    """The 1-based line in that file (0 when unknown)."""
    component: str
    """The model component's path or name ("" when none), e.g. /jointset/knee_r."""
    message: str
    """What is wrong."""


class Function:
    """A function of time u(t), used as an actuator's excitation."""
    def __call__(self, t: float) -> float:
        """The value at time t (s)."""


class Constant(Function):
    """u(t) = value."""
    def __init__(self, value: float) -> None: ...
    @property
    def value(self) -> float: ...


class Ramp(Function):
    """u(t) = 0 before start, slope * (t - start) from start on (not clamped)."""
    def __init__(self, start: float, slope: float) -> None: ...
    @property
    def start(self) -> float: ...
    @property
    def slope(self) -> float: ...


class Sine(Function):
    """u(t) = amplitude * sin(2 pi frequency_hz t + phase) + offset (phase in rad)."""
    def __init__(self, amplitude: float, frequency_hz: float, phase: float = 0.0,
                 offset: float = 0.0) -> None: ...
    @property
    def amplitude(self) -> float: ...
    @property
    def frequency_hz(self) -> float: ...
    @property
    def phase(self) -> float: ...
    @property
    def offset(self) -> float: ...


Excitation = Union[float, Function, Callable[[float], float]]


def load(path: PathLike, *, visualization: Optional[str] = None, collision: bool = False,
         contact: str = "nsc", strict: bool = False,
         parameters: Optional[Mapping[str, Union[float, Sequence[float]]]] = None,
         geometry_dirs: Sequence[PathLike] = (),
         cylinder_refinement: str = "several-wraps", nsc_solver: str = "apgd",
         nsc_iterations: int = 1000, nsc_tolerance: float = 1e-6,
         nsc_max_recovery_speed: float = 0.1, nsc_min_bounce_speed: float = 0.01,
         contact_material: Optional[Mapping[str, float]] = None,
         slip_speed: Optional[float] = None, external_loads: Sequence[PathLike] = (),
         disabled_forces: Sequence[str] = (),
         rename_force_classes: Optional[Mapping[str, str]] = None) -> "Model":
    """Reads an OpenSim model (.osim, every version 1.9 to 4.6) and builds what Sinew simulates.

    visualization: None/"none", "primitives" or "mesh" (visual assets of the bodies).
    collision: make the seed's collision shapes collide. contact: "smc" (penalty contact, a
    force: every integrator) or "nsc" (non-smooth: runs step with the NSC stepper at `step`,
    default 1 ms, whatever integrator is named). strict: anything approximated,
    substituted or not simulated is an Error.
    parameters: {"<component>/<property>": value} overriding what the file says before the
    model is built, in order; the component by name or path ("BIClong", "/forceset/BIClong"),
    the value a number, or a sequence of as many numbers as the property holds. Bodies: mass,
    mass_center (3), inertia (6: Ixx Iyy Izz Ixy Ixz Iyz) or inertia_xx ... inertia_yz.
    Coordinates: default_value, default_speed_value, range (2). Forces, actuators, muscles: any
    numeric property written directly in their element in the file (max_isometric_force,
    stiffness, optimal_force, ...). Joints, frames, path points, constraints, markers and
    controllers cannot be overridden yet.
    geometry_dirs: folders searched for mesh files (ContactMesh files too) after the model's
    folder and its Geometry/ folder, as `sinew simulate --geometry-dir`.
    cylinder_refinement: when a WrapCylinder refines its tangent points, as `sinew simulate
    --cylinder-refinement`: "several-wraps" (OpenSim 4.4 and later: only on paths with two or
    more wrap objects) or "always" (every OpenSim before 4.4, to compare with results it wrote).
    nsc_*: NSC's stepper, as `sinew simulate --nsc-*` (only with collision=True and
    contact="nsc"; other values than the defaults otherwise are an Error): nsc_solver "apgd"
    (accelerated projected gradient) or "gauss-seidel" (projected), the contact impulse solver;
    nsc_iterations (>= 1) its most iterations (sweeps) per step; nsc_tolerance (m/s, > 0) the
    largest violation of the contact law it stops at; nsc_max_recovery_speed (m/s, >= 0) the
    fastest an overlap is pushed out; nsc_min_bounce_speed (m/s, >= 0) restitution acts above
    it. The statistics of Model.simulate, Simulator and Batch count the steps whose solve
    stopped above the tolerance (with a UserWarning); simulate's contacts table has the
    solver's columns (docs/contact.md).
    Raises sinew.Error with file, line, component (also for an unknown or ambiguous component,
    a property it lacks, a wrong value, or a ContactMesh file not found: the message lists the
    folders searched).
    contact_material: the collision contact's default material, as `sinew simulate
    --friction ... --kt ...`: any of "friction", "restitution", "young_modulus",
    "poisson_ratio", "kn", "gn", "kt" (> 0: SMC's friction is a tangential spring per contact,
    kept from step to step) and "gt"; slip_speed: SMC's friction regularization speed (m/s,
    `--slip-speed`). Both need collision=True (slip_speed also contact="smc"); an unknown key
    or a bad value is a sinew.Error naming it.
    external_loads: OpenSim ExternalLoads files (.xml, each reading its datafile relative to
    itself): their ExternalForces act on the bodies they name, as `sinew simulate
    --external-loads`. disabled_forces: forces (of the model or of the external loads) left out
    by name, as `--disable-force`; a name no force has is a sinew.Error listing close names.
    rename_force_classes: {"OLD": "NEW"}: forces of class OLD are read as class NEW, as
    `--rename-force-class OLD=NEW` (OpenSim's own tests read Thelen2003Muscle as
    Thelen2003Muscle_Deprecated).
    """


def forward(setup: PathLike, *, model: Optional[PathLike] = None, integrator: str = "rk45",
            report_interval: float = 0.01, equilibrate_muscles: bool = False,
            cylinder_refinement: str = "several-wraps",
            rename_force_classes: Optional[Mapping[str, str]] = None,
            strict: bool = False) -> Result:
    """Runs an OpenSim ForwardTool setup file (*_Setup_Forward.xml) as `sinew forward` does and
    returns its states as a Result (bit for bit <name>_states.sto; nothing is written): the
    setup's model (or `model`) with its force_set_files (appended or replacing), external loads,
    ControlSet controls and states file (the row OpenSim takes at initial_time; the run then
    starts at that row's time), from there to final_time at integrator_error_tolerance within
    the step bounds, fibers at equilibrium when the setup or `equilibrate_muscles` asks.
    integrator: "rk45", "cvode", "cvode-gmres" or "cvode-gmres-bd". The setup's notes and what
    it sets that Sinew does not act on are UserWarnings (sinew.Error with strict=True); a setup
    without a model and no `model` is a sinew.Error.
    """


class Model:
    """A parsed model. Immutable; States, Simulators and Batches share it."""
    @property
    def path(self) -> str:
        """The .osim file it was read from."""
    @property
    def name(self) -> str:
        """The model's name in the file."""
    @property
    def coordinates(self) -> List[str]:
        """Coordinate names, the column order of q and u."""
    @property
    def bodies(self) -> List[str]:
        """Body names, ground first."""
    @property
    def actuators(self) -> List[str]:
        """Actuator names, the column order of controls and State.inputs."""
    @property
    def state_variables(self) -> List[str]:
        """Auxiliary state variables (<element>/<variable>), the column order of z."""
    @property
    def report(self) -> Dict[str, list]:
        """What the parser built, as data: bodies, joints (type, form, stand_in), forces
        (type, simulated, actuator, excitation_source, disabled), constraints, stand_ins
        (names of joints replaced by ball joints), warnings (file, line, component, message),
        not_simulated."""
    def default_state(self) -> "State":
        """Every coordinate at its default value and speed, assembled onto the constraints."""
    def equilibrate_muscles(self, state: "State") -> "State":
        """A copy of `state` with every muscle's fiber at muscle-tendon equilibrium at its pose,
        speeds and activations (OpenSim's equilibrateMuscles; the deprecated muscles by OpenSim's
        own iteration, balanced to 0.01 N). A muscle left unbalanced (a fiber at its minimum
        length, a deprecated muscle's tendon held at slack) is a UserWarning naming it; one
        without an equilibrium is a sinew.Error naming it."""
    def simulate(self, duration: float, *, accuracy: float = 1e-6, integrator: str = "rk45",
                 step: Optional[float] = None, report_interval: float = 0.01,
                 initial_states: Union[None, "State", PathLike] = None,
                 excitations: Optional[Mapping[str, Excitation]] = None,
                 controls: Optional[PathLike] = None,
                 equilibrate_muscles: bool = False) -> Result:
        """Forward simulation over `duration` s, what `sinew simulate` runs (same arrays bit for
        bit, Result.to_sto writes its states.sto byte for byte).

        integrator: "rk45" (error-controlled, accuracy), "cvode", "cvode-gmres" or
        "cvode-gmres-bd" (implicit, error-controlled, for stiff muscles), "euler" or "implicit-euler" (fixed `step`); for
        the error-controlled ones, step bounds the step. Reports at every multiple of report_interval
        and at the end. initial_states: a State, or a states table (.sto) whose first row
        gives the coordinates and the state variables it names (muscle activations, fiber
        lengths) as OpenSim's Forward tool takes it. excitations: actuator name ->
        number, Function, or Python function of time (called at every evaluation, slower),
        over the model's controllers. controls: an OpenSim ControlSet file.
        equilibrate_muscles: the fibers start at equilibrium at the initial state
        (equilibrate_muscles(), as `sinew simulate --equilibrate-muscles`); otherwise at the
        file's defaults or the initial state's values.
        Ctrl-C raises KeyboardInterrupt between steps.
        """
    def kinematics(self, motion: Union[None, PathLike, Result] = None) -> Dict[str, object]:
        """Body poses and marker positions in ground along `motion`: None (the default pose), a
        motion or states table (.mot/.sto; coordinates by name or OpenSim 4 path, degrees
        converted, coupler-driven coordinates following their drivers), or a Result.

        Returns time [n], bodies (names), p_GB [n, bodies, 3] (body origins, m), R_GB
        [n, bodies, 3, 3] (orientations), markers (names), marker_positions [n, markers, 3] (m).
        Constraints are not enforced (as `sinew kinematics`).
        """
    def analyze(self, motion: Union[PathLike, Result], *,
                coordinates: Optional[Sequence[str]] = None) -> Dict[str, object]:
        """OpenSim MuscleAnalysis-style tables of every geometry path (muscles, path springs,
        ligaments) along `motion` (a .mot/.sto table or a Result), the tables `sinew analyze`
        writes, bit for bit. Coordinate speeds are the derivative of OpenSim's quintic spline
        through each coordinate column (fewer than 6 rows: NaN speeds, a UserWarning).

        Returns time [n], paths (names), length and lengthening_speed [n, paths] (m, m/s),
        moment_arm: a dict from each coordinate of `coordinates` (default: every one not locked
        or coupled) to [n, paths] (m, OpenSim's moment arms); muscles: the muscles whose
        activation and fiber_length the table holds (a states table or a Result), and for them
        fiber_length, tendon_length (m), active_fiber_force, passive_fiber_force and
        tendon_force (N), each [n, muscles]. Paths Sinew does not compute, and wraps it does not
        apply, are a UserWarning; an unknown coordinate raises sinew.Error.
        """
    def export(self, path: PathLike, motion: Union[None, PathLike, Result] = None, *,
               visualization: str = "mesh", geometry_dirs: Sequence[str] = (),
               fps: float = 0.0, contacts: Union[None, PathLike, Result] = None) -> None:
        """Writes `motion` (as for kinematics) as a glTF file (.glb) or a self-contained HTML
        viewer (.html), byte for byte what `sinew export` writes. fps > 0 drops frames closer
        than 1/fps s. contacts (a contacts.sto path, or a Result: its contacts table) adds the
        contact forces as green arrows, as `sinew export --contacts` (needs a motion). Missing
        meshes and contact groups that name no body are a UserWarning."""
    def render(self, path: PathLike, motion: Union[None, PathLike, Result] = None, *,
               time: Optional[float] = None, visualization: str = "mesh",
               geometry_dirs: Sequence[str] = (), width: int = 800, height: int = 800,
               view: str = "iso", floor: bool = True,
               contacts: Union[None, PathLike, Result] = None) -> None:
        """Writes a PNG picture of the model at `time` (s) of `motion` (default: its first row;
        no motion: the default pose), byte for byte what `sinew render` writes. view: "iso",
        "front", "back", "right", "left" or "top". contacts (a contacts.sto path, or a Result:
        its contacts table) draws the contact forces at `time` as green arrows, as `sinew
        render --contacts` (needs a motion)."""
    def simulator(self, step: float, *, integrator: str = "euler", accuracy: float = 1e-6,
                  initial_states: Union[None, "State", PathLike] = None,
                  equilibrate_muscles: bool = False) -> "Simulator":
        """A Simulator that advances this model by `step` s per call (equilibrate_muscles as
        for simulate: its initial state's fibers at equilibrium)."""


class State:
    """A state of a model: a plain value (copy() is independent). Arrays are copies."""
    t: float
    """Time (s)."""
    q: np.ndarray
    """Coordinate values (rad or m), Model.coordinates order; setting places the bodies."""
    u: np.ndarray
    """Coordinate speeds (rad/s or m/s); setting places the bodies."""
    z: np.ndarray
    """Auxiliary state variables, Model.state_variables order."""
    inputs: np.ndarray
    """Actuator excitations, Model.actuators order."""
    @property
    def model(self) -> Model: ...
    def value(self, coordinate: str) -> float:
        """A coordinate's value (rad or m); sinew.Error for an unknown name."""
    def speed(self, coordinate: str) -> float:
        """A coordinate's speed (rad/s or m/s)."""
    def set_value(self, coordinate: str, value: float) -> None:
        """Sets a coordinate's value and places the bodies."""
    def set_speed(self, coordinate: str, speed: float) -> None:
        """Sets a coordinate's speed and places the bodies."""
    def copy(self) -> "State":
        """An independent copy."""


class Simulator:
    """One copy of a model stepped by fixed intervals, for control loops. Its inputs are the
    controls given to step (the model's own controllers are not used)."""
    def reset(self, state: Optional[State] = None) -> np.ndarray:
        """Starts again from `state` (default: the initial state); returns [q, u]."""
    def step(self, controls: Optional[ArrayLike] = None, repeat: int = 1) -> np.ndarray:
        """Sets the inputs to `controls` (one per actuator; omitted: unchanged), advances
        `repeat` steps (default 1, an action repeat) with them, returns the observation [q, u]
        (a new array of 2 x coordinates).

        NSC steps whose impulse solve stopped above the tolerance (statistics'
        "nsc_unconverged_steps") give a UserWarning from the call in which the first one since
        the last reset happens (once per reset); with a model loaded strict=True, every call
        that adds one raises sinew.Error instead (after taking its steps: the state has
        advanced)."""
    @property
    def t(self) -> float: ...
    @property
    def q(self) -> np.ndarray: ...
    @property
    def u(self) -> np.ndarray: ...
    @property
    def state(self) -> State:
        """A copy of the current state."""
    @property
    def statistics(self) -> Dict[str, Union[int, float]]:
        """What the steps since the last reset() (or since the Simulator was made) did, with
        the keys and meanings of Result.statistics: "steps", "rejected", "evaluations"; an NSC
        model's also "nsc_solves", "nsc_unconverged_steps", "nsc_most_iterations",
        "nsc_worst_residual" (m/s). A new dict; reset() sets every figure to 0."""
    @property
    def model(self) -> Model: ...


class Batch:
    """n independent copies of a model stepped together by fixed intervals, across `threads`
    threads (default: every core) with the GIL released; one System shared read-only."""
    def __init__(self, model: Model, n: int, *, step: float, integrator: str = "euler",
                 threads: Optional[int] = None, accuracy: float = 1e-6) -> None: ...
    def reset(self, states: Union[None, State, Sequence[State]] = None) -> None:
        """Every copy from the default state (None), from one State, or copy i from states[i]."""
    def step(self, controls: Optional[ArrayLike] = None) -> None:
        """Advances every copy one step; controls: [n, actuators] (omit without actuators).

        NSC steps whose solve stopped above the tolerance give one UserWarning per call, naming
        the copies whose first such step since the last reset it took; with strict=True, every
        call in which a copy adds one raises sinew.Error instead (after the step)."""
    @property
    def q(self) -> np.ndarray:
        """[n, coordinates] values (a copy)."""
    @property
    def u(self) -> np.ndarray:
        """[n, coordinates] speeds (a copy)."""
    @property
    def t(self) -> np.ndarray:
        """[n] times (a copy)."""
    @property
    def statistics(self) -> Dict[str, np.ndarray]:
        """Per copy, Simulator.statistics: the same keys, each an array [n] (int64 counts,
        float64 "nsc_worst_residual"), counted since the last reset(). A new dict."""
    def state(self, i: int) -> State:
        """A copy of copy i's state."""
    @property
    def n(self) -> int: ...
    @property
    def threads(self) -> int: ...
    @property
    def model(self) -> Model: ...
    def __len__(self) -> int: ...


def write_table(path: PathLike, name: str, labels: Sequence[str], time: ArrayLike,
                values: ArrayLike) -> None:
    """Writes an OpenSim storage file (.sto) as `sinew simulate` writes its tables."""
