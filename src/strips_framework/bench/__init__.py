"""Benchmark matrices: problems x configurations x repetitions, each run isolated.

- :mod:`~strips_framework.bench.matrix` reads the matrix file into runs;
- :mod:`~strips_framework.bench.configs` says what command each configuration runs;
- :mod:`~strips_framework.bench.isolation` runs one child under time and memory limits;
- :mod:`~strips_framework.bench.runner` turns a child's output into a row, plan validated;
- :mod:`~strips_framework.bench.executors` runs many, locally or on Dask, rows streamed to
  :mod:`~strips_framework.bench.results`;
- :mod:`~strips_framework.bench.summary`, :mod:`~strips_framework.bench.plots` and
  :mod:`~strips_framework.bench.report` make the table, the plots and the report.

See docs/bench.md.
"""
