"""The exceptions rollbem raises.

Every one derives from :class:`RollbemError`. They follow the command line's exit codes:

==================  =========================================================  =========
exception           raised for                                                 CLI exit
==================  =========================================================  =========
``InputError``      bad input: a file that is not text, malformed TOML, an     2
                    unknown or missing key, a wrong type, a value out of
                    range, a solver that does not apply; ``key`` names the
                    dotted key (``"wheel.radius"``) where it is known
``OutputError``     an output that cannot be written                            3
``NumericalError``  a singular or non-finite BEM system                         4
``SolveError``      a run that did not end ``solved`` (or with the status the   5
                    scene declares in ``[checks] status``), only when asked:
                    ``check=True`` or ``raise_for_status()``
``InternalError``   a panic inside rollbem (a bug: please report it)            -
==================  =========================================================  =========

``InputError`` is a :class:`ValueError`, ``NumericalError`` an :class:`ArithmeticError` and ``OutputError`` an
:class:`OSError`, so code that catches the built-in kinds keeps working.

Where Python has a class of its own, rollbem raises it rather than one of these: a file that is not there, not
readable or a directory raises Python's ``OSError`` subclass of that ``errno`` (``FileNotFoundError``,
``PermissionError``, ``IsADirectoryError``; ``filename`` names the file), as ``open()`` does (the CLI's exit code 2);
a solver or stress quantity a result does not hold raises ``KeyError``; an argument of the wrong kind (a drive that
is not a ``Scene`` or a mapping, a load path that is not a sequence) raises ``TypeError``. A file that is there but
is not UTF-8 text, and a sweep spec whose ``base`` scene is not there, are ``InputError``.
"""

from __future__ import annotations

from typing import Any, Optional

__all__ = ["RollbemError", "InputError", "OutputError", "NumericalError", "SolveError", "InternalError"]


class RollbemError(Exception):
    """Base of every exception rollbem raises."""


class InputError(RollbemError, ValueError):
    """Bad input (the CLI's exit code 2).

    Attributes:
        key: the dotted key of the offending value (``"wheel.radius"``, ``"drive.normal_load"``,
            ``"steps[2].substeps"``), or ``None`` where the input has no key (an unreadable file, TOML that does not
            parse).
        path: the file the input came from, or ``"<scene>"`` for a scene made in Python.
        message: the whole message, as the CLI prints it after ``error:``.
    """

    def __init__(self, message: str, *, key: Optional[str] = None, path: Optional[str] = None) -> None:
        super().__init__(message)
        self.message = message
        self.key = key
        self.path = path


class OutputError(RollbemError, OSError):
    """An output could not be written or produced (the CLI's exit code 3)."""

    def __init__(self, message: str, *, path: Optional[str] = None) -> None:
        super().__init__(message)
        self.message = message
        self.path = path

    def __str__(self) -> str:
        return self.message


class NumericalError(RollbemError, ArithmeticError):
    """The BEM system is singular or not finite (the CLI's exit code 4).

    Attributes:
        stage: the pipeline stage that failed (e.g. ``"condensation"``).
    """

    def __init__(self, message: str, *, stage: Optional[str] = None) -> None:
        super().__init__(message)
        self.message = message
        self.stage = stage


class SolveError(RollbemError):
    """A run did not end with the status its scene expects (the CLI's exit code 5), raised only when the caller asks
    (``check=True``, ``Report.raise_for_status()``, ``Run.raise_for_status()``).

    Attributes:
        status: the run's status (``"infeasible"``, ``"not_converged"``, ``"contact_at_zone_edge"``, ...).
        solver: the solver's name.
        explanation: why, with the numbers (``Run.explanation``).
        report: the whole :class:`rollbem.Report` (``None`` when raised by ``Run.raise_for_status``).
    """

    def __init__(
        self,
        message: str,
        *,
        status: str,
        solver: str,
        explanation: str,
        report: Any = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        self.status = status
        self.solver = solver
        self.explanation = explanation
        self.report = report


class InternalError(RollbemError):
    """A panic inside rollbem, caught before it reached Python: a bug (please report it with the input)."""
