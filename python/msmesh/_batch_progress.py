"""Progress of ``msmesh batch``: a bar redrawn on stderr when it is a terminal (done, failed,
running, meshes per minute), else one plain line per finished mesh."""

import sys
import time
from typing import Optional, TextIO


def failure(record: dict) -> str:
    """'INPUT: ERROR' (the error alone when it already starts with the input)."""
    error, name = str(record.get("error", "")), str(record.get("input", ""))
    return error if error.startswith(name + ":") else f"{name}: {error}"


class Progress:
    def __init__(self, total: int, stream: Optional[TextIO] = None, quiet: bool = False):
        self.total, self.done, self.failed, self.running = total, 0, 0, 0
        self.stream = stream or sys.stderr
        self.quiet = quiet
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self.start = time.monotonic()
        self.drawn = False

    def rate(self) -> float:
        minutes = (time.monotonic() - self.start) / 60
        return (self.done + self.failed) / minutes if minutes > 0 else 0.0

    def line(self) -> str:
        finished = self.done + self.failed
        width = 30
        filled = int(width * finished / self.total) if self.total else width
        return (f"[{'#' * filled}{'.' * (width - filled)}] {finished}/{self.total}  done {self.done}  failed "
                f"{self.failed}  running {self.running}  {self.rate():.1f} meshes/min")

    def draw(self) -> None:
        if self.quiet or not self.tty:
            return
        self.stream.write("\r" + self.line() + "\033[K")
        self.stream.flush()
        self.drawn = True

    def finished(self, record: dict) -> None:
        if record.get("status") == "ok":
            self.done += 1
        else:
            self.failed += 1
        if self.quiet:
            return
        if not self.tty:
            n = self.done + self.failed
            what = f"{record.get('input')}: ok" if record.get("status") == "ok" else "FAILED: " + failure(record)
            self.stream.write(f"[{n}/{self.total}] {what} ({record.get('seconds', 0)} s)\n")
            self.stream.flush()
        else:
            if record.get("status") != "ok":
                self.stream.write("\r\033[K" + f"failed: {failure(record)}\n")
            self.draw()

    def close(self) -> None:
        if self.drawn:
            self.stream.write("\r" + self.line() + "\033[K\n")
            self.stream.flush()
