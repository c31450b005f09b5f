"""Progress for long work: one tqdm bar on a terminal, one line at the end elsewhere (CI, ``make ... > log``).

>>> list(progress([1, 2], "demo", stream=None))
[1, 2]
>>> import io
>>> out = io.StringIO()
>>> list(progress(range(20), "linear_independence", stream=out)) == list(range(20))
True
>>> out.getvalue().count("\\n"), out.getvalue().startswith("linear_independence: 20 of 20 done in ")
(1, True)
"""

from __future__ import annotations

import sys
import time
from collections.abc import Iterable, Iterator
from typing import TypeVar

T = TypeVar("T")
#: The default stream: ``sys.stderr`` as it is when the progress starts (not when this module was imported)
STDERR = "stderr"


class Ticker:
    """Progress of ``total`` steps: a tqdm bar on a TTY (the last finished step as its postfix), otherwise one line
    when :meth:`close` is called (``desc: k of total done in t s``), nothing when ``stream`` is None."""

    def __init__(self, total: int, desc: str, *, stream=STDERR):
        stream = sys.stderr if stream == STDERR else stream
        self.total, self.desc, self.stream, self.done = total, desc, stream, 0
        self.start = time.perf_counter()
        self.bar = None
        if stream is not None and getattr(stream, "isatty", lambda: False)():
            from tqdm import tqdm

            self.bar = tqdm(total=total, desc=desc, leave=False, file=stream)

    def step(self, label: str | None = None) -> None:
        self.done += 1
        if self.bar is not None:
            if label:
                self.bar.set_postfix_str(label, refresh=False)
            self.bar.update(1)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
        elif self.stream is not None:
            print(f"{self.desc}: {self.done} of {self.total} done in {time.perf_counter() - self.start:.1f} s",
                  file=self.stream, flush=True)


def progress(items: Iterable[T], desc: str, *, stream=STDERR) -> Iterator[T]:
    """Iterate ``items`` showing progress (:class:`Ticker`): a tqdm bar on a TTY, otherwise one plain line when the
    loop ends (before, one line per item: about 100 ``rank ... n k/20`` lines in a ``make reproduce`` log)."""
    seq = list(items)
    ticker = Ticker(len(seq), desc, stream=stream)
    try:
        for item in seq:
            yield item
            ticker.step()
    finally:
        ticker.close()
