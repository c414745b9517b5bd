"""encode: the writer. Packs a model (codec.pack_file) and, unless the stored values are kept,
refuses a result that would not validate: a writer makes files that validate."""

from __future__ import annotations

from . import tables as T
from .codec import pack_file
from .errors import EncodeError
from .model import Cbf
from .validation import validate


def encode(model: Cbf, *, keep_stored: bool = False, profile: str = "default") -> bytes:
    """Write a Cbf. By default fills sequence numbers, code copies, the count,
    the magic numbers and every checksum, then refuses a result that does not
    validate. ``keep_stored=True`` writes every stored value as given, so a
    faulty file is reproduced byte for byte."""
    out = pack_file(model, keep_stored=keep_stored, profile=profile)
    if not keep_stored:
        # A writer makes files that validate: no error, and strings in ASCII (N4).
        refuse = {c["id"] for c in T.checks_of("string_ascii")}
        errors = [f for f in validate(out, profile=profile) if f.severity == "error" or f.check in refuse]
        if errors:
            e = errors[0]
            where = f"record {e.record}" if e.record is not None else "file"
            raise EncodeError(f"{where}: the result would fail check {e.check}: {e.message}", offset=e.offset)
    return out
