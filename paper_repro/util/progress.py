"""Progress for long work: a tqdm bar on a terminal, plain lines elsewhere (CI, ``make ... > log``).

>>> list(progress([1, 2], "demo", stream=None))
[1, 2]
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator
from typing import TypeVar

T = TypeVar("T")


def progress(items: Iterable[T], desc: str, *, stream=sys.stderr) -> Iterator[T]:
    """Iterate ``items`` showing progress: tqdm on a TTY, otherwise one plain line per item
    (``desc k/N``), nothing at all when ``stream`` is None."""
    seq = list(items)
    if stream is None:
        yield from seq
        return
    if getattr(stream, "isatty", lambda: False)():
        from tqdm import tqdm

        yield from tqdm(seq, desc=desc, leave=False, file=stream)
        return
    for k, item in enumerate(seq, 1):
        print(f"{desc} {k}/{len(seq)}: {item}", file=stream, flush=True)
        yield item
