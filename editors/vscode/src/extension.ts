// The ABB RAPID extension: starts `rapid lsp` and connects VS Code to it;
// finding the binary is in binary.ts, whether a workspace holds RAPID code
// in workspace.ts, the debugger and the path view in run.ts.
import * as vscode from "vscode";
import {
  LanguageClient,
  type LanguageClientOptions,
  RevealOutputChannelOn,
  type ServerOptions,
  TransportKind,
} from "vscode-languageclient/node";
import { askForPath, binaryOrName, findBinary, reportMissing } from "./binary";
import { registerDiff } from "./diff";
import { registerRun } from "./run";
import { holdsRapid } from "./workspace";

let client: LanguageClient | undefined;
/// The extension's folder: its README says how to install the server.
let extensionUri: vscode.Uri | undefined;
let log: vscode.OutputChannel | undefined;
let traceLog: vscode.OutputChannel | undefined;
/// The server was asked for: the workspace holds RAPID code, or a RAPID
/// file was opened (until then the extension waits, see `activate`).
let wanted = false;

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  extensionUri = context.extensionUri;
  log = vscode.window.createOutputChannel("RAPID Language Server");
  traceLog = vscode.window.createOutputChannel("RAPID Language Server Trace");
  context.subscriptions.push(log, traceLog);

  context.subscriptions.push(
    vscode.commands.registerCommand("rapid.restartServer", async () => {
      wanted = true;
      await stopServer();
      await startServer();
    }),
    vscode.commands.registerCommand("rapid.showServerLog", () => log?.show(true)),
    vscode.commands.registerCommand("rapid.setServerPath", () => askForPath()),
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (
        wanted &&
        (event.affectsConfiguration("rapid.server.path") ||
          event.affectsConfiguration("rapid.server.extraArgs"))
      ) {
        await stopServer();
        await startServer();
      }
    }),
  );

  context.subscriptions.push({ dispose: () => void stopServer() });
  // The `rapid` debugger (`rapid dap`), "Show path" and "Compare with
  // backup…", with the binary found as the server's is.
  registerRun(context, binaryOrName);
  registerDiff(context, binaryOrName);

  // A workspace with RAPID modules, a backup's BACKINFO or SYSPAR, a
  // rapid.toml or a .pgf program starts the server at once: it checks every
  // file, and the Problems panel lists them before any is opened. Any other
  // workspace (activated for a `.mod` or `.sys` of another language) waits
  // for a RAPID file to be opened.
  const rapidOpen = () => vscode.workspace.textDocuments.some((d) => d.languageId === "rapid");
  if (rapidOpen() || (await holdsRapid())) {
    wanted = true;
    await startServer();
  } else {
    const waiting = vscode.workspace.onDidOpenTextDocument(async (doc) => {
      if (doc.languageId === "rapid" && !wanted) {
        wanted = true;
        waiting.dispose();
        await startServer();
      }
    });
    context.subscriptions.push(waiting);
  }
}

export async function deactivate(): Promise<void> {
  await stopServer();
}

async function startServer(): Promise<void> {
  const config = vscode.workspace.getConfiguration("rapid");
  const { command, configured } = findBinary();
  if (!command) {
    const readme = extensionUri && vscode.Uri.joinPath(extensionUri, "README.md");
    void reportMissing(configured, readme, log);
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

/// The `rapid` settings as plain JSON, for the server's initialization.
function settingsForServer(): unknown {
  return JSON.parse(JSON.stringify(vscode.workspace.getConfiguration("rapid")));
}
