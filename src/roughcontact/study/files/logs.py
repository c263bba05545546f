"""Logging set-up for jobs: the package logs through :mod:`logging`
(logger ``roughcontact`` and its children); a Snakemake job or the command
line sends those records to a file with :func:`log_to`."""
from __future__ import annotations

import contextlib
import logging
import os

__all__ = ["log_to"]

FORMAT = "%(asctime)s %(levelname)s %(name)s: %(message)s"


@contextlib.contextmanager
def log_to(path: str | os.PathLike | None, *, level: int = logging.INFO):
    """Append the package's log records to *path* while the block runs (nothing
    if *path* is None); an exception leaving the block is logged before it propagates."""
    logger = logging.getLogger("roughcontact")
    handler = None
    if path is not None:
        os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
        handler = logging.FileHandler(path)
        handler.setFormatter(logging.Formatter(FORMAT))
        logger.addHandler(handler)
        if logger.level == logging.NOTSET or logger.level > level:
            logger.setLevel(level)
    try:
        yield logger
    except BaseException as exc:
        logger.error("FAILED: %s", exc)
        raise
    finally:
        if handler is not None:
            logger.removeHandler(handler)
            handler.close()
