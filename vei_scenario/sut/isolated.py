"""A native FMU stepped in a child process of its own, so that a crash or a hang inside its binary fails
the one run it drives (one line naming the controller, the step time and the reason) and never the
process that runs it: ``vei run``, a sweep's worker, a search.

Why a child per run: an FMU is native code loaded into the process; a segmentation fault there ends the
process whatever Python does, and a ``doStep`` that never returns cannot be interrupted from Python (no
signal handler runs while C code holds the interpreter). The child is forked when the run makes its
controller, builds the :class:`~vei_scenario.sut.fmu.FmuController` there, and answers one message per
step over a socket pair; the parent waits for each answer at most ``--controller-timeout`` seconds. When
the child dies (a signal, or an exit without an answer) or overruns, the parent kills and reaps it: no
process is left behind, and a child whose parent dies is killed with it (a hung ``doStep`` reads no
end-of-file).
"""

from __future__ import annotations

import os
import signal
import socket
import struct
from multiprocessing.connection import Connection

from vei_scenario.child_process import die_with_parent
from vei_scenario.sut.contract import ControllerFault, Observation
from vei_scenario.sut.fmu import INPUTS, FmuController, FmuPorts, _unzipped


class IsolatedFmu:
    """:class:`FmuController`'s interface, the FMU itself in a forked child."""

    def __init__(self, ports: FmuPorts, label: str, properties: dict[str, str], timeout_s: float | None) -> None:
        self.ports, self.label, self.timeout_s = ports, label, timeout_s
        _unzipped(ports.path)  # (extracted here: the parent owns the directory and removes it at exit)
        parent, child = socket.socketpair()
        parent_pid = os.getpid()
        self.pid = os.fork()
        if self.pid == 0:  # the child: serve, and never return into the parent's code
            status = 0
            try:
                die_with_parent(parent_pid)
                parent.close()
                _serve(Connection(child.detach()), ports, label, properties)
            except BaseException:  # noqa: BLE001 (the parent says what happened, from the missing answer)
                status = 1
            finally:
                os._exit(status)
        child.close()
        self.inputs = _Inputs(ports)
        self.vrs = [vr for _, vr in ports.inputs]
        self.conn = Connection(parent.detach())
        self.pending = False  # a step sent and not answered (the parent was interrupted waiting)
        self._answer(None, "while instantiating it")

    def _answer(self, t_s: float | None, where: str):
        """The child's answer, else one :class:`ControllerFault` saying why there is none."""
        try:
            ready = self.conn.poll(self.timeout_s)
            message = self.conn.recv() if ready else None
        except (EOFError, OSError):
            message = ()
        if message is None:
            self._kill()
            call = "step" if t_s is not None else f"instantiating {self.ports.path.name}"
            reason = f"{call} did not return within {self.timeout_s:g} s (--controller-timeout)"
            raise ControllerFault(self.label, reason, t_s)
        if message == ():
            raise ControllerFault(self.label, f"{self.ports.path.name} {self._death()} {where}", t_s)
        if message[0] == "fault":
            self._reap()
            raise ControllerFault(self.label, message[1], t_s if message[2] is None else message[2])
        return message[1]

    def step(self, obs: Observation) -> float:
        vrs, values = self.inputs.inputs_of(obs)
        mask = sum(1 << i for i, vr in enumerate(self.vrs) if vr in vrs)  # (the threat's inputs may be absent)
        try:
            self.conn.send_bytes(struct.pack(f"<Qdd{len(values)}d", mask, obs.t_s, obs.dt_s, *values))
        except OSError:
            raise ControllerFault(self.label, f"{self.ports.path.name} {self._death()}", obs.t_s) from None
        self.pending = True
        answer = self._answer(obs.t_s, "in doStep")
        self.pending = False
        return answer

    def close(self) -> None:
        """End the instance in the child and the child with it (killed if it does not end within 2 s)."""
        if self.pid is None:
            return
        if self.pending:  # (stuck in its step: nothing to end gracefully)
            self._kill()
            return
        try:
            self.conn.send_bytes(b"")
            self.conn.poll(2.0)
        except OSError:
            pass
        self._kill()

    def _death(self) -> str:
        """How the child ended (reaped): 'crashed (SIGSEGV)', 'exited with status 1'."""
        pid, self.pid = self.pid, None
        self.conn.close()
        if pid is None:
            return "ended"
        _, status = os.waitpid(pid, 0)
        if os.WIFSIGNALED(status):
            return f"crashed ({signal.Signals(os.WTERMSIG(status)).name})"
        return f"ended with exit status {os.WEXITSTATUS(status)}"

    def _kill(self) -> None:
        if self.pid is not None:
            try:
                os.kill(self.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self._reap()

    def _reap(self) -> None:
        pid, self.pid = self.pid, None
        self.conn.close()
        if pid is not None:
            os.waitpid(pid, 0)

    def __del__(self) -> None:
        try:
            self._kill()
        except Exception:  # noqa: BLE001, S110 (interpreter shutdown)
            pass


def _serve(conn: Connection, ports: FmuPorts, label: str, properties: dict[str, str]) -> None:
    """In the child: make the instance, then one answer per observation until None or end-of-file."""
    import faulthandler

    faulthandler.disable()  # (a crash is said once, by the parent, in one line)
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # (Ctrl-C is the parent's to handle)
    signal.signal(signal.SIGALRM, signal.SIG_DFL)
    try:
        fmu = FmuController(ports, label, properties)
    except ControllerFault as fault:
        conn.send(("fault", fault.reason, fault.t_s))
        return
    conn.send(("ok", None))
    all_vrs = [vr for _, vr in ports.inputs]
    while True:
        try:
            message = conn.recv_bytes()
        except EOFError:
            message = b""
        if not message:
            fmu.close()
            return
        mask, t_s, dt_s = struct.unpack_from("<Qdd", message)
        values = list(struct.unpack_from(f"<{(len(message) - 24) // 8}d", message, 24))
        vrs = [vr for i, vr in enumerate(all_vrs) if mask >> i & 1]
        try:
            conn.send(("ok", fmu.step_values(vrs, values, t_s, dt_s)))
        except ControllerFault as fault:  # (the instance is ended as FMI allows, in step)
            conn.send(("fault", fault.reason, fault.t_s))
            return


class _Inputs(FmuController):
    """The parent's half of the FMU: which inputs an observation gives (no instance)."""

    def __init__(self, ports: FmuPorts) -> None:
        self.ports, self.inputs = ports, [(INPUTS[n], vr) for n, vr in ports.inputs]
