"""One grading process and the pipe to it, which the server's event loop reads.

The server hands a job to a process by writing it to the process's end of a pipe, and
the event loop reads the answer when it arrives (``loop.add_reader``): no thread stands
between the two, so a job costs the server a write, a read and two pickles (about a
twentieth of a millisecond), where a :class:`concurrent.futures.ProcessPoolExecutor`
takes a manager thread, a feeder thread and their wake-ups (about ten times as much, at
every submit and every preview).

A process runs one job at a time (:mod:`.grading_pool` hands a job only to an idle one).
Usage::

    worker = Worker(context, setup, (manifest, folders))
    worker.wait_ready()                        # optional: start and load now, blocking
    answer = await worker.run(function, *args) # raises WorkerDied if the process died
    worker.stop()

A process that dies (killed, out of memory) fails the job it was running with
:class:`WorkerDied`; the pool replaces it.
"""

from __future__ import annotations

import asyncio
import multiprocessing.connection
import pickle
import signal
from typing import Callable

from ..errors import DynagradeError

#: what a process is sent to stop
_STOP = None


class WorkerDied(DynagradeError):
    """The grading process ended while it ran a job (or before it could take one)."""


def _serve(connection: multiprocessing.connection.Connection, setup: Callable,
           setup_args: tuple) -> None:
    """A grading process: set up, then answer each job ``(function, args)`` with
    ``(True, result)`` or ``(False, exception)`` until told to stop. Ctrl-C in the
    terminal is the server's to handle: the server stops its processes."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    setup(*setup_args)
    while True:
        try:
            job = connection.recv()
        except EOFError:  # the server is gone
            return
        if job is _STOP:
            return
        function, args = job
        try:
            answer = (True, function(*args))
        except Exception as error:  # the caller raises it, as a local call would
            answer = (False, error)
        try:
            connection.send(answer)
        except (pickle.PicklingError, TypeError, AttributeError) as error:
            connection.send((False, RuntimeError(f"the grading answer could not be sent back: "
                                                 f"{error}")))


class Worker:
    """One grading process: at most one job at a time, its answer read on the loop."""

    def __init__(self, context, setup: Callable, setup_args: tuple,
                 on_end: Callable[[Worker], None] = lambda worker: None):
        self._connection, child = context.Pipe()
        self.process = context.Process(target=_serve, args=(child, setup, setup_args),
                                       daemon=True)
        self.process.start()
        child.close()
        #: called on the loop once the process has ended (not after :meth:`stop`)
        self._on_end = on_end
        self._loop: asyncio.AbstractEventLoop | None = None
        self._job: asyncio.Future | None = None
        self._stopped = False

    @property
    def busy(self) -> bool:
        return self._job is not None

    def wait_ready(self) -> None:
        """Block until the process has set up and answers (before any job on a loop)."""
        self._connection.send((_ping, ()))
        self._connection.recv()

    def run(self, function: Callable, *args) -> asyncio.Future:
        """Send the job; the future holds its result, or raises what it raised, or
        :class:`WorkerDied`. The process is busy until the future is done."""
        loop = asyncio.get_running_loop()
        if self._loop is None:
            self._loop = loop
            loop.add_reader(self._connection.fileno(), self._readable)
        assert self._job is None, "a grading process runs one job at a time"
        job = self._job = loop.create_future()
        try:
            self._connection.send((function, args))
        except (OSError, ValueError):  # the process is gone: the job fails at once
            self._ended()
        return job

    def stop(self, seconds: float = 5.0) -> None:
        """Ask the process to end after its job, wait up to ``seconds``, then kill it."""
        self._stopped = True
        try:
            self._connection.send(_STOP)
        except (OSError, ValueError):
            pass
        self.process.join(seconds)
        if self.process.is_alive():
            self.process.kill()
            self.process.join(1.0)
        self._detach_from_any_thread()

    def _readable(self) -> None:
        try:
            ok, answer = self._connection.recv()
        except (EOFError, OSError):
            self._ended()
            return
        job, self._job = self._job, None
        if job is None or job.done():
            return
        if ok:
            job.set_result(answer)
        else:
            job.set_exception(answer)

    def _ended(self) -> None:
        """The process is gone: fail its job, stop reading, tell the pool."""
        self._detach()
        job, self._job = self._job, None
        if job is not None and not job.done():
            job.set_exception(WorkerDied("a grading process ended while grading"))
        if not self._stopped:
            self._stopped = True
            self._on_end(self)

    def _detach_from_any_thread(self) -> None:
        """:meth:`_detach` on the loop's thread (a retired pool stops in another)."""
        loop = self._loop
        try:
            here = asyncio.get_running_loop()
        except RuntimeError:
            here = None
        if loop is not None and loop is not here and loop.is_running():
            loop.call_soon_threadsafe(self._detach)
        else:
            self._detach()

    def _detach(self) -> None:
        if self._loop is not None and not self._loop.is_closed():
            try:
                self._loop.remove_reader(self._connection.fileno())
            except (OSError, ValueError, RuntimeError):
                pass
        self._loop = None
        self._connection.close()


def _ping() -> bool:
    return True
