// The `rapid` binary: where it is (the `rapid.server.path` setting, else
// PATH), and what to say and offer when it is missing.
import * as fs from "node:fs";
import * as path from "node:path";
import * as vscode from "vscode";

/// The binary as configured or found on PATH; `undefined` when missing.
/// `configured` is the setting's value, for the message.
export interface Binary {
  command: string | undefined;
  configured: string;
}

export function findBinary(): Binary {
  const config = vscode.workspace.getConfiguration("rapid");
  const configured = (config.get<string>("server.path") ?? "").trim();
  if (configured) {
    const file = expandHome(configured);
    return { command: isExecutable(file) ? file : undefined, configured };
  }
  return { command: findOnPath("rapid"), configured };
}

/// The command the debugger and "Show path" run (`rapid` when missing, so
/// that the error names it).
export function binaryOrName(): string {
  return findBinary().command ?? "rapid";
}

/// Says that the binary is missing, how to install it, and offers to open
/// the install instructions or to give its path. `readme` is the
/// extension's README (the project has no public home yet).
export async function reportMissing(
  configured: string,
  readme: vscode.Uri | undefined,
  log: vscode.OutputChannel | undefined,
): Promise<void> {
  const what = configured
    ? `The rapid binary set in 'rapid.server.path' (${configured}) does not exist or cannot be run.`
    : "The rapid binary was not found on PATH.";
  const how =
    "Install it with 'cargo install --path lsp' in a clone of rapid (it goes to ~/.cargo/bin), or set its path.";
  log?.appendLine(`${what} ${how}`);
  const choice = await vscode.window.showErrorMessage(
    `${what} RAPID diagnostics, hover and completion need it. ${how}`,
    "How to install",
    "Set path",
  );
  if (choice === "How to install" && readme) {
    await vscode.commands.executeCommand("markdown.showPreview", readme);
  } else if (choice === "Set path") {
    await askForPath();
  }
}

/// Asks for the binary's path and saves it as `rapid.server.path` (the
/// server restarts on the change). An input box, not the Settings page:
/// in a remote window (code-server, SSH) the setting belongs to the remote
/// machine, which the user settings page does not show.
export async function askForPath(): Promise<void> {
  const config = vscode.workspace.getConfiguration("rapid");
  const home = process.env.HOME ?? process.env.USERPROFILE ?? "";
  const suggestion = home ? path.join(home, ".cargo", "bin", exeName("rapid")) : "";
  const value = await vscode.window.showInputBox({
    title: "Path of the rapid binary",
    prompt: "The `rapid` binary (cargo install --path lsp puts it in ~/.cargo/bin). Saved as rapid.server.path.",
    value: (config.get<string>("server.path") ?? "").trim() || suggestion,
    ignoreFocusOut: true,
    validateInput: (text) => {
      const file = expandHome(text.trim());
      if (!file) return "Give the path of the rapid binary.";
      return isExecutable(file) ? undefined : `${file} does not exist or cannot be run.`;
    },
  });
  if (value === undefined) {
    return;
  }
  await config.update("server.path", value.trim(), vscode.ConfigurationTarget.Global);
}

function exeName(name: string): string {
  return process.platform === "win32" ? `${name}.exe` : name;
}

export function expandHome(file: string): string {
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
