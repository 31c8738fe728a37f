"""The compiled part of strips-framework: everything else is in pyproject.toml."""

from Cython.Build import cythonize
from setuptools import Extension, setup

setup(
    ext_modules=cythonize(
        [
            Extension(
                "strips_framework.forward._successors",
                ["src/strips_framework/forward/_successors.pyx"],
                optional=True,  # no compiler: the pure-Python reference runs
            )
        ],
        language_level=3,
    )
)
