#!/usr/bin/env python3
"""An agent-style session with `rapid mcp`, as an AI assistant would run it.

It writes a RAPID module with a mistake (`=` where RAPID assigns with `:=`)
and a test module for it (with the assertion module the server gives as a
resource), asks the server to `check` the unsaved text, lets
`fix` repair it, saves the repaired module, checks the task again and runs
its tests with `test`. It ends green (exit 0) only when the check finds no
errors or warnings and every test passes.

    python3 examples/mcp-agent/agent.py [--rapid PATH] [--workdir DIR]

The server speaks the Model Context Protocol over stdio: one JSON-RPC
message per line. Only the Python standard library is used.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

COUNTER = """MODULE Counter
    PERS num nBoxes := 0;

    PROC AddBoxes(num n)
        nBoxes = nBoxes + n;
    ENDPROC

    FUNC num BoxesPerLayer(num rows, num cols)
        RETURN rows * cols;
    ENDFUNC
ENDMODULE
"""

COUNTER_TEST = """MODULE Counter_test
    PROC setup()
        nBoxes := 0;
    ENDPROC

    PROC counts_boxes()
        AddBoxes 3;
        AddBoxes 4;
        AssertEqual nBoxes, 7 \\Message:="boxes after two adds";
    ENDPROC

    PROC layers_hold_rows_times_columns()
        AssertEqual BoxesPerLayer(3, 4), 12;
    ENDPROC
ENDMODULE
"""


class Server:
    """A `rapid mcp` process and the requests sent to it."""

    def __init__(self, rapid, root):
        self.process = subprocess.Popen(
            [rapid, "mcp", "--root", root],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
        )
        self.next_id = 1
        init = self.request(
            "initialize",
            {
                "protocolVersion": "2025-06-18",
                "capabilities": {},
                "clientInfo": {"name": "example-agent", "version": "1"},
            },
        )
        self.send({"jsonrpc": "2.0", "method": "notifications/initialized"})
        print(f"connected to {init['serverInfo']['name']} {init['serverInfo']['version']}")

    def send(self, message):
        self.process.stdin.write(json.dumps(message) + "\n")
        self.process.stdin.flush()

    def request(self, method, params):
        request_id = self.next_id
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": request_id, "method": method, "params": params})
        while True:
            line = self.process.stdout.readline()
            if not line:
                sys.exit("the server stopped")
            message = json.loads(line)
            if message.get("id") == request_id:
                if "error" in message:
                    sys.exit(f"{method}: {message['error']['message']}")
                return message["result"]

    def tool(self, name, **arguments):
        """Calls a tool: its typed answer (or the end of the session when it fails)."""
        result = self.request("tools/call", {"name": name, "arguments": arguments})
        summary = result["content"][0]["text"]
        if result.get("isError"):
            sys.exit(f"{name} failed: {summary}")
        print(f"\n--- {name}\n{summary.rstrip()}")
        return result["structuredContent"]

    def close(self):
        self.process.stdin.close()
        self.process.wait()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rapid", default=shutil.which("rapid") or "rapid")
    parser.add_argument("--workdir", help="where the task is written (default: a temporary folder)")
    args = parser.parse_args()
    workdir = args.workdir or tempfile.mkdtemp(prefix="rapid-agent-")
    task = os.path.join(workdir, "cell")
    os.makedirs(task, exist_ok=True)
    with open(os.path.join(task, "Counter_test.mod"), "w") as f:
        f.write(COUNTER_TEST)

    server = Server(args.rapid, workdir)
    # 0. Keep the assertion module the tests use beside them, so that
    #    `check` knows AssertEqual (the server gives it as a resource).
    assert_module = server.request("resources/read", {"uri": "rapid://test/RapidAssert.sys"})
    with open(os.path.join(task, "RapidAssert.sys"), "w") as f:
        f.write(assert_module["contents"][0]["text"])
    # 1. The assistant wrote Counter.mod; before saving it, check the text
    #    in its task (the test module beside it is read from disk).
    report = server.tool("check", path="cell/Counter.mod", text=COUNTER)
    assert report["errors"] > 0, "the faulty module has an error"
    # 2. Apply the safe fixes, and save the repaired module.
    fixed = server.tool("fix", path="cell/Counter.mod", text=COUNTER)
    if fixed["remaining"]:
        sys.exit("findings remain that need a person")
    with open(os.path.join(task, "Counter.mod"), "w") as f:
        f.write(fixed["text"])
    # 3. Check the whole task as saved, then run its tests.
    report = server.tool("check", path="cell")
    tests = server.tool("test", path="cell")
    server.close()

    green = report["errors"] == 0 and report["warnings"] == 0 and tests["success"]
    print(f"\n{'green' if green else 'red'}: {report['errors']} errors, "
          f"{tests['passed']} of {len(tests['tests'])} tests passed")
    return 0 if green else 1


if __name__ == "__main__":
    sys.exit(main())
