// The ABB RAPID extension: starts `rapid lsp` and connects VS Code to it;
// the debugger and the path view are in run.ts.
import * as fs from "node:fs";
import * as path from "node:path";
import * as vscode from "vscode";
import {
  LanguageClient,
  type LanguageClientOptions,
  RevealOutputChannelOn,
  type ServerOptions,
  TransportKind,
} from "vscode-languageclient/node";
import { registerRun } from "./run";

let client: LanguageClient | undefined;
/// The extension's folder: its README says how to install the server.
let extensionUri: vscode.Uri | undefined;
let log: vscode.OutputChannel | undefined;
let traceLog: vscode.OutputChannel | undefined;

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  extensionUri = context.extensionUri;
  log = vscode.window.createOutputChannel("RAPID Language Server");
  traceLog = vscode.window.createOutputChannel("RAPID Language Server Trace");
  context.subscriptions.push(log, traceLog);

  context.subscriptions.push(
    vscode.commands.registerCommand("rapid.restartServer", async () => {
      await stopServer();
      await startServer();
    }),
    vscode.commands.registerCommand("rapid.showServerLog", () => log?.show(true)),
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (
        event.affectsConfiguration("rapid.server.path") ||
        event.affectsConfiguration("rapid.server.extraArgs")
      ) {
        await stopServer();
        await startServer();
      }
    }),
  );

  context.subscriptions.push({ dispose: () => void stopServer() });
  // The `rapid` debugger (`rapid dap`) and "Show path", with the binary
  // found as the server's is.
  registerRun(context, () => {
    const config = vscode.workspace.getConfiguration("rapid");
    const configured = (config.get<string>("server.path") ?? "").trim();
    return configured ? expandHome(configured) : (findOnPath("rapid") ?? "rapid");
  });
  await startServer();
}

export async function deactivate(): Promise<void> {
  await stopServer();
}

async function startServer(): Promise<void> {
  const config = vscode.workspace.getConfiguration("rapid");
  const configured = (config.get<string>("server.path") ?? "").trim();
  const command = configured ? expandHome(configured) : findOnPath("rapid");
  if (!command || (configured && !isExecutable(command))) {
    await reportMissingServer(configured);
    return;
  }
  const extraArgs = config.get<string[]>("server.extraArgs") ?? [];
  log?.appendLine(`Starting ${command} lsp ${extraArgs.join(" ")}`.trimEnd());

  const run = {
    command,
    args: ["lsp", ...extraArgs],
    transport: TransportKind.stdio,
  };
  const serverOptions: ServerOptions = { run, debug: run };
  const clientOptions: LanguageClientOptions = {
    documentSelector: [
      { scheme: "file", language: "rapid" },
      { scheme: "untitled", language: "rapid" },
    ],
    outputChannel: log,
    traceOutputChannel: traceLog,
    revealOutputChannelOn: RevealOutputChannelOn.Never,
    synchronize: {
      // EIO.cfg declares the I/O signals that programs use by name.
      fileEvents: vscode.workspace.createFileSystemWatcher("**/*.{cfg,CFG,toml}"),
      // The server reads its settings from the `rapid` section (it ignores
      // `rapid.server` and `rapid.trace`, which are the extension's).
      configurationSection: "rapid",
    },
    initializationOptions: { rapid: settingsForServer() },
  };

  client = new LanguageClient("rapid", "RAPID Language Server", serverOptions, clientOptions);
  try {
    await client.start();
  } catch (err) {
    log?.appendLine(`The server failed to start: ${String(err)}`);
    void vscode.window.showErrorMessage(
      `The RAPID language server (${command} lsp) failed to start: ${String(err)}`,
    );
  }
}

async function stopServer(): Promise<void> {
  const running = client;
  client = undefined;
  if (running) {
    try {
      await running.stop();
    } catch (err) {
      log?.appendLine(`Stopping the server: ${String(err)}`);
    }
  }
}

async function reportMissingServer(configured: string): Promise<void> {
  const what = configured
    ? `The rapid binary set in 'rapid.server.path' (${configured}) does not exist or cannot be run.`
    : "The rapid binary was not found on PATH.";
  log?.appendLine(`${what} Install it with 'cargo install --path lsp' in a clone of rapid (see the extension's README).`);
  const choice = await vscode.window.showErrorMessage(
    `${what} RAPID diagnostics, hover and completion need it.`,
    "How to install",
    "Set path",
  );
  if (choice === "How to install" && extensionUri) {
    // The project has no public home yet: its README, shipped with the
    // extension, says how to install the server.
    await vscode.commands.executeCommand(
      "markdown.showPreview",
      vscode.Uri.joinPath(extensionUri, "README.md"),
    );
  } else if (choice === "Set path") {
    await vscode.commands.executeCommand("workbench.action.openSettings", "rapid.server.path");
  }
}

/// The `rapid` settings as plain JSON, for the server's initialization.
function settingsForServer(): unknown {
  return JSON.parse(JSON.stringify(vscode.workspace.getConfiguration("rapid")));
}

function expandHome(file: string): string {
  const home = process.env.HOME ?? process.env.USERPROFILE ?? "";
  return file.startsWith("~/") && home ? path.join(home, file.slice(2)) : file;
}

function isExecutable(file: string): boolean {
  try {
    const stat = fs.statSync(file);
    if (!stat.isFile()) {
      return false;
    }
    if (process.platform !== "win32") {
      fs.accessSync(file, fs.constants.X_OK);
    }
    return true;
  } catch {
    return false;
  }
}

function findOnPath(name: string): string | undefined {
  const dirs = (process.env.PATH ?? "").split(path.delimiter).filter(Boolean);
  const exts =
    process.platform === "win32"
      ? (process.env.PATHEXT ?? ".EXE;.CMD;.BAT").split(";").map((e) => e.toLowerCase())
      : [""];
  for (const dir of dirs) {
    for (const ext of exts) {
      const candidate = path.join(dir, name + ext);
      if (isExecutable(candidate)) {
        return candidate;
      }
    }
  }
  return undefined;
}
