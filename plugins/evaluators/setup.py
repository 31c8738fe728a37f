"""The compiled part of strips-evaluators: everything else is in pyproject.toml."""

from Cython.Build import cythonize
from setuptools import Extension, setup

setup(
    ext_modules=cythonize(
        [
            Extension(
                "strips_evaluators.heuristics._explore",
                ["src/strips_evaluators/heuristics/_explore.pyx"],
                optional=True,  # no compiler: the pure-Python reference runs
            )
        ],
        language_level=3,
    )
)
