// The debugger and "RAPID: Show path" in the real editor: a workspace with the
// runtime's motion fixture (runtime/tests/programs/motion.mod) and a launch
// configuration; a breakpoint is set in the editor's margin, the session
// starts, stops there, shows the routine's data in the Variables view, steps,
// continues and ends, with the program's output in the Debug Console. Then
// "Show path" opens the path of that last run in a webview, and of a routine
// that has not run yet (run then). Last, a session with a robot (`robot` in
// its launch configuration) stops at a breakpoint: the path opens beside the
// editor with the arm at that moment and the move that brought it there,
// and follows a step. Expectations come from the fixture's own `!>` output
// lines and from `rapid run --trace`.
import { spawnSync } from "node:child_process";
import * as fs from "node:fs";
import * as path from "node:path";

const SQUARE = `MODULE Square
  CONST robtarget pCorner := [[500, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC square()
    MoveL pCorner, v200, fine, tool0;
    MoveL Offs(pCorner, 100, 0, 0), v200, z10, tool0;
    MoveL Offs(pCorner, 100, 100, 0), v200, z10, tool0;
    MoveL Offs(pCorner, 0, 100, 0), v200, fine, tool0;
  ENDPROC
ENDMODULE
`;

/** The robot of the session that follows the path (it reaches the square). */
const ROBOT = "IRB 1200-7/0.7";

/** Runs the debugger's and the path view's checks; `ctx` holds run.mjs's helpers. */
export async function debugSteps(ctx) {
  const { page, port, tmp, out, rapid, repo, assert, runCommand, goTo, TIMEOUT } = ctx;
  // a failing check leaves a screenshot of what the editor showed
  let n = 0;
  const step = (name, fn) =>
    ctx.step(name, async () => {
      n += 1;
      try {
        await fn();
      } catch (err) {
        await page.screenshot({ path: path.join(out, `vscode-debug-failed-${n}.png`) }).catch(() => {});
        throw err;
      }
    });
  const ws = path.join(tmp, "debug-workspace");
  fs.mkdirSync(path.join(ws, ".vscode"), { recursive: true });
  const fixture = fs.readFileSync(path.join(repo, "runtime/tests/programs/motion.mod"), "utf8");
  fs.writeFileSync(path.join(ws, "motion.mod"), fixture);
  fs.writeFileSync(path.join(ws, "Square.mod"), SQUARE);
  fs.writeFileSync(
    path.join(ws, ".vscode", "launch.json"),
    JSON.stringify({
      version: "0.2.0",
      configurations: [
        { type: "rapid", request: "launch", name: "Run motion", program: "${workspaceFolder}/motion.mod", entry: "main" },
        {
          type: "rapid",
          request: "launch",
          name: "Run square",
          program: "${workspaceFolder}/Square.mod",
          entry: "square",
          robot: ROBOT,
        },
      ],
    }),
  );
  const lines = fixture.split("\n");
  const lineOf = (needle) => lines.findIndex((l) => l.includes(needle)) + 1;
  // the fixture's expected output
  const printed = lines.filter((l) => l.startsWith("!> ")).map((l) => l.slice(3));
  const inTable = printed.find((l) => l.startsWith("in table ")).slice("in table ".length);
  const breakLine = lineOf('TPWrite "in table "');
  const movesOf = (file, entry) => {
    const trace = path.join(tmp, `${entry}.json`);
    const r = spawnSync(rapid, ["run", file, "--entry", entry, "--trace", trace], { encoding: "utf8" });
    if (r.status !== 0) throw new Error(`rapid run ${file} --entry ${entry}: ${r.stderr}`);
    return JSON.parse(fs.readFileSync(trace, "utf8")).moves.length;
  };
  const motionMoves = movesOf(path.join(ws, "motion.mod"), "main");
  // the square's moves with the robot: when each ends
  const squareTrace = path.join(tmp, "square-robot.json");
  const ran = spawnSync(
    rapid,
    ["run", path.join(ws, "Square.mod"), "--entry", "square", "--robot", ROBOT, "--trace", squareTrace],
    { encoding: "utf8" },
  );
  if (ran.status !== 0) throw new Error(`rapid run Square.mod --robot: ${ran.stderr}`);
  const squareEnds = JSON.parse(fs.readFileSync(squareTrace, "utf8")).moves.map((m) => m.end);
  const squareMoves = movesOf(path.join(ws, "Square.mod"), "square");

  await page.goto(`http://127.0.0.1:${port}/?folder=${encodeURIComponent(ws)}`);
  await page.waitForSelector(".monaco-workbench");
  await page.waitForTimeout(1500);
  // from the Explorer, by mouse: a webview keeps the keys (Ctrl+P) it is given
  const open = async (name) => {
    const explorer = page.locator(".explorer-folders-view");
    if (!(await explorer.isVisible())) {
      await page.locator(".activitybar .action-label[aria-label^='Explorer']").first().click();
    }
    await explorer.locator(".monaco-list-row", { hasText: name }).first().click();
    await page.locator(".tabs-container .tab.active", { hasText: name }).first().waitFor({ state: "visible" });
    await page.locator(".monaco-editor textarea").first().focus();
  };
  const callStackTop = () => page.locator(".debug-call-stack .monaco-list-row", { hasText: "main" }).first();
  const waitFor = async (what, probe) => {
    const deadline = Date.now() + TIMEOUT;
    let last;
    while (Date.now() < deadline) {
      last = await probe();
      if (last === true) return;
      await page.waitForTimeout(200);
    }
    throw new Error(`${what}: ${last}`);
  };

  await step(`the debugger stops at a breakpoint set in the margin (motion.mod:${breakLine})`, async () => {
    await open("motion.mod");
    await goTo(breakLine, 5);
    await runCommand("Debug: Toggle Breakpoint");
    await page.locator(".monaco-editor .codicon-debug-breakpoint").first().waitFor({ state: "visible" });
    // F5: the launch configuration of .vscode/launch.json
    await page.locator(".monaco-editor textarea").first().focus();
    await page.keyboard.press("F5");
    await page.locator(".debug-toolbar").waitFor({ state: "visible" });
    await waitFor("the call stack", async () => {
      const text = (await callStackTop().innerText().catch(() => "")).replace(/\s+/g, " ");
      return new RegExp(`motion\\.mod\\s*${breakLine}:`).test(text) || `top frame: ${text}`;
    });
    // the Call Stack's header says why
    await page.getByText("Paused on breakpoint").first().waitFor({ state: "visible" });
    // the editor marks the line the program stopped at
    await page.locator(".debug-top-stack-frame-line").first().waitFor({ state: "attached" });
  });

  await step(`the Variables view shows the routine's data (here = [${inTable}, ...])`, async () => {
    const row = page.locator(".debug-variables .monaco-list-row", { hasText: "here" }).first();
    const locals = page.locator(".debug-variables .monaco-list-row", { hasText: "Locals" }).first();
    await locals.waitFor({ state: "visible" });
    if ((await locals.getAttribute("aria-expanded")) !== "true") await locals.click();
    await row.waitFor({ state: "visible" });
    const text = (await row.innerText()).replace(/\s+/g, "");
    await page.screenshot({ path: path.join(out, "vscode-debug-breakpoint.png") });
    assert(text.includes(`here:[${inTable},`) || text.includes(`here=[${inTable},`), `variable row: ${text}`);
    const scopes = (await page.locator(".debug-variables .monaco-list-row").allInnerTexts()).join(" | ");
    assert(/Module/.test(scopes), `no Module scope: ${scopes}`);
  });

  await step("step over goes to the next line, continue runs to the end and the session ends", async () => {
    await page.locator(".monaco-editor textarea").first().focus();
    await page.keyboard.press("F10");
    await waitFor("after the step", async () => {
      const text = (await callStackTop().innerText().catch(() => "")).replace(/\s+/g, " ");
      return new RegExp(`motion\\.mod\\s*${breakLine + 1}:`).test(text) || `top frame: ${text}`;
    });
    await page.keyboard.press("F5");
    await page.locator(".debug-toolbar").waitFor({ state: "hidden" });
    await runCommand("View: Toggle Debug Console");
    const repl = page.locator(".repl .monaco-list-rows");
    await waitFor("the Debug Console", async () => {
      const text = await repl.first().innerText().catch(() => "");
      const missing = printed.filter((l) => !text.includes(l));
      return missing.length === 0 || `missing ${JSON.stringify(missing)} in ${JSON.stringify(text)}`;
    });
    await page.screenshot({ path: path.join(out, "vscode-debug-ended.png") });
  });

  const pathView = () => page.frameLocator("iframe.webview.ready").frameLocator("#active-frame");
  await step(`RAPID: Show path opens the last run of main in a webview (${motionMoves} moves)`, async () => {
    await open("motion.mod");
    await goTo(lineOf("PROC main()") + 1, 5);
    await runCommand("RAPID: Show path");
    await page.locator(".tabs-container .tab", { hasText: "Path: main" }).first().waitFor({ state: "visible" });
    const view = pathView();
    await waitFor("the path page", async () => {
      const count = await view.locator("#count").innerText({ timeout: 1000 }).catch(() => "");
      return count === `${motionMoves} moves` || `it says ${JSON.stringify(count)}`;
    });
    // the page the debug session wrote (titled with the entry), not a new run
    const title = await view.locator("header b").innerText();
    assert(title.endsWith("motion.mod (main)"), `page title ${JSON.stringify(title)}`);
    const drawn = await view.locator("canvas#c").evaluate((c) => c.width > 0 && c.height > 0);
    assert(drawn, "the canvas has no size");
    await page.screenshot({ path: path.join(out, "vscode-show-path.png") });
  });

  await step(`RAPID: Show path runs a routine that has not run yet (square: ${squareMoves} moves)`, async () => {
    await open("Square.mod");
    await goTo(SQUARE.split("\n").findIndex((l) => l.includes("MoveL pCorner")) + 1, 5);
    await runCommand("RAPID: Show path");
    await page.locator(".tabs-container .tab", { hasText: "Path: square" }).first().waitFor({ state: "visible" });
    const view = pathView();
    await waitFor("the path page", async () => {
      const count = await view.locator("#count").innerText({ timeout: 1000 }).catch(() => "");
      return count === `${squareMoves} moves` || `it says ${JSON.stringify(count)}`;
    });
    await page.screenshot({ path: path.join(out, "vscode-show-path-square.png") });
  });

  const squareLines = SQUARE.split("\n");
  const squareBreak = squareLines.findIndex((l) => l.includes("Offs(pCorner, 100, 100, 0)")) + 1;
  const squareTop = () => page.locator(".debug-call-stack .monaco-list-row", { hasText: "square" }).first();
  const followed = async (what, line, end) => {
    const view = pathView();
    await waitFor(what, async () => {
      const here = await view.locator("#current").innerText({ timeout: 1000 }).catch(() => "");
      const now = await view.locator("#now").innerText({ timeout: 1000 }).catch(() => "");
      return (
        (here.includes(`Square.mod:${line} at ${end.toFixed(3)} s`) &&
          here.includes(`the last move: MoveL`) &&
          here.includes(`Square.mod:${line - 1})`) &&
          now.startsWith(`${end.toFixed(3)} s of ${end.toFixed(3)} s: MoveL`)) ||
        `the page says ${JSON.stringify(here)} / ${JSON.stringify(now)}`
      );
    });
  };
  await step(`the path follows the debugger: the arm at the breakpoint (Square.mod:${squareBreak}, ${squareEnds[1].toFixed(3)} s), then after a step`, async () => {
    await open("Square.mod");
    await goTo(squareBreak, 5);
    await runCommand("Debug: Toggle Breakpoint");
    // the quick access of launch configurations ("debug " in the palette)
    await page.keyboard.press("F1");
    const input = page.locator(".quick-input-widget input");
    await input.waitFor({ state: "visible" });
    await input.fill("debug Run square");
    await page.locator(".quick-input-widget .monaco-list-row", { hasText: "Run square" }).first().waitFor({ state: "visible" });
    await page.keyboard.press("Enter");
    await page.locator(".debug-toolbar").waitFor({ state: "visible" });
    await waitFor("the call stack", async () => {
      const text = (await squareTop().innerText().catch(() => "")).replace(/\s+/g, " ");
      return new RegExp(`Square\\.mod\\s*${squareBreak}:`).test(text) || `top frame: ${text}`;
    });
    // beside the editor, the robot at the breakpoint: two moves made
    await page.locator(".tabs-container .tab", { hasText: "Path: square" }).first().waitFor({ state: "visible" });
    await followed("the path at the breakpoint", squareBreak, squareEnds[1]);
    const view = pathView();
    assert(await view.locator("#timebar").isVisible(), "no time bar: the arm is not drawn");
    assert((await view.locator("#count").innerText()) === "2 moves", "not the two moves made so far");
    await page.screenshot({ path: path.join(out, "vscode-debug-path-breakpoint.png") });
    // a step: the page follows, one move on
    await page.locator(".monaco-editor textarea").first().focus();
    await page.keyboard.press("F10");
    await followed("the path after the step", squareBreak + 1, squareEnds[2]);
    await page.screenshot({ path: path.join(out, "vscode-debug-path-step.png") });
    await page.keyboard.press("F5");
    await page.locator(".debug-toolbar").waitFor({ state: "hidden" });
  });
}
