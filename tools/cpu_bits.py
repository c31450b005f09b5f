"""Which float results are the same bits on every CPU, and how far apart the others are (issue 31, item 1).

Computes a fixed set of float results of the public API -- patch points, derivatives and normals with the compiled
and the numpy kernel, blending values, normalizing coefficients, elevation, the Bezier limit -- on seeded
inputs, and writes them (hex floats) to a JSON file.  ``make test-cpus`` runs it under each OpenBLAS kernel that
numpy's DYNAMIC_ARCH build can be forced to (``OPENBLAS_CORETYPE``), under numba's host and generic targets
(``NUMBA_CPU_NAME=generic``) and under numpy's SIMD dispatch limited as on other CPUs (``NPY_DISABLE_CPU_FEATURES``,
:data:`NUMPY_VARIANTS`: on an AVX512 machine numpy's exp, log, power, tan, ... are Intel SVML, not correctly
rounded, where an AVX2 or older machine runs other code), then compares every run with the host's run::

    .venv/bin/python tools/cpu_bits.py compute build/cpus/host.json
    .venv/bin/python tools/cpu_bits.py compare build/cpus/host.json build/cpus/*.json --report reports/cpu_bits.md
    .venv/bin/python tools/cpu_bits.py pin tests/fixtures/cpu_bits.json   # after a change of these results
    NPY_DISABLE_CPU_FEATURES="$(.venv/bin/python tools/cpu_bits.py numpy-env avx2)" \
        .venv/bin/python tools/cpu_bits.py compute build/cpus/numpy-avx2.json

``tests/test_cpu_bits.py`` (marker ``bits``) recomputes the promised items and compares them with the pinned
sha256, so running it under another kernel (``make test-cpus``, CI) checks their bits against this machine's.

``compare`` prints one line per run and item (identical, or the largest difference relative to the item's
largest magnitude) and exits 1 if an item that the README promises bit-identical differs (:data:`PROMISED`).
The report is a report (raw numbers of this machine), not data.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from pathlib import Path

import numpy as np

#: Items whose bits the README promises to be the same on every CPU (any OpenBLAS kernel, any numba target, any
#: SIMD code numpy dispatches to).
PROMISED = ("evaluate_normalized", "coefficients", "elevate", "elevation_matrix", "bezier_limit", "subdivision")
#: numpy's run-time SIMD dispatch limited as on other CPUs (``NPY_DISABLE_CPU_FEATURES``, :func:`numpy_env`):
#: ``avx2`` a Haswell-like x86-64 without AVX512 (no SVML), ``baseline`` only the build's baseline (SSE4.2 on x86-64).
NUMPY_VARIANTS = ("avx2", "baseline")


def numpy_env(variant: str) -> str | None:
    """The value of ``NPY_DISABLE_CPU_FEATURES`` that limits numpy's dispatch to ``variant`` (:data:`NUMPY_VARIANTS`),
    computed from this numpy's dispatch targets (only those may be named: numpy warns about any other); ``None``
    if the variant does not apply (``avx2`` on a build without AVX512 targets, e.g. not x86-64).  Features the CPU
    lacks may be named: numpy then just keeps them off."""
    from numpy._core._multiarray_umath import __cpu_dispatch__

    if variant == "baseline":
        off = list(__cpu_dispatch__)
    elif variant == "avx2":
        off = [t for t in __cpu_dispatch__ if "AVX512" in t or t == "X86_V4"]
    else:
        raise ValueError(f"unknown numpy variant {variant!r}; one of {NUMPY_VARIANTS}")
    return " ".join(off) or None


def numpy_dispatch() -> dict:
    """The SIMD targets numpy runs here (float64 power, exp, log10): shows that ``NPY_DISABLE_CPU_FEATURES`` took
    effect (``opt_func_info``, numpy >= 2.2; else the enabled dispatch targets)."""
    env = os.environ.get("NPY_DISABLE_CPU_FEATURES", "")
    try:
        from numpy.lib.introspect import opt_func_info
    except ImportError:  # pragma: no cover - numpy < 2.2
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__

        return {"NPY_DISABLE_CPU_FEATURES": env, "targets": [t for t in __cpu_dispatch__ if __cpu_features__.get(t)]}
    info = opt_func_info(func_name="^(power|exp|log10)$", signature="float64")
    return {"NPY_DISABLE_CPU_FEATURES": env,
            **{f: next((v["current"] for sig, v in d.items() if sig.startswith("d")), "?") for f, d in info.items()}}


def _kernel_info() -> dict:
    from threadpoolctl import threadpool_info

    np.ones(2) @ np.ones(2)  # load BLAS
    blas = [i.get("architecture") for i in threadpool_info() if i.get("user_api") == "blas"]
    return {"openblas": blas, "OPENBLAS_CORETYPE": os.environ.get("OPENBLAS_CORETYPE", ""),
            "NUMBA_CPU_NAME": os.environ.get("NUMBA_CPU_NAME", ""), "numpy": numpy_dispatch()}


def compute(promised_only: bool = False) -> dict:
    """The results, as lists of hex floats, keyed by item (only the :data:`PROMISED` ones with ``promised_only``)."""
    import paper_repro as pr
    from paper_repro.core.labels import delta

    out: dict[str, list[str]] = {}

    def put(name: str, arr) -> None:
        if promised_only and name.split("/")[0] not in PROMISED:
            return
        a = np.asarray(arr, dtype=float).ravel()
        out[name] = [float(x).hex() for x in a]

    rng = np.random.default_rng(31)
    for n, alpha in ((1, 0.3), (3, math.pi / 2), (6, 2.9)):
        pts = pr.sample_points(alpha, 257, seed=n)
        net = rng.normal(size=(delta(n), 3))
        put(f"evaluate_normalized/n{n}", pr.evaluate_normalized(n, alpha, pts[:64]))
        put(f"coefficients/n{n}", list(pr.coefficients(n, alpha).values()))
        for kernel in () if promised_only else ("numba", "numpy"):
            os.environ["PAPER_REPRO_KERNEL"] = kernel
            p = pr.Patch(n, alpha, net)
            put(f"patch_{kernel}_kernel_points/n{n}", p(pts))
            put(f"patch_{kernel}_kernel_derivative/n{n}", p.derivative(pts, "u"))
            put(f"patch_{kernel}_kernel_normals/n{n}", p.normals(pts))
            # one point at a time: the numpy kernel's product is then a (<= 4, F) x (F, 1) BLAS product
            put(f"patch_{kernel}_kernel_points_per_point/n{n}", np.vstack([p(pts[i: i + 1]) for i in range(8)]))
        os.environ.pop("PAPER_REPRO_KERNEL", None)
        if n <= 3:
            put(f"elevation_matrix/n{n}", pr.elevation_matrix(n, alpha))
            put(f"elevate/n{n}", pr.elevate(net, n, alpha))
        _, nodes = pr.bezier_limit(net, n)
        put(f"bezier_limit/n{n}", [nodes[k] for k in sorted(nodes)])
    # the product route of subdivision: powers of kappa', sigma' (n = 12 at alpha = 2.9 met numpy's SVML power)
    for n in (3, 12):
        put(f"subdivision/n{n}", np.stack([pr.subdivision_matrix(n, 2.9, part) for part in ("u", "v", "w", "middle")]))
    return out


def fingerprints(values: dict) -> dict:
    """sha256 of each item's hex floats: what ``tests/fixtures/cpu_bits.json`` pins (``pin``)."""
    import hashlib

    return {k: hashlib.sha256(" ".join(v).encode()).hexdigest() for k, v in sorted(values.items())}


def compare(ref_path: Path, paths: list[Path], report: Path | None, note: str = "") -> int:
    ref = json.loads(ref_path.read_text())
    runs = {path: json.loads(path.read_text()) for path in paths if path != ref_path}
    lines = ["# Float results across CPU kernels (tools/cpu_bits.py)", "",
             "Each run recomputes the items of `tools/cpu_bits.py` in a fresh process on this machine, with one "
             "setting changed: the OpenBLAS kernel (`OPENBLAS_CORETYPE`), numba's target (`NUMBA_CPU_NAME`) or the "
             "SIMD code numpy's ufuncs dispatch to (`NPY_DISABLE_CPU_FEATURES`; `numpy` below: the dispatch target "
             "of float64 power, exp, log10 in that run).", "",
             *([note, ""] if note else []),
             f"Reference run: `{ref_path.name}` ({ref['info']})", "", "Runs compared with it:", ""]
    lines += [f"* `{path.stem}`: {run['info']}" for path, run in runs.items()]
    lines += ["", "| run | item | same bits | largest difference / largest magnitude |", "|---|---|---|---|"]
    bad = 0
    for path, run in runs.items():
        for item, hexes in sorted(ref["values"].items()):
            other = run["values"].get(item)
            a = np.array([float.fromhex(x) for x in hexes])
            b = np.array([float.fromhex(x) for x in other]) if other is not None else None
            if b is None or a.shape != b.shape:
                same, diff = False, "missing or other shape"
            else:
                same = a.tobytes() == b.tobytes()
                scale = float(np.nanmax(np.abs(a))) if a.size else 0.0
                diff = f"{float(np.nanmax(np.abs(a - b))) / scale:.1e}" if (not same and scale) else "0"
            promised = item.split("/")[0] in PROMISED
            if promised and not same:
                bad += 1
            lines.append(f"| {path.stem} | {item} | {'yes' if same else 'NO'}{' (promised)' if promised else ''} "
                         f"| {diff} |")
            if not same:
                print(f"{path.stem}: {item}: differs ({diff}){'  <- PROMISED bit-identical' if promised else ''}")
        print(f"{path.stem}: {run['info']}")
    if report:
        report.parent.mkdir(parents=True, exist_ok=True)
        report.write_text("\n".join(lines) + "\n")
    print(f"cpu_bits: {bad} promised item(s) differ" if bad else "cpu_bits: every promised item has the same bits")
    return 1 if bad else 0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("compute")
    c.add_argument("out", type=Path)
    m = sub.add_parser("compare")
    m.add_argument("ref", type=Path)
    m.add_argument("runs", type=Path, nargs="+")
    m.add_argument("--report", type=Path)
    m.add_argument("--note", default="", help="a paragraph for the report (how and when the runs were made)")
    p = sub.add_parser("pin", help="write the sha256 of every promised item (tests/fixtures/cpu_bits.json)")
    p.add_argument("out", type=Path)
    e = sub.add_parser("numpy-env", help="print NPY_DISABLE_CPU_FEATURES for a numpy dispatch variant (exit 1 if it "
                                         "does not apply to this numpy build)")
    e.add_argument("variant", choices=NUMPY_VARIANTS)
    args = ap.parse_args(argv)
    if args.cmd == "numpy-env":
        value = numpy_env(args.variant)
        if value is None:
            print(f"cpu_bits: numpy variant {args.variant} does not apply to this numpy build", file=sys.stderr)
            return 1
        print(value)
        return 0
    if args.cmd == "pin":
        args.out.write_text(json.dumps(fingerprints(compute(promised_only=True)), indent=1, sort_keys=True) + "\n")
        print(f"cpu_bits: pinned {args.out}")
        return 0
    if args.cmd == "compute":
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(json.dumps({"info": _kernel_info(), "values": compute()}, indent=0, sort_keys=True))
        print(f"cpu_bits: {args.out} ({_kernel_info()})")
        return 0
    return compare(args.ref, args.runs, args.report, args.note)


if __name__ == "__main__":
    sys.exit(main())
