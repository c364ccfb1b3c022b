#!/usr/bin/env python3
"""Benchmarks of `rapid lsp` over the stdio protocol, with the real binary.

    cargo build --release -p rapid-lsp
    python3 tests/bench/lsp_bench.py target/release/rapid ../shared/corpus

Scenarios: the largest corpus module alone; a synthesised ~9,000-line module
(routines from the generator below, not corpus text); the largest module
opened inside the whole corpus as the workspace. For each: indexing time
(`initialized` to the server's "indexed" log), keystroke-to-diagnostics
latency (a didChange to the publishDiagnostics of its version, debounce off,
and with the default debounce), hover and completion latency, and the
server's resident memory. Prints a Markdown table of medians and p99.
"""

import json
import os
import random
import select
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

RAPID_EXT = {".mod", ".modx", ".sys", ".sysx", ".prg"}


class Server:
    def __init__(self, binary, root, options, caps=None):
        self.proc = subprocess.Popen(
            [binary, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL
        )
        self.out = self.proc.stdout.fileno()
        self.inp = self.proc.stdin.fileno()
        self.buf = b""
        self.next_id = 0
        uri = root.as_uri()
        self.request("initialize", {
            "processId": None, "rootUri": uri,
            "workspaceFolders": [{"uri": uri, "name": "bench"}],
            # What VS Code declares for completion: items' detail and
            # documentation are resolved when an item is shown.
            "capabilities": {
                "general": {"positionEncodings": ["utf-16"]},
                "textDocument": {"completion": {"completionItem": {
                    "resolveSupport": {"properties": ["documentation", "detail", "additionalTextEdits"]}}}},
                **(caps or {}),
            },
            "initializationOptions": options,
        })
        self.t_initialized = time.perf_counter()
        self.notify("initialized", {})

    # Messages are read in the thread that waits for them: a reader thread
    # handing them over through a queue adds its own latency spikes (5 and
    # 10 ms, from the interpreter's thread switching) to the server's.
    def _fill(self, deadline):
        """Reads what the server wrote, waiting until `deadline` at most."""
        wait = max(0.0, deadline - time.perf_counter())
        ready, _, _ = select.select([self.out], [], [], wait)
        if not ready:
            raise TimeoutError("no answer from the server")
        chunk = os.read(self.out, 1 << 20)
        if not chunk:
            raise EOFError("the server closed its output")
        self.buf += chunk

    def _message(self, deadline):
        """The next message, with the time its last byte arrived."""
        while True:
            head, sep, rest = self.buf.partition(b"\r\n\r\n")
            if sep:
                length = next(int(l.split(b":")[1]) for l in head.split(b"\r\n")
                              if l.lower().startswith(b"content-length:"))
                if len(rest) >= length:
                    t = time.perf_counter()
                    self.buf = rest[length:]
                    return t, json.loads(rest[:length])
            self._fill(deadline)

    def send(self, msg):
        body = json.dumps(msg).encode()
        data = memoryview(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        # Read while writing: a large message must not wait for a server
        # that waits for its own output to be read.
        while data:
            readable, writable, _ = select.select([self.out], [self.inp], [])
            if readable:
                self._fill(time.perf_counter())
            if writable:
                data = data[os.write(self.inp, data[: 1 << 16]):]

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def wait(self, pred, timeout=120):
        deadline = time.perf_counter() + timeout
        while True:
            t, m = self._message(deadline)
            if "method" in m and "id" in m:
                self.send({"jsonrpc": "2.0", "id": m["id"], "result": None})
            if pred(m):
                return t, m

    def request(self, method, params):
        self.next_id += 1
        i = self.next_id
        t0 = time.perf_counter()
        self.send({"jsonrpc": "2.0", "id": i, "method": method, "params": params})
        t1, m = self.wait(lambda m: m.get("id") == i and "method" not in m)
        return (t1 - t0) * 1000, m

    def rss_mb(self):
        status = Path(f"/proc/{self.proc.pid}/status").read_text()
        fields = dict(l.split(":", 1) for l in status.splitlines() if ":" in l)
        rss = int(fields["VmRSS"].split()[0]) / 1024
        hwm = int(fields["VmHWM"].split()[0]) / 1024
        return rss, hwm

    def cpu_ms(self):
        """User + system CPU time of the server so far."""
        fields = Path(f"/proc/{self.proc.pid}/stat").read_text().rsplit(")", 1)[1].split()
        ticks = os.sysconf("SC_CLK_TCK")
        return (int(fields[11]) + int(fields[12])) * 1000 / ticks

    def stop(self):
        try:
            self.request("shutdown", None)
            self.notify("exit", None)
            self.proc.wait(timeout=10)
        except Exception:
            self.proc.kill()


def pct(values, p):
    s = sorted(values)
    return s[min(len(s) - 1, int(round(p / 100 * (len(s) - 1))))]


def synthesize(n_lines):
    """A module of generated routines (our own generator, not corpus text)."""
    rnd = random.Random(7)
    out = ["MODULE Synth", "    CONST num nMax := 100;", "    VAR num nCount := 0;",
           "    PERS tooldata tSynth := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];",
           "    CONST robtarget pBase := [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];", ""]
    i = 0
    while len(out) < n_lines - 1:
        i += 1
        out += [f"    PROC step{i}(num a, INOUT num b)",
                f"        VAR num k{i} := 0;",
                f"        VAR robtarget p{i};",
                f"        p{i} := Offs(pBase, a * {rnd.randint(1, 9)}, {rnd.randint(-50, 50)}, 0);",
                f"        FOR j FROM 1 TO nMax DO",
                f"            k{i} := k{i} + j * a;",
                f"            IF k{i} > {rnd.randint(100, 999)} THEN",
                f"                b := b + 1;",
                f"            ELSE",
                f"                nCount := nCount + 1;",
                f"            ENDIF",
                f"        ENDFOR",
                f"        MoveL p{i}, v{rnd.choice([100, 200, 500, 1000])}, z{rnd.choice([1, 5, 10, 50])}, tSynth;",
                f"        TPWrite \"step {i}: \"\\Num:=k{i};",
                "    ENDPROC", ""]
        if i > 1:
            out.insert(len(out) - 2, f"        step{i - 1} a, b;")
    out.append("ENDMODULE")
    return "\n".join(out) + "\n"


def identifier_positions(text, rnd, n):
    """(line, character) of identifiers inside routine bodies."""
    import re
    lines = text.splitlines()
    cands = []
    in_routine = False
    for ln, line in enumerate(lines):
        low = line.strip().lower()
        if low.startswith(("proc ", "func ", "trap ", "local proc", "local func", "local trap")):
            in_routine = True
            continue
        if low.startswith(("endproc", "endfunc", "endtrap")):
            in_routine = False
        if in_routine and not low.startswith("!"):
            for m in re.finditer(r"[A-Za-z_][A-Za-z0-9_]*", line.split("!")[0]):
                if '"' not in line[:m.start()]:
                    cands.append((ln, m.start() + 1))
    rnd.shuffle(cands)
    return cands[:n]


def body_line(text):
    """A line inside the largest routine body where a keystroke goes."""
    lines = text.splitlines()
    best, start = (0, 0), None
    for ln, line in enumerate(lines):
        low = line.strip().lower()
        if low.startswith(("proc ", "func ", "trap ", "local proc", "local func")):
            start = ln
        elif low.startswith(("endproc", "endfunc", "endtrap")) and start is not None:
            if ln - start > best[1] - best[0]:
                best = (start, ln)
            start = None
    return (best[0] + best[1]) // 2


def run(binary, root, path, label, delay, n_keys=100, n_req=200):
    rnd = random.Random(1)
    options = {"diagnosticsDelay": delay} if delay is not None else {}
    s = Server(binary, root, options)
    t_idx, m = s.wait(lambda m: m.get("method") == "window/logMessage"
                      and m["params"]["message"].startswith("indexed "))
    index_ms = (t_idx - s.t_initialized) * 1000
    index_cpu = s.cpu_ms()
    indexed = m["params"]["message"]
    text = path.read_text(encoding="utf-8", errors="replace") if path.suffix else ""
    raw = path.read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError:
        text = raw.decode("latin-1")
    uri = path.as_uri()
    t0 = time.perf_counter()
    s.notify("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "rapid", "version": 1, "text": text}})
    t1, _ = s.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics"
                   and m["params"]["uri"] == uri and m["params"].get("version") == 1)
    open_ms = (t1 - t0) * 1000
    line = body_line(text)
    indent = len(text.splitlines()[line]) - len(text.splitlines()[line].lstrip())
    keys, fulls = [], []
    version = 1
    cpu0 = s.cpu_ms()
    for k in range(n_keys):
        version += 1
        # Type `x` at the start of the line's code, then delete it: every
        # other keystroke leaves a syntax error, as typing does.
        if k % 2 == 0:
            change = {"range": {"start": {"line": line, "character": indent}, "end": {"line": line, "character": indent}}, "text": "x"}
        else:
            change = {"range": {"start": {"line": line, "character": indent}, "end": {"line": line, "character": indent + 1}}, "text": ""}
        t0 = time.perf_counter()
        s.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": version}, "contentChanges": [change]})
        is_v = lambda m, v=version: (m.get("method") == "textDocument/publishDiagnostics"
                                     and m["params"]["uri"] == uri and m["params"].get("version") == v)
        # First the quick publication (syntax, others carried over), then
        # the full check's.
        t1, _ = s.wait(is_v)
        t2, _ = s.wait(is_v)
        keys.append((t1 - t0) * 1000)
        fulls.append((t2 - t0) * 1000)
    key_cpu = (s.cpu_ms() - cpu0) / n_keys
    hovers, completions = [], []
    for (ln, ch) in identifier_positions(text, rnd, n_req):
        ms, _ = s.request("textDocument/hover", {"textDocument": {"uri": uri}, "position": {"line": ln, "character": ch}})
        hovers.append(ms)
    for _ in range(n_req):
        ms, m = s.request("textDocument/completion", {"textDocument": {"uri": uri}, "position": {"line": line, "character": indent}})
        completions.append(ms)
    result = m.get("result") or []
    # A list (`CompletionList`, cut when long) or a plain array.
    n_items = len(result["items"]) if isinstance(result, dict) else len(result)
    rss, hwm = s.rss_mb()
    s.stop()
    return {
        "label": label, "indexed": indexed, "index_ms": index_ms, "open_ms": open_ms,
        "index_cpu": index_cpu, "key_cpu": key_cpu,
        "keys": keys, "fulls": fulls, "hovers": hovers, "completions": completions, "items": n_items,
        "rss": rss, "hwm": hwm, "lines": text.count("\n") + 1,
    }


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else "target/release/rapid"
    corpus = Path(sys.argv[2] if len(sys.argv) > 2 else "../shared/corpus").resolve()
    files = [p for p in corpus.rglob("*") if p.is_file() and p.suffix.lower() in {".mod", ".sys"}]
    largest = max(files, key=lambda p: p.stat().st_size)
    tmp = Path(tempfile.mkdtemp(prefix="rapid-lsp-bench-"))
    alone = tmp / "alone"
    alone.mkdir()
    shutil.copy(largest, alone / largest.name)
    synth = tmp / "synth"
    synth.mkdir()
    (synth / "Synth.mod").write_text(synthesize(9000))
    results = []
    for delay in (0, None):
        d = "off" if delay == 0 else "default (75 ms)"
        results.append(run(binary, alone, alone / largest.name, f"largest corpus module, debounce {d}", delay))
        results.append(run(binary, synth, synth / "Synth.mod", f"synthesised module, debounce {d}", delay))
        results.append(run(binary, corpus, largest, f"whole corpus, largest module open, debounce {d}", delay))
    shutil.rmtree(tmp, ignore_errors=True)
    print(f"largest corpus module: {largest.relative_to(corpus)}\n")
    print("| scenario | lines | indexing (wall, server CPU) | open to diagnostics | keystroke to first diagnostics (median / p99) | keystroke to full check's diagnostics (median / p99; server CPU per keystroke) | hover (median / p99) | completion (median / p99, items) | RSS (now / peak) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in results:
        med = statistics.median
        print(f"| {r['label']} | {r['lines']} | {r['index_ms']:.0f} ms, {r['index_cpu']:.0f} ms CPU ({r['indexed']}) | {r['open_ms']:.1f} ms "
              f"| {med(r['keys']):.1f} / {pct(r['keys'], 99):.1f} ms "
              f"| {med(r['fulls']):.1f} / {pct(r['fulls'], 99):.1f} ms; {r['key_cpu']:.1f} ms CPU "
              f"| {med(r['hovers']):.2f} / {pct(r['hovers'], 99):.2f} ms "
              f"| {med(r['completions']):.2f} / {pct(r['completions'], 99):.2f} ms ({r['items']}) "
              f"| {r['rss']:.0f} / {r['hwm']:.0f} MB |")


if __name__ == "__main__":
    main()
