#!/usr/bin/env python3
"""Response times of `rapid mcp`'s tools over stdio, with the real binary.

    cargo build --release -p rapid-lsp
    python3 tests/bench/mcp_bench.py target/release/rapid ../shared/corpus [RUNS]

One server (roots: this repository and the corpus) answers each scenario
RUNS times (default 20; 5 for the corpus and the huge text); the time of a
request is from writing it to reading its answer. Beside them, `rapid check`
as a process on the same inputs, for the overhead of the protocol. Prints a
Markdown table of medians and p90.
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


class Server:
    def __init__(self, binary, roots):
        args = [binary, "mcp"]
        for r in roots:
            args += ["--root", str(r)]
        self.proc = subprocess.Popen(args, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        self.next_id = 0
        self.request(
            "initialize",
            {"protocolVersion": "2025-06-18", "capabilities": {}, "clientInfo": {"name": "bench", "version": "0"}},
        )
        self.send({"jsonrpc": "2.0", "method": "notifications/initialized"})

    def send(self, message):
        self.proc.stdin.write(json.dumps(message) + "\n")
        self.proc.stdin.flush()

    def request(self, method, params):
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": self.next_id, "method": method, "params": params})
        while True:
            m = json.loads(self.proc.stdout.readline())
            if m.get("id") == self.next_id:
                return m

    def call(self, tool, **arguments):
        start = time.perf_counter()
        answer = self.request("tools/call", {"name": tool, "arguments": arguments})
        took = time.perf_counter() - start
        return took, answer["result"]

    def close(self):
        self.proc.stdin.close()
        self.proc.wait()


def stats(times):
    times = sorted(times)
    p90 = times[min(len(times) - 1, int(len(times) * 0.9))]
    return statistics.median(times) * 1e3, p90 * 1e3


def process_times(args, runs):
    out = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        out.append(time.perf_counter() - start)
    return out


def main():
    binary = os.path.abspath(sys.argv[1])
    corpus = Path(sys.argv[2]).resolve()
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 20
    tmp = Path(tempfile.mkdtemp(prefix="rapid-mcp-bench-"))
    big = tmp / "Big.mod"
    big.write_text(
        subprocess.run(
            [sys.executable, str(REPO / "lsp/bench/synth_module.py"), "9000"], capture_output=True, text=True, check=True
        ).stdout
    )
    main_text = (REPO / "examples/palletizer/MainModule.mod").read_text()
    big_text = big.read_text()
    huge = "MODULE huge\n" + "  ! a comment line that makes the module larger than a controller loads\n" * 130_000 + "ENDMODULE\n"

    loop = tmp / "loop" / "Loop.mod"
    loop.parent.mkdir()
    loop.write_text(
        "MODULE Loop\n  PROC main()\n    VAR num n;\n    WHILE TRUE DO\n      n := n + 1;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n"
    )
    server = Server(binary, [REPO, corpus, tmp])
    rows = []

    def scenario(label, tool, n=runs, check=None, **arguments):
        times = []
        for _ in range(n):
            took, result = server.call(tool, **arguments)
            if result.get("isError") and check is None:
                sys.exit(f"{label}: {result['content'][0]['text']}")
            if check:
                check(result)
            times.append(took)
        rows.append((label, *stats(times), n))

    scenario("check examples/palletizer (a folder, 2 modules)", "check", path=str(REPO / "examples/palletizer"))
    scenario(
        "check the unsaved text of MainModule.mod in its task",
        "check",
        path=str(REPO / "examples/palletizer/MainModule.mod"),
        text=main_text,
    )
    scenario(f"check a 9,000-line module as text ({len(big_text) // 1024} KB)", "check", text=big_text, limit=10)
    scenario("check the whole corpus", "check", n=max(3, runs // 4), path=str(corpus), limit=10)
    scenario(
        f"check a {len(huge) // (1024 * 1024)} MB text (refused: too large)",
        "check",
        n=max(3, runs // 4),
        check=lambda r: r["structuredContent"]["skipped"] or sys.exit("not refused"),
        text=huge,
    )
    scenario("fix the text of MainModule.mod", "fix", path=str(REPO / "examples/palletizer/MainModule.mod"), text=main_text)
    scenario("lookup_builtin MoveL", "lookup_builtin", name="MoveL")
    scenario("list_symbols examples/palletizer", "list_symbols", path=str(REPO / "examples/palletizer"))
    scenario(
        "run examples/palletizer (462 statements, 146 moves)",
        "run",
        path=str(REPO / "examples/palletizer"),
        signals=[{"name": "diBoxPresent", "value": 1}],
    )
    scenario("test examples/testing (4 tests)", "test", path=str(REPO / "examples/testing"))
    scenario(
        "run an endless loop to its budget (1,000,000 statements)",
        "run",
        n=max(3, runs // 4),
        check=lambda r: r["structuredContent"]["status"] == "budget" or sys.exit("not stopped"),
        path=str(loop),
    )
    server.close()

    for name, args in [
        ("process: rapid check examples/palletizer", [binary, "check", str(REPO / "examples/palletizer")]),
        ("process: rapid check Big.mod", [binary, "check", str(big)]),
        ("process: rapid check the whole corpus", [binary, "check", str(corpus), "--format", "concise"]),
    ]:
        n = runs if "corpus" not in name else max(3, runs // 4)
        t = process_times(args, n)
        rows.append((name, *stats(t), n))

    print("| scenario | median ms | p90 ms | runs |")
    print("| --- | --- | --- | --- |")
    for name, median, p90, n in rows:
        print(f"| {name} | {median:.1f} | {p90:.1f} | {n} |")


if __name__ == "__main__":
    main()
