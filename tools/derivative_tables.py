"""Rewrite ``paper_repro/resources/derivative_tables.json``: the derivative matrix C for n = 1..10 recovered exactly
modulo two primes (:func:`paper_repro.theory.derivative_matrix.derivative_polynomials`, a route that knows nothing of
the closed form).  The file is the independent reference of claim ``derivative_all_n``;
``tests/test_derivative_tables.py`` recomputes it (n <= 3 fast, n <= 10 slow).  About 20 s.  Usage::

    .venv/bin/python tools/derivative_tables.py
"""

from __future__ import annotations

from paper_repro.theory.derivative_matrix import TABLE_MAX_N, TABLES, tables_text
from paper_repro.util.io import write_text


def main() -> None:
    write_text(TABLES, tables_text(TABLE_MAX_N, progress=True))
    print(f"derivative tables: n = 1..{TABLE_MAX_N} recovered and written to {TABLES}")


if __name__ == "__main__":
    main()
