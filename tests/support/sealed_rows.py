"""Results rows written by a test, sealed as parksim seals them (parksim/results/tables/RowSeal.h):
the row's JSON object, then the key row_checksum with 16 hex digits of the 64-bit FNV-1a hash
of the object's text without that key. Tests that plant a change in a table (errors made
larger, a better baseline) write their rows through this, so the tables stay ones parksim
accepts; an unsealed or edited row is refused (tests/sweep test that)."""
import json

_FNV_OFFSET = 0xCBF29CE484222325
_FNV_PRIME = 0x100000001B3


def _fnv1a64(data):
    h = _FNV_OFFSET
    for byte in data:
        h ^= byte
        h = (h * _FNV_PRIME) & 0xFFFFFFFFFFFFFFFF
    return h


def sealed_line(row):
    """One results.jsonl line (without its newline) for `row`, a dict; an existing
    row_checksum is dropped and computed anew."""
    body = {k: v for k, v in row.items() if k != "row_checksum"}
    text = json.dumps(body, separators=(",", ":"), ensure_ascii=False)
    seal = _fnv1a64(text.encode("utf-8"))
    return text[:-1] + ',"row_checksum":"%016x"}' % seal


def write_sealed(path, rows):
    """Writes `rows` (dicts) to `path` as a sealed results.jsonl table."""
    path.write_text("".join(sealed_line(r) + "\n" for r in rows), encoding="utf-8")
