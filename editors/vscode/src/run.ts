// Running RAPID on the simulated controller: the `rapid` debugger (`rapid
// dap`) and "RAPID: Show path", which draws the motion of a routine's last
// run (the page `rapid run --plot` writes) in a webview. While a debug
// session runs, the webview follows it: at each stop the adapter sends the
// page's state (`rapidPath`: the moves so far, the arm at that time, the
// move that brought the robot there), which the page redraws.
import { execFile } from "node:child_process";
import * as crypto from "node:crypto";
import * as fs from "node:fs";
import * as path from "node:path";
import * as vscode from "vscode";

/// One finished run whose path page is on disk.
interface LastRun {
  program: string;
  entry: string;
  page: string;
  when: number;
}

const RUNS_KEY = "rapid.lastRuns";
let panel: vscode.WebviewPanel | undefined;
/// The debug session the panel follows, if any.
let panelSession: string | undefined;
let runLog: vscode.OutputChannel | undefined;

/// Registers the debugger and "Show path"; `rapid` names the binary.
export function registerRun(context: vscode.ExtensionContext, rapid: () => string): void {
  const pages = path.join(context.globalStorageUri.fsPath, "paths");
  runLog = vscode.window.createOutputChannel("RAPID Run");
  context.subscriptions.push(runLog);

  context.subscriptions.push(
    vscode.debug.registerDebugAdapterDescriptorFactory("rapid", {
      createDebugAdapterDescriptor() {
        return new vscode.DebugAdapterExecutable(rapid(), ["dap"]);
      },
    }),
    vscode.debug.registerDebugConfigurationProvider("rapid", {
      // F5 without a launch.json: run `main` of the current file's task.
      resolveDebugConfiguration(_folder, config) {
        if (!config.type && !config.request && !config.name) {
          const editor = vscode.window.activeTextEditor;
          if (editor?.document.languageId !== "rapid") {
            return config;
          }
          return { type: "rapid", request: "launch", name: "Run main", program: "${file}", entry: "main" };
        }
        return config;
      },
      // Every launch draws its path, for "Show path" to open afterwards.
      resolveDebugConfigurationWithSubstitutedVariables(_folder, config) {
        if (config.request === "launch" && typeof config.program === "string" && !config.plot) {
          fs.mkdirSync(pages, { recursive: true });
          config.plot = pageFile(pages, config.program, config.entry ?? "main");
        }
        return config;
      },
    }),
    vscode.debug.onDidReceiveDebugSessionCustomEvent((e) => {
      if (e.session.type === "rapid" && e.event === "rapidPath") {
        followPath(e.session, e.body as PathEvent);
      }
    }),
    vscode.debug.onDidTerminateDebugSession((session) => {
      const c = session.configuration;
      if (session.type === "rapid" && typeof c.plot === "string" && fs.existsSync(c.plot)) {
        void remember(context, { program: c.program, entry: c.entry ?? "main", page: c.plot, when: Date.now() });
      }
    }),
    vscode.commands.registerCommand("rapid.showPath", () => showPath(context, pages, rapid)),
  );
}

/// What the adapter sends at each stop: the page it rewrote and its state.
interface PathEvent {
  page: string;
  state: { moves: unknown[] };
}

/// Keeps the panel at the debugger's stop: the state goes to the page the
/// panel shows for this session, or the session's page opens beside the
/// editor (the first stop after the robot moved, unless
/// `rapid.debug.showPath` is off; a panel open for another run follows too).
function followPath(session: vscode.DebugSession, event: PathEvent): void {
  if (panel && panelSession === session.id) {
    void panel.webview.postMessage(event.state);
    return;
  }
  const open = vscode.workspace.getConfiguration("rapid").get<boolean>("debug.showPath", true);
  if (!panel && !(open && event.state.moves.length > 0)) {
    return;
  }
  if (!fs.existsSync(event.page)) {
    return;
  }
  show(event.page, `Path: ${session.configuration.entry ?? "main"}`, session.id);
}

/// The page of a program's routine: one file per program and routine.
function pageFile(pages: string, program: string, entry: string): string {
  const hash = crypto.createHash("sha256").update(path.resolve(program)).digest("hex").slice(0, 12);
  return path.join(pages, `${entry.replace(/[^A-Za-z0-9_]/g, "_")}-${hash}.html`);
}

async function remember(context: vscode.ExtensionContext, run: LastRun): Promise<void> {
  const runs = context.workspaceState.get<LastRun[]>(RUNS_KEY, []).filter((r) => r.page !== run.page);
  runs.push(run);
  await context.workspaceState.update(RUNS_KEY, runs.slice(-50));
}

/// The routine around `line`: its kind and name, or undefined between routines.
export function routineAt(lines: string[], line: number): { kind: string; name: string } | undefined {
  const header = /^\s*(?:LOCAL\s+)?(PROC|FUNC\s+\w+|TRAP)\s+([A-Za-z][A-Za-z0-9_]*)/i;
  const end = /^\s*END(PROC|FUNC|TRAP)\b/i;
  for (let i = Math.min(line, lines.length - 1); i >= 0; i--) {
    const h = header.exec(lines[i]);
    if (h) {
      return { kind: h[1].split(/\s/)[0].toUpperCase(), name: h[2] };
    }
    if (i < line && end.test(lines[i])) {
      return undefined;
    }
  }
  return undefined;
}

/// Opens the path of the current routine's last run (a debug session of it,
/// or else a run of it now, with `rapid run --plot`).
async function showPath(context: vscode.ExtensionContext, pages: string, rapid: () => string): Promise<void> {
  const editor = vscode.window.activeTextEditor;
  if (editor?.document.languageId !== "rapid") {
    void vscode.window.showErrorMessage("RAPID: Show path: open a RAPID module and put the cursor in a procedure.");
    return;
  }
  const doc = editor.document;
  const lines = doc.getText().split(/\r?\n/);
  const routine = routineAt(lines, editor.selection.active.line);
  if (routine && routine.kind !== "PROC") {
    void vscode.window.showErrorMessage(
      `RAPID: Show path: ${routine.name} is a ${routine.kind}; put the cursor in a procedure (or between routines, for main).`,
    );
    return;
  }
  const entry = routine?.name ?? "main";
  const file = doc.uri.fsPath;
  // A debug session of this routine: its page, kept at its stops.
  const session = vscode.debug.activeDebugSession;
  const c = session?.configuration;
  if (
    session?.type === "rapid" &&
    typeof c?.plot === "string" &&
    typeof c.program === "string" &&
    (c.entry ?? "main").toLowerCase() === entry.toLowerCase() &&
    contains(c.program, file) &&
    fs.existsSync(c.plot)
  ) {
    show(c.plot, `Path: ${entry}`, session.id);
    return;
  }
  const last = context.workspaceState
    .get<LastRun[]>(RUNS_KEY, [])
    .filter((r) => r.entry.toLowerCase() === entry.toLowerCase() && contains(r.program, file))
    .filter((r) => fs.existsSync(r.page))
    .sort((a, b) => b.when - a.when)[0];
  if (last) {
    show(last.page, `Path: ${entry}`);
    return;
  }
  fs.mkdirSync(pages, { recursive: true });
  const page = pageFile(pages, file, entry);
  const command = rapid();
  const args = ["run", file, "--entry", entry, "--plot", page];
  runLog?.appendLine(`${command} ${args.join(" ")}`);
  const ran = await new Promise<{ code: number; stderr: string }>((resolve) => {
    execFile(command, args, { maxBuffer: 16 * 1024 * 1024 }, (err, stdout, stderr) => {
      runLog?.append(stdout);
      runLog?.append(stderr);
      const code = err ? (typeof err.code === "number" ? err.code : -1) : 0;
      resolve({ code, stderr: err && typeof err.code !== "number" ? String(err) : stderr });
    });
  });
  // status 1: the run ended with an error, and its path up to there is drawn
  if ((ran.code !== 0 && ran.code !== 1) || !fs.existsSync(page)) {
    runLog?.show(true);
    void vscode.window.showErrorMessage(`RAPID: Show path: ${entry} could not run: ${ran.stderr.trim()}`);
    return;
  }
  await remember(context, { program: file, entry, page, when: Date.now() });
  show(page, `Path: ${entry}`);
}

/// Whether `program` (a module or a task's folder) holds `file`.
function contains(program: string, file: string): boolean {
  const rel = path.relative(path.resolve(program), path.resolve(file));
  return rel === "" || (!rel.startsWith("..") && !path.isAbsolute(rel));
}

/// Shows `page` in the panel (beside the editor), following the debug
/// session `session` when given.
function show(page: string, title: string, session?: string): void {
  if (!panel) {
    panel = vscode.window.createWebviewPanel(
      "rapid.path",
      title,
      { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true },
      { enableScripts: true, retainContextWhenHidden: true },
    );
    panel.onDidDispose(() => {
      panel = undefined;
      panelSession = undefined;
    });
  }
  panel.title = title;
  panelSession = session;
  // the page is self-contained: its data and script are inline
  panel.webview.html = fs.readFileSync(page, "utf8");
  panel.reveal(undefined, true);
}
