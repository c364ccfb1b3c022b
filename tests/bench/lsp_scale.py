#!/usr/bin/env python3
"""`rapid lsp` on a large workspace while it indexes (issue 27).

    python3 tests/bench/layouts.py /tmp/ws corpus 12     # ~10,000 modules
    python3 tests/bench/lsp_scale.py target/release/rapid /tmp/ws

Starts the server on the folder (the client declares work-done progress),
opens a module at once (the largest of the first corpus copy) and, until
the server logs "indexed", sends every 20 ms a hover on an identifier of
that module and a completion at a statement start, in turn. Prints the
time to the open module's first diagnostics and to the end of indexing
(from `initialized`), the `$/progress` notifications seen, the hover and
completion latencies during indexing (median, p99, max), and the server's
peak resident memory.
"""

import random
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from lsp_bench import Server, body_line, identifier_positions, pct  # noqa: E402

RAPID_EXT = {".mod", ".modx", ".sys", ".sysx", ".prg"}


class Watching(Server):
    """A server whose messages are also counted by method."""

    def __init__(self, *args, **kwargs):
        self.seen = []
        super().__init__(*args, **kwargs)

    def _message(self, deadline):
        t, m = super()._message(deadline)
        if "method" in m:
            self.seen.append((t, m))
        return t, m


def main():
    binary, root = sys.argv[1], Path(sys.argv[2]).resolve()
    files = sorted(p for p in root.rglob("*") if p.is_file() and p.suffix.lower() in RAPID_EXT)
    first = [p for p in files if p.relative_to(root).parts[0] == files[0].relative_to(root).parts[0]]
    path = max(first, key=lambda p: p.stat().st_size)
    raw = path.read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        text = raw.decode("latin-1")
    s = Watching(binary, root, {}, caps={"window": {"workDoneProgress": True}})
    t0 = s.t_initialized
    uri = path.as_uri()
    s.notify("textDocument/didOpen", {"textDocument": {
        "uri": uri, "languageId": "rapid", "version": 1, "text": text}})
    positions = identifier_positions(text, random.Random(1), 10_000) or [(0, 0)]
    line = body_line(text)
    indent = len(text.splitlines()[line]) - len(text.splitlines()[line].lstrip())
    hovers, completions = [], []
    first_diag = indexed = None
    i = 0
    while indexed is None:
        if i % 2 == 0:
            ln, ch = positions[(i // 2) % len(positions)]
            ms, _ = s.request("textDocument/hover", {
                "textDocument": {"uri": uri}, "position": {"line": ln, "character": ch}})
            hovers.append(ms)
        else:
            ms, _ = s.request("textDocument/completion", {
                "textDocument": {"uri": uri}, "position": {"line": line, "character": indent}})
            completions.append(ms)
        i += 1
        for t, m in s.seen:
            if first_diag is None and m["method"] == "textDocument/publishDiagnostics" \
                    and m["params"]["uri"] == uri:
                first_diag = t - t0
            if m["method"] == "window/logMessage" and m["params"]["message"].startswith("indexed "):
                indexed = t - t0
        time.sleep(0.02)
    if first_diag is None:
        t, _ = s.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics"
                      and m["params"]["uri"] == uri, timeout=600)
        first_diag = t - t0
    progress = sum(1 for _, m in s.seen if m["method"] == "$/progress")
    _, hwm = s.rss_mb()
    s.stop()
    size = sum(p.stat().st_size for p in files)
    print(f"workspace: {len(files)} modules, {size / 1e6:.1f} MB; open: {path.relative_to(root)}")
    print(f"first diagnostics of the open module: {first_diag * 1000:.0f} ms after initialized")
    print(f"indexed: {indexed:.2f} s after initialized; $/progress notifications: {progress}")
    for name, times in (("hover", hovers), ("completion", completions)):
        if times:
            print(f"{name} during indexing: {len(times)} requests, median "
                  f"{statistics.median(times):.2f} ms, p99 {pct(times, 99):.2f} ms, "
                  f"max {max(times):.2f} ms")
    print(f"peak resident memory: {hwm:.0f} MB ({hwm * 1e6 / size:.1f}x the modules)")


if __name__ == "__main__":
    main()
