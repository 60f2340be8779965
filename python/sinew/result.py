"""Result: what Model.simulate returns, plain NumPy arrays (it pickles, so Dask can gather it)."""
from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Union

import numpy as np


class Result:
    """The states of a simulation at its report times.

    time: [n] seconds. q, u: [n, coordinates] values (rad or m) and speeds, in the order of
    `coordinates`. z: [n, state variables], in the order of `state_variables`. states: the
    states table as `sinew simulate` writes it to states.sto, columns named by `labels`.
    final_state: the sinew.State at the end. statistics: the integrator's steps, rejected steps
    and evaluations; an NSC run's also "nsc_solves" (steps with contacts), "nsc_unconverged_steps"
    (those whose impulse solve stopped at its iteration limit above the tolerance),
    "nsc_most_iterations" and "nsc_worst_residual" (m/s). contacts: the contacts table as
    `sinew simulate` writes it to contacts.sto ([n, contact_labels]; no columns when the run has
    no contact): per contact force (and an NSC run's "nsc_contact") the net force (N) and torque
    about the body's origin (N m) on each body, in ground, "<force>.<body>.force.X|Y|Z" and
    ".torque.X|Y|Z", then the number of active contacts, in all and per body pair, and for NSC
    "nsc_contact.solver_iterations" and ".solver_residual" (the last step's impulse solve) and
    ".unconverged_steps" (so far) (docs/contact.md). forces: the forces table as `sinew
    simulate` writes forces.sto ([n, force_labels]: OpenSim's ForceReporter columns, e.g. each
    muscle's tension, each spring's force; forces that apply none are left out, as OpenSim
    leaves them out). controls: the actuators' controls (excitations) as `sinew forward` writes
    <name>_controls.sto ([n, control_labels]).
    """

    def __init__(self, *, time: np.ndarray, q: np.ndarray, u: np.ndarray, z: np.ndarray,
                 coordinates: List[str], state_variables: List[str], labels: List[str],
                 states: np.ndarray, final_state: Any, statistics: Dict[str, Union[int, float]],
                 contact_labels: Optional[List[str]] = None,
                 contacts: Optional[np.ndarray] = None,
                 force_labels: Optional[List[str]] = None,
                 forces: Optional[np.ndarray] = None,
                 control_labels: Optional[List[str]] = None,
                 controls: Optional[np.ndarray] = None) -> None:
        self.time = time
        self.q = q
        self.u = u
        self.z = z
        self.coordinates = list(coordinates)
        self.state_variables = list(state_variables)
        self.labels = list(labels)
        self.states = states
        self.final_state = final_state
        self.statistics = dict(statistics)
        self.contact_labels = list(contact_labels or [])
        self.contacts = (np.asarray(contacts) if contacts is not None
                         else np.zeros((len(time), len(self.contact_labels))))
        self.force_labels = list(force_labels or [])
        self.forces = (np.asarray(forces) if forces is not None
                       else np.zeros((len(time), len(self.force_labels))))
        self.control_labels = list(control_labels or [])
        self.controls = (np.asarray(controls) if controls is not None
                         else np.zeros((len(time), len(self.control_labels))))

    def __getstate__(self) -> Dict[str, Any]:
        # A sinew.State holds its model and does not pickle: keep the arrays only.
        state = dict(self.__dict__)
        state["final_state"] = None
        return state

    def __len__(self) -> int:
        return len(self.time)

    def __repr__(self) -> str:
        return (f"<sinew.Result {len(self.time)} times from {self.time[0]:g} to "
                f"{self.time[-1]:g} s, {len(self.coordinates)} coordinates>")

    def to_sto(self, path: "os.PathLike[str] | str") -> None:
        """Writes the states table as `sinew simulate` writes states.sto (byte for byte)."""
        from ._sinew import write_table
        write_table(os.fspath(path), "states", self.labels, self.time, self.states)

    def contacts_to_sto(self, path: "os.PathLike[str] | str") -> None:
        """Writes the contacts table as `sinew simulate` writes contacts.sto (byte for byte).
        Raises ValueError when the run has no contact columns (the CLI writes no file then)."""
        if not self.contact_labels:
            raise ValueError("this run has no contacts table (no contact force or collision)")
        from ._sinew import write_table
        write_table(os.fspath(path), "Contacts", self.contact_labels, self.time, self.contacts)

    def forces_to_sto(self, path: "os.PathLike[str] | str") -> None:
        """Writes the forces table as `sinew simulate` writes forces.sto (byte for byte)."""
        from ._sinew import write_table
        write_table(os.fspath(path), "ForceReporter", self.force_labels, self.time, self.forces)

    def controls_to_sto(self, path: "os.PathLike[str] | str") -> None:
        """Writes the controls table as `sinew forward` writes <name>_controls.sto (byte for
        byte)."""
        from ._sinew import write_table
        write_table(os.fspath(path), "controls", self.control_labels, self.time, self.controls)

    def to_pandas(self) -> Any:
        """The states table as a pandas DataFrame indexed by time (needs pandas)."""
        try:
            import pandas as pd
        except ImportError as error:
            raise ImportError("Result.to_pandas needs pandas (pip install pandas)") from error
        return pd.DataFrame(self.states, index=pd.Index(self.time, name="time"),
                            columns=self.labels)
