"""The compiled part of strips-framework: everything else is in pyproject.toml."""

from Cython.Build import cythonize
from setuptools import Extension, setup

setup(
    ext_modules=cythonize(
        [
            Extension(
                f"strips_framework.forward.{name}",
                [f"src/strips_framework/forward/{name}.pyx"],
                optional=True,  # no compiler: the pure-Python reference runs
            )
            for name in ("_successors", "_search", "_packing")
        ],
        language_level=3,
    )
)
