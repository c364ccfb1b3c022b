// Whether a workspace holds RAPID code: the extension activates on
// workspaces that may (see `activationEvents`) and starts the language
// server only when one does, so that the Problems panel lists the whole
// workspace before any file is opened, and a Go module (`go.mod`) or a
// Windows driver (`.sys`) does not start it.
import * as vscode from "vscode";

/// Extensions of RAPID modules, in any letter case.
const MODULES = "**/*.{mod,MOD,Mod,modx,MODX,sys,SYS,Sys,sysx,SYSX,prg,PRG}";
/// What a controller backup or a RAPID project has beside its modules.
const MARKERS = "{**/BACKINFO/*,**/SYSPAR/*,**/rapid.toml,**/*.pgf,**/*.PGF}";
const EXCLUDE = "{**/node_modules/**,**/.git/**,**/target/**}";

/// Does the text start like a RAPID module (a `%%%` header or `MODULE
/// name`), as the language's `firstLine` says?
export function looksLikeRapid(text: string): boolean {
  for (const raw of text.replace(/^\ufeff/, "").split(/\r?\n|\r/)) {
    const line = raw.trim();
    if (line === "" || line.startsWith("!")) {
      continue;
    }
    return /^(%%%|module\s+[a-z][a-z0-9_]*\s*(\(|!|$))/i.test(line);
  }
  return false;
}

/// Whether the open workspace holds RAPID code: a backup's or a project's
/// markers, or a module that starts like one (the first few looked at).
export async function holdsRapid(): Promise<boolean> {
  if (!vscode.workspace.workspaceFolders?.length) {
    return false;
  }
  if ((await vscode.workspace.findFiles(MARKERS, EXCLUDE, 1)).length > 0) {
    return true;
  }
  const modules = await vscode.workspace.findFiles(MODULES, EXCLUDE, 50);
  for (const uri of modules) {
    try {
      const bytes = await vscode.workspace.fs.readFile(uri);
      if (looksLikeRapid(Buffer.from(bytes.subarray(0, 4096)).toString("latin1"))) {
        return true;
      }
    } catch {
      // unreadable: not evidence either way
    }
  }
  return false;
}
