"""The ``strips`` command line: argument parsing, text and JSON output, exit codes and the
process limits the CLI sets."""
