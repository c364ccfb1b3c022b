// End-to-end test of the RAPID extension in a real VS Code: code-server serves
// VS Code on 127.0.0.1, Chromium (playwright-core) drives it. The extension is
// installed from the .vsix, the workspace is a copy of examples/palletizer with
// a seeded error, and what the editor shows is compared with what the `rapid`
// binary itself says (`rapid check --format json`, `rapid builtins NAME`).
//
//   node run.mjs --vsix rapid.vsix --rapid /path/to/rapid --out tests/output
//
// Prints one line per check and "N passed, N failed" at the end.
import { spawn, spawnSync } from "node:child_process";
import * as fs from "node:fs";
import * as net from "node:net";
import * as os from "node:os";
import * as path from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { makeWorkspace } from "../../e2e-workspace.mjs";
import { debugSteps } from "./debug.mjs";
import { diffSteps } from "./diff.mjs";

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, "../../..");

function arg(name, fallback) {
  const i = process.argv.indexOf(`--${name}`);
  return i >= 0 ? process.argv[i + 1] : fallback;
}
const vsix = path.resolve(arg("vsix", path.join(here, "../rapid.vsix")));
const rapid = path.resolve(arg("rapid", "rapid"));
const out = path.resolve(arg("out", path.join(repo, "tests/output")));
const chromiumPath = arg("chromium", "/usr/bin/chromium");
const codeServer = path.join(here, "node_modules/code-server/out/node/entry.js");
const TIMEOUT = Number(process.env.RAPID_E2E_TIMEOUT_MS ?? 60000);

fs.mkdirSync(out, { recursive: true });
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), "rapid-vscode-e2e-"));
const log = (...a) => console.log("[e2e]", ...a);

// ------------------------------------------------------------ the workspace
const ws = path.join(tmp, "workspace");
const mainFile = makeWorkspace(ws);
const lines = fs.readFileSync(mainFile, "latin1").split("\n");
const lineOf = (needle) => {
  const i = lines.findIndex((l) => l.includes(needle));
  if (i < 0) throw new Error(`no line with ${needle}`);
  return i + 1;
};

// What the rapid binary says about the workspace: the editor must show it.
const check = spawnSync(rapid, ["check", ws, "--format", "json"], { encoding: "utf8" });
if (check.error) throw check.error;
const findings = JSON.parse(check.stdout);
const expected = findings.filter(
  (d) => d.severity === "error" && path.basename(d.file) === "MainModule.mod",
);
// a file the test never opens
const cellExpected = findings.filter((d) => path.basename(d.file) === "Cell.sys");
if (expected.length === 0) {
  throw new Error(`rapid check found no error in the seeded file:\n${check.stdout}${check.stderr}`);
}
const builtin = (name) => {
  const r = spawnSync(rapid, ["builtins", name], { encoding: "utf8" });
  if (r.status !== 0) throw new Error(`rapid builtins ${name}: ${r.stderr}`);
  return r.stdout.split("\n")[0].trim();
};
const waitTimeSignature = builtin("WaitTime");
const moveLSignature = builtin("MoveL");
// the names of the parameters written with a leading backslash that come
// after the last required one (Tool): what may follow `tool\`
const moveLParams = moveLSignature
  .replace(/^[^(]*\(|\)[^)]*$/g, "")
  .split(/[,|]/)
  .map((p) => p.trim());
const lastRequired = moveLParams.findLastIndex((p) => !p.startsWith("\\"));
const moveLOptionals = moveLParams
  .slice(lastRequired + 1)
  .map((p) => p.split(/\s+/).pop().replace(/\{.*$/, ""));
// the robtarget the seeded module uses most: first after `MoveL `
const words = lines.join("\n").match(/[A-Za-z][A-Za-z0-9_]*/g) ?? [];
const uses = (name) => words.filter((w) => w.toLowerCase() === name.toLowerCase()).length;
// in scope where the test types (after `WaitTime 0.2;`): the module's and
// that routine's own
const robtargets = [];
{
  let routine = null;
  const here = lines.findIndex((l) => l.includes("WaitTime 0.2;"));
  lines.forEach((l, i) => {
    if (/^\s*(LOCAL\s+)?(PROC|FUNC|TRAP)\b/i.test(l)) routine = i;
    const name = l.match(/^\s*(?:LOCAL\s+|TASK\s+)?(?:VAR|PERS|CONST)\s+robtarget\s+([A-Za-z][A-Za-z0-9_]*)/i)?.[1];
    const routineOfHere = routine !== null && routine <= here && !lines.slice(routine, here).some((x) => /^\s*END(PROC|FUNC|TRAP)\b/i.test(x));
    if (name && (routine === null || (routineOfHere && i <= here))) robtargets.push(name);
    if (/^\s*END(PROC|FUNC|TRAP)\b/i.test(l)) routine = null;
  });
  robtargets.sort((a, b) => uses(b) - uses(a) || a.toLowerCase().localeCompare(b.toLowerCase()));
}
log(`expected: ${expected.map((d) => `${d.code} at ${d.line}:${d.column}`).join(", ")}; MoveL optional arguments ${moveLOptionals.join(" ")}`);

// ------------------------------------------------------------ code-server
const data = path.join(tmp, "data");
const extensions = path.join(tmp, "extensions");
const settings = JSON.stringify(
    {
      "workbench.startupEditor": "none",
      "workbench.tips.enabled": false,
      "workbench.welcomePage.walkthroughs.openOnInstall": false,
      "security.workspace.trust.enabled": false,
      "extensions.autoCheckUpdates": false,
      "extensions.autoUpdate": false,
      "telemetry.telemetryLevel": "off",
      "update.mode": "none",
      "editor.hover.delay": 100,
      "editor.quickSuggestions": { other: false, comments: false, strings: false },
      "editor.wordBasedSuggestions": "off",
      "chat.disableAIFeatures": true,
      "workbench.secondarySideBar.defaultVisibility": "hidden",
      "rapid.trace.server": "messages",
      // unused data (W201, the seeded findings of Cell.sys and of the lone
      // file) are hints by default, which the Problems panel does not list
      "rapid.rules": { W201: "warning" },
      // code-server's extension host takes PATH from a login shell, not from
      // this process: name the binary (so the PATH lookup is not exercised here).
      "rapid.server.path": rapid,
    },
    null,
    2,
);
// code-server is a remote: machine-scoped settings (rapid.server.path) are
// read from the remote machine's settings, the rest from the user's.
for (const scope of ["User", "Machine"]) {
  fs.mkdirSync(path.join(data, scope), { recursive: true });
  fs.writeFileSync(path.join(data, scope, "settings.json"), settings);
}
const env = {
  ...process.env,
  PATH: `${path.dirname(rapid)}${path.delimiter}${process.env.PATH}`,
};
const csArgs = ["--user-data-dir", data, "--extensions-dir", extensions];
const install = spawnSync(process.execPath, [codeServer, ...csArgs, "--install-extension", vsix], {
  encoding: "utf8",
  env,
});
log(`install-extension: ${(install.stdout + install.stderr).trim().split("\n").pop()}`);
if (install.status !== 0) {
  throw new Error(`code-server --install-extension failed:\n${install.stdout}${install.stderr}`);
}

const port = await new Promise((resolve, reject) => {
  const srv = net.createServer();
  srv.on("error", reject);
  srv.listen(0, "127.0.0.1", () => {
    const p = srv.address().port;
    srv.close(() => resolve(p));
  });
});
fs.writeFileSync(path.join(tmp, "config.yaml"), "auth: none\ncert: false\n");
const server = spawn(
  process.execPath,
  [
    codeServer,
    ...csArgs,
    "--config", path.join(tmp, "config.yaml"),
    "--bind-addr", `127.0.0.1:${port}`,
    "--auth", "none",
    "--disable-telemetry",
    "--disable-update-check",
    "--disable-workspace-trust",
    "--disable-getting-started-override",
    ws,
  ],
  { env, stdio: ["ignore", "pipe", "pipe"], detached: false },
);
const serverLog = fs.createWriteStream(path.join(out, "vscode-code-server.log"));
server.stdout.pipe(serverLog);
server.stderr.pipe(serverLog);

let passed = 0;
let failed = 0;
const failures = [];
// RAPID_E2E_ONLY=debug (or diff, or backup) runs the debugger's (or Compare
// with backup's, or the backups') checks alone (while working on them)
const onlyDebug = process.env.RAPID_E2E_ONLY !== undefined;
async function step(name, fn, always = false) {
  if (onlyDebug && !always) return;
  try {
    await fn();
    passed += 1;
    console.log(`ok - ${name}`);
  } catch (err) {
    failed += 1;
    failures.push(name);
    console.log(`FAILED - ${name}: ${err?.message ?? err}`);
    // What the window showed when the step failed, for the CI log's reader.
    const slug = name.replace(/[^A-Za-z0-9]+/g, "-").slice(0, 60);
    await page?.screenshot({ path: path.join(out, `failed-${slug}.png`) }).catch(() => {});
  }
}
function assert(cond, message) {
  if (!cond) throw new Error(message);
}
/// How many times the extension's log says it started `rapid lsp` (from
/// `command`, when given).
function serverStarts(command) {
  const line = command ? `Starting ${command} lsp` : /^Starting /gm;
  let n = 0;
  const walk = (dir) => {
    for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
      const p = path.join(dir, e.name);
      if (e.isDirectory()) walk(p);
      else if (e.name.endsWith("RAPID Language Server.log")) {
        const text = fs.readFileSync(p, "utf8");
        n += typeof line === "string" ? text.split(line).length - 1 : (text.match(line) ?? []).length;
      }
    }
  };
  walk(path.join(data, "logs"));
  return n;
}

let browser;
let page;
try {
  // wait for the server
  const started = Date.now();
  for (;;) {
    try {
      const res = await fetch(`http://127.0.0.1:${port}/healthz`);
      if (res.ok) break;
    } catch {}
    if (Date.now() - started > TIMEOUT) throw new Error("code-server did not start");
    await new Promise((r) => setTimeout(r, 250));
  }
  browser = await chromium.launchPersistentContext(path.join(tmp, "chromium"), {
    executablePath: chromiumPath,
    viewport: { width: 1400, height: 900 },
    headless: true,
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--disable-quic",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
    ],
  });
  page = browser.pages()[0] ?? (await browser.newPage());
  page.setDefaultTimeout(TIMEOUT);
  await page.goto(`http://127.0.0.1:${port}/?folder=${encodeURIComponent(ws)}`);
  await page.waitForSelector(".monaco-workbench");
  await page.waitForSelector(".part.editor");
  await page.waitForTimeout(1500);

  const runCommand = async (label) => {
    await page.keyboard.press("F1");
    const input = page.locator(".quick-input-widget input");
    await input.waitFor({ state: "visible" });
    await input.fill(`>${label}`);
    await page.waitForTimeout(300);
    await page.keyboard.press("Enter");
  };
  const goTo = async (line, column) => {
    await page.keyboard.press("Control+G");
    const input = page.locator(".quick-input-widget input");
    await input.waitFor({ state: "visible" });
    await input.fill(`:${line}:${column}`);
    await page.waitForTimeout(200);
    await page.keyboard.press("Enter");
    await page.waitForTimeout(200);
  };
  const editorText = () => page.locator(".monaco-editor .view-lines").first();
  const showHoverAt = async (line, column) => {
    await page.keyboard.press("Escape");
    await goTo(line, column);
    await runCommand("Show or Focus Hover");
    const hover = page.locator(".monaco-hover:not(.hidden) .monaco-hover-content, .monaco-hover:not(.hidden) .hover-contents").first();
    await hover.waitFor({ state: "visible" });
    // the hover may first say "Loading..."
    const deadline = Date.now() + TIMEOUT;
    let text = "";
    while (Date.now() < deadline) {
      text = (await page.locator(".monaco-hover:not(.hidden)").first().innerText()).trim();
      if (text && !/^Loading/.test(text)) break;
      await page.waitForTimeout(200);
    }
    return text;
  };

  await step("the workspace starts the server: Problems lists its modules before any is opened", async () => {
    // The workspace's diagnostics come once the extension has started the
    // server and it has read the folder, which under load can outlast one
    // wait; the command that shows Problems is given again meanwhile, in
    // case the palette took it before the workbench was ready.
    const rowOf = (want) =>
      page
        .locator(".markers-panel .monaco-list-row", { hasText: want.code })
        .filter({ hasText: want.message.slice(0, 20) })
        .first();
    const deadline = Date.now() + 2 * TIMEOUT;
    let shown = false;
    while (!shown && Date.now() < deadline) {
      await page.keyboard.press("Escape");
      await runCommand("View: Focus Problems");
      shown = true;
      for (const want of [expected[0], cellExpected[0]]) {
        try {
          await rowOf(want).waitFor({ state: "visible", timeout: 10000 });
        } catch {
          shown = false;
          break;
        }
      }
    }
    if (!shown) {
      const panel = await page.locator(".markers-panel").first().innerText().catch(() => "(no Problems panel)");
      throw new Error(`Problems does not list both seeded errors: ${JSON.stringify(panel.slice(0, 500))}`);
    }
    const tabs = await page.locator(".tabs-container .tab").count();
    await page.screenshot({ path: path.join(out, "vscode-workspace-problems.png") });
    assert(tabs === 0, `${tabs} editors are open`);
  });

  // open the seeded module through Quick Open
  await page.keyboard.press("Control+P");
  await page.locator(".quick-input-widget input").waitFor({ state: "visible" });
  await page.locator(".quick-input-widget input").fill("MainModule.mod");
  await page.waitForSelector(".quick-input-list .monaco-list-row");
  await page.keyboard.press("Enter");
  await editorText().waitFor({ state: "visible" });
  await page.locator(".monaco-editor textarea").first().focus();

  await step("the file is recognised as RAPID", async () => {
    const mode = page.locator("#status\\.editor\\.mode");
    await mode.waitFor({ state: "visible" });
    const text = (await mode.innerText()).trim();
    assert(text === "ABB RAPID", `language status says ${JSON.stringify(text)}`);
  });

  await step("TextMate grammar colours the first paint (keywords, types and numbers differ)", async () => {
    // Monaco gives each colour of the theme a mtkN class: without the
    // grammar, MODULE, num and 3 would be one plain token colour.
    const classOf = async (word) =>
      page.locator(".view-line span span", { hasText: new RegExp(`^${word}$`) }).first().getAttribute("class");
    const kw = await classOf("MODULE");
    const type = await classOf("num");
    const number = await classOf("3");
    assert(
      kw && type && number && new Set([kw, type, number]).size === 3,
      `classes MODULE=${kw} num=${type} 3=${number}`,
    );
  });

  await step(`a diagnostic appears for the seeded error (${expected[0].code})`, async () => {
    await runCommand("View: Focus Problems");
    const row = page.locator(".markers-panel .monaco-list-row", { hasText: expected[0].code });
    await row.first().waitFor({ state: "visible", timeout: TIMEOUT });
    const text = await row.first().innerText();
    assert(text.includes(expected[0].message.slice(0, 30)), `problem row: ${text}`);
    assert(text.includes(`[Ln ${expected[0].line}, Col ${expected[0].column}]`), `problem row: ${text}`);
    await page.locator(".monaco-editor textarea").first().focus();
  });

  await step(`a file that is not open is in the Problems panel too (Cell.sys: ${cellExpected[0]?.code})`, async () => {
    assert(cellExpected.length > 0, "rapid check found nothing in Cell.sys");
    await runCommand("View: Focus Problems");
    const want = cellExpected[0];
    const row = page.locator(".markers-panel .monaco-list-row", { hasText: want.code }).filter({
      hasText: want.message.slice(0, 20),
    });
    await row.first().waitFor({ state: "visible", timeout: TIMEOUT });
    const text = await row.first().innerText();
    assert(text.includes(`[Ln ${want.line}, Col ${want.column}]`), `problem row: ${text}`);
    const file = page.locator(".markers-panel .monaco-list-row", { hasText: "Cell.sys" });
    assert((await file.count()) > 0, "no Cell.sys row in the Problems panel");
    const tabs = (await page.locator(".tabs-container .tab").allInnerTexts()).join(" ");
    assert(!tabs.includes("Cell.sys"), `Cell.sys is open: ${tabs}`);
    await page.screenshot({ path: path.join(out, "vscode-problems.png") });
    await page.locator(".monaco-editor textarea").first().focus();
  });

  await step("RAPID: Restart Language Server starts a new server", async () => {
    const starts = () => serverStarts();
    const before = starts();
    assert(before >= 1, `the log channel shows ${before} server starts`);
    await runCommand("RAPID: Restart Language Server");
    const deadline = Date.now() + TIMEOUT;
    while (starts() <= before && Date.now() < deadline) await page.waitForTimeout(200);
    assert(starts() > before, "no new server start in the log channel");
    // and the new server publishes the diagnostics again
    const row = page.locator(".markers-panel .monaco-list-row", { hasText: expected[0].code });
    await row.first().waitFor({ state: "visible", timeout: TIMEOUT });
    await page.locator(".monaco-editor textarea").first().focus();
  });

  await step("hover over a built-in call shows its signature", async () => {
    const line = lineOf("WaitTime 0.2;");
    const text = await showHoverAt(line, lines[line - 1].indexOf("WaitTime") + 3);
    assert(text.includes(waitTimeSignature), `hover: ${text}\nexpected: ${waitTimeSignature}`);
  });

  await step("hover over a constant expression shows its value", async () => {
    const line = lineOf("\\Num:=nSlots");
    const text = await showHoverAt(line, lines[line - 1].indexOf("nSlots") + 3);
    assert(/\b24\b/.test(text), `hover: ${text}`);
  });

  await step("hover over a constant's declaration shows its value too", async () => {
    const line = lineOf("CONST num nSlots");
    const text = await showHoverAt(line, lines[line - 1].indexOf("nSlots") + 3);
    assert(/\b24\b/.test(text), `hover: ${text}`);
  });

  await step("parameter names are hinted before literals, not before names", async () => {
    await page.keyboard.press("Escape");
    const line = lineOf("SetDO doVacuum, 1;");
    await goTo(line, 1);
    const view = page.locator(".view-line", { hasText: "SetDO" }).first();
    const deadline = Date.now() + TIMEOUT;
    let text = "";
    while (Date.now() < deadline) {
      text = (await view.innerText()).replace(/\u00a0/g, " ");
      if (/Value:\s*1/.test(text)) break;
      await page.waitForTimeout(200);
    }
    assert(/Value:\s*1/.test(text), `the SetDO line shows ${JSON.stringify(text)}`);
    assert(!/Signal:/.test(text), `a hint before a name: ${JSON.stringify(text)}`);
    const move = (await page.locator(".view-line", { hasText: "MoveL pPickAbove" }).first().innerText()).replace(/\u00a0/g, " ");
    assert(!/ToPoint:|Tool:/.test(move), `hints before names: ${JSON.stringify(move)}`);
  });

  await step("semantic tokens from the server colour a user routine call", async () => {
    await page.keyboard.press("Escape");
    const line = lineOf("PickBox;");
    await goTo(line, lines[line - 1].indexOf("PickBox") + 3);
    await runCommand("Developer: Inspect Editor Tokens and Scopes");
    const widget = page.locator(".token-inspect-widget");
    await widget.waitFor({ state: "visible" });
    const deadline = Date.now() + TIMEOUT;
    let text = "";
    while (Date.now() < deadline) {
      text = await widget.innerText();
      if (/semantic token type\s+(method|function)/.test(text)) break;
      await page.waitForTimeout(200);
    }
    await page.screenshot({ path: path.join(out, "vscode-tokens.png") });
    await page.keyboard.press("Escape");
    assert(/semantic token type\s+(method|function)/.test(text), `inspector: ${text}`);
  });

  await step("completion after \\ lists the optional arguments", async () => {
    await page.keyboard.press("Escape");
    const line = lineOf("WaitTime 0.2;");
    await goTo(line, lines[line - 1].length + 1);
    await page.keyboard.press("End");
    await page.keyboard.press("Enter");
    await page.keyboard.type("MoveL pPickAbove, v300, fine, tGripper\\", { delay: 20 });
    const rows = page.locator(".suggest-widget.visible .monaco-list-row");
    try {
      await rows.first().waitFor({ state: "visible", timeout: 5000 });
    } catch {
      log("no completion popped up on '\\' by itself; asking with Ctrl+Space");
      await page.keyboard.press("Control+Space");
      await rows.first().waitFor({ state: "visible" });
    }
    await page.waitForTimeout(500);
    const labels = (await rows.allInnerTexts()).map((t) => t.trim().split(/\s/)[0].replace(/^\\/, ""));
    // only what may come after the Tool argument, in order
    assert(
      labels.join(" ") === moveLOptionals.join(" "),
      `completion rows after tGripper\\: ${labels.join(", ")}; expected ${moveLOptionals.join(", ")}`,
    );
    // signature help marks that parameter, with its type
    await page.keyboard.press("Escape");
    await page.keyboard.press("Control+Shift+Space");
    const hints = page.locator(".parameter-hints-widget");
    await hints.waitFor({ state: "visible" });
    const active = (await hints.locator(".parameter.active").first().innerText()).trim();
    const signature = (await hints.locator(".signature .code").first().innerText()).trim();
    await page.screenshot({ path: path.join(out, "vscode-signature.png") });
    await page.keyboard.press("Escape");
    assert(active === "[\\PERS wobjdata WObj]", `active parameter ${JSON.stringify(active)} in ${signature}`);
    assert(signature.includes("robtarget ToPoint"), `no types in ${signature}`);
    await page.keyboard.press("Control+Space");
    await rows.first().waitFor({ state: "visible" });
    await page.keyboard.type("WOb", { delay: 20 });
    await page.waitForTimeout(500);
    const first = (await rows.first().innerText()).trim();
    assert(/^\\?WObj\b/.test(first), `after \\WOb the first row is ${first}`);
    await page.screenshot({ path: path.join(out, "vscode-completion.png") });
    await page.keyboard.press("Escape");
  });

  await step("a blank after MoveL opens its first argument: the robtargets, the most used first", async () => {
    await page.keyboard.press("Escape");
    const line = lineOf("WaitTime 0.2;");
    await goTo(line, lines[line - 1].length + 1);
    await page.keyboard.press("End");
    await page.keyboard.press("Enter");
    await page.keyboard.type("MoveL ", { delay: 20 });
    const rows = page.locator(".suggest-widget.visible .monaco-list-row");
    await rows.first().waitFor({ state: "visible", timeout: 10000 });
    await page.waitForTimeout(500);
    const labels = (await rows.allInnerTexts()).map((t) => t.trim().split(/\s/)[0]);
    await page.screenshot({ path: path.join(out, "vscode-completion-first-argument.png") });
    await page.keyboard.press("Escape");
    await page.keyboard.press("Control+Z");
    assert(robtargets.length > 0, "no robtarget in the seeded module");
    assert(labels[0] === robtargets[0], `first row ${labels[0]}, expected ${robtargets[0]}: ${labels.join(", ")}`);
    assert(!labels.includes("nPlaced"), `a num offered for a robtarget: ${labels.join(", ")}`);
  });

  await step("MoveL ranks first at the start of a statement", async () => {
    await page.keyboard.press("Escape");
    const line = lineOf("WaitTime 0.2;");
    await goTo(line, lines[line - 1].length + 1);
    await page.keyboard.press("End");
    await page.keyboard.press("Enter");
    await page.keyboard.press("Control+Space");
    const rows = page.locator(".suggest-widget.visible .monaco-list-row");
    await rows.first().waitFor({ state: "visible" });
    await page.waitForTimeout(500);
    const first = (await rows.first().innerText()).trim().split(/\s/)[0];
    await page.keyboard.press("Escape");
    await page.keyboard.press("Control+Z");
    assert(first === "MoveL", `the first row is ${first}`);
  });

  // "Compare with backup…" and its view, on this workspace
  const only = process.env.RAPID_E2E_ONLY;
  await diffSteps({ page, ws, tmp, out, rapid, assert, runCommand, TIMEOUT, step: (n, f) => step(n, f, only === "diff") });

  /// A controller backup at `backup` (BACKINFO, and an EIO.cfg with the
  /// input diGo): returns a function that writes a file into it.
  const backupWriter = (backup) => {
    const write = (rel, text) => {
      fs.mkdirSync(path.dirname(path.join(backup, rel)), { recursive: true });
      fs.writeFileSync(path.join(backup, rel), text);
    };
    write("BACKINFO/backinfo.txt", "backup\n");
    write("SYSPAR/EIO.cfg", 'EIO:CFG_1.0:6:1::\n#\nEIO_SIGNAL:\n\n      -Name "diGo" -SignalType "DI" -Device "d652"\n');
    return write;
  };

  const backupStep = (name, fn) => step(name, fn, only === "backup");
  await backupStep("a controller backup opened as the workspace shows its Problems before any file is opened", async () => {
    const backup = path.join(tmp, "backup", "CELL_BACKUP");
    const write = backupWriter(backup);
    write(
      "RAPID/TASK1/PROGMOD/Cell.mod",
      "MODULE Cell\n    PROC main()\n        VAR num nSpare;\n        WaitDI diGo, 1;\n    ENDPROC\nENDMODULE\n",
    );
    const want = JSON.parse(spawnSync(rapid, ["check", backup, "--format", "json"], { encoding: "utf8" }).stdout);
    assert(want.length === 1 && want[0].code === "W201", `rapid check says ${JSON.stringify(want)}`);
    await page.goto(`http://127.0.0.1:${port}/?folder=${encodeURIComponent(backup)}`);
    await page.waitForSelector(".monaco-workbench");
    await page.waitForTimeout(1500);
    await runCommand("View: Focus Problems");
    const row = page.locator(".markers-panel .monaco-list-row", { hasText: "W201" }).filter({ hasText: "nSpare" });
    await row.first().waitFor({ state: "visible", timeout: TIMEOUT });
    const tabs = await page.locator(".tabs-container .tab").count();
    await page.screenshot({ path: path.join(out, "vscode-backup-problems.png") });
    assert(tabs === 0, `${tabs} editors are open`);
  });

  await backupStep("one file opened without its folder gets its task from its place (a backup's SYSMOD and SYSPAR)", async () => {
    const backup = path.join(tmp, "lone", "BACKUP");
    const write = backupWriter(backup);
    write(
      "RAPID/TASK1/PROGMOD/Lone.mod",
      "MODULE Lone\n    PROC main()\n        VAR num nUnused;\n        LibHelper;\n        WaitDI diGo, 1;\n    ENDPROC\nENDMODULE\n",
    );
    write("RAPID/TASK1/SYSMOD/Lib.sys", "MODULE Lib(SYSMODULE)\n    PROC LibHelper()\n    ENDPROC\nENDMODULE\n");
    const lone = path.join(backup, "RAPID/TASK1/PROGMOD/Lone.mod");
    const want = JSON.parse(
      spawnSync(rapid, ["check", lone, "--format", "json"], { encoding: "utf8" }).stdout,
    ).map((d) => `${d.code}@${d.line}`);
    assert(want.join(" ") === "W201@3", `rapid check says ${want.join(" ")}`);
    // An empty window (no folder) that opens the file, as VS Code's own
    // "open in a new window" does: the workbench's `openFile` payload. (The
    // simple File: Open File... dialog checks a typed path asynchronously and
    // lost the Enter on a busy CI machine.)
    const payload = JSON.stringify([["openFile", `vscode-remote://127.0.0.1:${port}${lone}`]]);
    await page.goto(`http://127.0.0.1:${port}/?ew=true&payload=${encodeURIComponent(payload)}`);
    await page.waitForSelector(".monaco-workbench");
    const tab = page.locator(".tabs-container .tab", { hasText: "Lone.mod" }).first();
    await tab.waitFor({ state: "visible", timeout: TIMEOUT });
    // the editor shows the file, and the workbench has settled (focus moves to
    // the editor as it opens, closing a palette opened before)
    await page.locator(".monaco-editor .view-lines", { hasText: "MODULE Lone" }).first().waitFor({ state: "visible", timeout: TIMEOUT });
    await page.waitForTimeout(2000);
    // the title names the file and no folder (a folder's name would follow it)
    const title = await page.title();
    assert(!/BACKUP|TASK1|PROGMOD/.test(title), `the window has a folder open: ${title}`);
    await runCommand("View: Focus Problems");
    const row = page.locator(".markers-panel .monaco-list-row", { hasText: "W201" });
    await row.first().waitFor({ state: "visible", timeout: TIMEOUT });
    // the task's routine and the backup's signal are known: only W201
    await page.waitForTimeout(2000);
    const rows = (await page.locator(".markers-panel .monaco-list-row").allInnerTexts()).join("\n");
    await page.screenshot({ path: path.join(out, "vscode-lone-file.png") });
    assert(!/W101|I103/.test(rows), `Problems: ${rows}`);
  });

  // the debugger and the path view, in a workspace of their own
  const debugStep = (name, fn) => step(name, fn, only === "debug");
  await debugSteps({ page, port, tmp, out, rapid, repo, step: debugStep, assert, runCommand, goTo, TIMEOUT });

  await step("a missing server binary gives a message with a link to the install instructions", async () => {
    const machine = path.join(data, "Machine", "settings.json");
    const bogus = path.join(tmp, "no-such-dir", "rapid");
    fs.writeFileSync(machine, JSON.stringify({ ...JSON.parse(settings), "rapid.server.path": bogus }, null, 2));
    const toast = page.locator(".notifications-toasts .notification-toast", { hasText: bogus });
    await toast.first().waitFor({ state: "visible" });
    const text = await toast.first().innerText();
    await page.screenshot({ path: path.join(out, "vscode-missing-server.png") });
    assert(/does not exist or cannot be run/.test(text), `notification: ${text}`);
    assert(/How to install/.test(text), `notification without the install link: ${text}`);
    assert(/cargo install --path lsp/.test(text), `notification without how to install: ${text}`);
    // the instructions are the extension's own README (no web page yet)
    await toast.first().locator(".monaco-button", { hasText: "How to install" }).click();
    const preview = page.locator(".tabs-container .tab", { hasText: "README" });
    await preview.first().waitFor({ state: "visible" });
    await page.screenshot({ path: path.join(out, "vscode-install-readme.png") });
    // "Set path" in this remote window asks for the path and starts the server
    const startsBefore = serverStarts(rapid);
    await runCommand("RAPID: Restart Language Server");
    const again = page.locator(".notifications-toasts .notification-toast", { hasText: bogus });
    await again.first().waitFor({ state: "visible" });
    await again.first().locator(".monaco-button", { hasText: "Set path" }).click();
    const input = page.locator(".quick-input-widget input");
    await input.waitFor({ state: "visible" });
    await input.fill(path.join(tmp, "no-such-dir", "still-not-rapid"));
    await page.waitForTimeout(500);
    const refused = (await page.locator(".quick-input-widget").innerText()).trim();
    assert(/does not exist or cannot be run/.test(refused), `a bad path is not refused: ${refused}`);
    await input.fill(rapid);
    await page.waitForTimeout(500);
    await page.screenshot({ path: path.join(out, "vscode-set-path.png") });
    await page.keyboard.press("Enter");
    const saved = () =>
      ["Machine", "User"].some((scope) => {
        const file = path.join(data, scope, "settings.json");
        return fs.existsSync(file) && fs.readFileSync(file, "utf8").includes(JSON.stringify(rapid).slice(1, -1));
      }) && !fs.readFileSync(machine, "utf8").includes(bogus);
    const deadline = Date.now() + TIMEOUT;
    while (!saved() && Date.now() < deadline) await page.waitForTimeout(200);
    assert(saved(), "rapid.server.path was not saved");
    // the server starts with the path given
    while (serverStarts(rapid) <= startsBefore && Date.now() < deadline) await page.waitForTimeout(200);
    assert(serverStarts(rapid) > startsBefore, "no server start with the path given");
    fs.writeFileSync(machine, settings);
  });
} catch (err) {
  failed += 1;
  failures.push(`setup: ${err?.message ?? err}`);
  console.log(`FAILED - setup: ${err?.stack ?? err}`);
} finally {
  if (page) {
    await page.screenshot({ path: path.join(out, "vscode.png") }).catch(() => {});
    // the extension's log, for whoever reads a failure
    const logs = path.join(data, "logs");
    if (fs.existsSync(logs)) fs.cpSync(logs, path.join(out, "vscode-logs"), { recursive: true });
  }
  await browser?.close().catch(() => {});
  server.kill("SIGTERM");
  await new Promise((resolve) => {
    if (server.exitCode !== null) return resolve();
    server.once("exit", resolve);
    setTimeout(resolve, 5000);
  });
  // The profile, workspace and code-server data are scratch (what is worth
  // keeping was copied to `out`): left behind, every run leaves one.
  fs.rmSync(tmp, { recursive: true, force: true, maxRetries: 3 });
}
console.log(`screenshots and logs: ${out}`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
