"""The progress bar behind ``progress=True``: the module calls it as ``bar(done, total)``.

tqdm draws it when tqdm is installed (it is not a dependency); otherwise one line on stderr is
rewritten in place. Nothing is drawn for work that ends within ``delay`` seconds, so that short
calls inside a loop stay silent.
"""

from __future__ import annotations

import sys
import time

__all__ = ["ProgressBar"]


class ProgressBar:
    """A callable ``bar(done, total)`` that draws once the work has taken ``delay`` seconds."""

    def __init__(self, delay: float = 1.0, stream=None, unit: str = "queries"):
        self.delay = delay
        self.stream = stream
        self.unit = unit
        self.started = time.monotonic()
        self._tqdm = None
        self._drawn = False

    def __call__(self, done: int, total: int) -> None:
        if not self._drawn and time.monotonic() - self.started < self.delay:
            return
        if not self._drawn:
            self._drawn = True
            try:
                from tqdm import tqdm
            except ImportError:
                tqdm = None
            if tqdm is not None:
                self._tqdm = tqdm(total=total, unit=self.unit, file=self.stream or sys.stderr, unit_scale=True)
        if self._tqdm is not None:
            self._tqdm.update(done - self._tqdm.n)
            if done >= total:
                self._tqdm.close()
            return
        stream = self.stream or sys.stderr
        percent = 100.0 * done / total if total else 100.0
        stream.write(f"\rcircledist: {done:,} of {total:,} {self.unit} ({percent:.0f} %)")
        if done >= total:
            stream.write("\n")
        stream.flush()
