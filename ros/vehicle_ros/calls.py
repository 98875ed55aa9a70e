"""Service callbacks run in rospy's threads; the simulation belongs to the main thread.

A callback hands its work to :class:`MainThreadCalls` and waits: the node's loop runs the
queued calls just before each driver step (Webots: "effects apply at the next driver step"),
so no library call ever races a step. While a call runs, file descriptor 2 goes to a
temporary file: the C API prints its warnings (Webots' own text) there, and the node passes
them on to its stderr and to ``/rosout``.
"""

import os
import queue
import sys
import tempfile
import threading
from typing import Any, Callable, List, Optional, Tuple

__all__ = ["CarCalls", "MainThreadCalls", "SimulationEnded"]


class SimulationEnded(RuntimeError):
    """The simulation stopped before the call could run (the world's duration elapsed, the
    master went away or the node was interrupted)."""


class _Pending:
    def __init__(self, work: Callable[[], Any]) -> None:
        self.work = work
        self.done = threading.Event()
        self.result: Any = None
        self.error: Optional[BaseException] = None
        self.warnings: List[str] = []


def capture_stderr(work: Callable[[], Any]) -> Tuple[Any, str]:
    """Runs ``work`` with fd 2 in a temporary file; returns its result and what it printed.
    The text goes on to the real stderr too, so the node's console shows Webots' warnings
    exactly as a controller's would."""
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), 2)
        try:
            result = work()
        finally:
            sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)
        sink.seek(0)
        text = sink.read().decode("utf-8", "replace")
    if text:
        sys.stderr.write(text)
        sys.stderr.flush()
    return result, text


class MainThreadCalls:
    """A queue of calls from the service threads, run by the main thread."""

    def __init__(self, on_warning: Callable[[str], None]) -> None:
        self._queue: "queue.Queue[_Pending]" = queue.Queue()
        self._on_warning = on_warning
        self._closed = threading.Event()

    def call(self, work: Callable[[], Any]) -> Any:
        """Runs ``work`` on the main thread before the next step and returns its result;
        raises :class:`SimulationEnded` if the simulation stops first."""
        if self._closed.is_set():
            raise SimulationEnded("the simulation has ended")
        pending = _Pending(work)
        self._queue.put(pending)
        while not pending.done.wait(0.1):
            if self._closed.is_set():
                self.run_pending()
        if pending.error is not None:
            raise pending.error
        return pending.result

    def run_pending(self) -> None:
        """Runs every queued call (main thread; also drains the queue once closed)."""
        while True:
            try:
                pending = self._queue.get_nowait()
            except queue.Empty:
                return
            if self._closed.is_set():
                pending.error = SimulationEnded("the simulation has ended")
            else:
                try:
                    pending.result, text = capture_stderr(pending.work)
                    for line in text.splitlines():
                        if line.strip():
                            self._on_warning(line)
                except Exception as error:  # handed to the caller's thread, raised there
                    pending.error = error
            pending.done.set()

    def close(self) -> None:
        """No more calls: the waiting ones and later ones raise :class:`SimulationEnded`."""
        self._closed.set()
        self.run_pending()


class CarCalls:
    """One car's view of the node's queue when the node serves several cars: each call runs
    with that car's controller selected (``webots_vehicle.controllers.select``), so the
    library call reaches that car's controller."""

    def __init__(self, calls: MainThreadCalls, select: Callable[[], None]) -> None:
        self._calls = calls
        self._select = select

    def call(self, work: Callable[[], Any]) -> Any:
        """As :meth:`MainThreadCalls.call`, with the car's controller selected first."""

        def selected() -> Any:
            self._select()
            return work()

        return self._calls.call(selected)
