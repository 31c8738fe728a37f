"""Reading the user's files: bad bytes, TOML syntax, nesting and huge integers are
reported at their line and column, never as a traceback."""

from pathlib import Path

import pytest

from strips_framework.errors import InputError
from strips_framework.user_files import MAX_NESTING, is_file, read_text, read_toml


def error_of(path: Path) -> InputError:
    with pytest.raises(InputError) as raised:
        read_toml(path, "the config")
    return raised.value


def test_a_byte_that_is_not_utf8_is_reported_at_its_line_and_column(tmp_path: Path) -> None:
    path = tmp_path / "x.toml"
    path.write_bytes(b"[limits]\ntime = 5 # caf\xe9\n")
    error = error_of(path)
    assert (error.path, error.line, error.column) == (str(path), 2, 15)
    assert error.message == "the config is not UTF-8 text: byte 0xe9 (invalid continuation byte)"


def test_toml_syntax_errors_give_the_line_and_column(tmp_path: Path) -> None:
    path = tmp_path / "x.toml"
    path.write_text('[prover]\nname = "resolution"\n[strategy\n')
    error = error_of(path)
    assert (error.line, error.column) == (3, 10)
    assert str(error) == f"{path}:3:10: not valid TOML: Expected ']' at the end of a table declaration"


@pytest.mark.parametrize("opener,closer", [("[", "]"), ("{a = ", "}")])
def test_nesting_deeper_than_tomllib_recurses_is_an_error_at_the_deep_opening(
    tmp_path: Path, opener: str, closer: str
) -> None:
    path = tmp_path / "x.toml"
    path.write_text("[limits]\nx = " + opener * 5000 + "1" + closer * 5000 + "\n")
    error = error_of(path)
    assert error.line == 2 and error.column is not None and error.column > MAX_NESTING
    assert "nested deeper than" in error.message


def test_an_integer_of_thousands_of_digits_is_an_error_at_its_position(tmp_path: Path) -> None:
    path = tmp_path / "x.toml"
    path.write_text("[limits]\nnodes = " + "9" * 5000 + "\n")
    error = error_of(path)
    assert (error.line, error.column) == (2, 9)
    assert "digits" in error.message


def test_unreadable_names_are_errors_not_exceptions(tmp_path: Path) -> None:
    for name in ("x\x00y", "n" * 5000):
        assert not is_file(tmp_path / name)
        with pytest.raises(InputError, match="cannot read the plan"):
            read_text(tmp_path / name, "the plan")
