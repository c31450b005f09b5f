"""The package version (single source: read by setuptools and by ``paper_repro.__version__``)."""

__version__ = "0.2.0"
