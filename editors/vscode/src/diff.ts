// "RAPID: Compare with backup…": `rapid diff` between a backup (or task
// folder, or module) chosen in a dialog and the workspace folder (or the
// folder or file the command was run on in the Explorer), shown in the
// "RAPID Changes" view: tasks, modules, moved targets, data, routines,
// configuration and built-ins. A changed module opens VS Code's diff of its
// two files; a datum, routine or configuration entry opens at its line.
// "RAPID: Open Changes Report" shows the Markdown report of the last
// comparison (the one `rapid diff --format markdown` writes for a pull
// request).
import { execFile } from "node:child_process";
import * as fs from "node:fs";
import * as path from "node:path";
import * as vscode from "vscode";

// The parts of `rapid diff --format json` shown here (docs/diff.md).
interface Side {
  declaration: string;
  value?: string;
  line: number;
}
interface Motion {
  translation_mm?: number;
  rotation_deg?: number;
  joints_deg?: number;
  conf?: [string, string];
  external_axes?: { path: string; old: string; new: string }[];
  reach?: { reachable: boolean; detail: string };
}
interface Datum {
  name: string;
  status: Status;
  old?: Side;
  new?: Side;
  changed: string[];
  derived?: boolean;
  motion?: Motion;
  fields?: { path: string; old: string; new: string }[];
}
interface Routine {
  name: string;
  kind: string;
  status: Status;
  old_line?: number;
  new_line?: number;
  hunks: { lines: { tag: "context" | "removed" | "added"; depth: number; text: string }[] }[];
}
interface Module {
  name: string;
  status: Status;
  old_file?: string;
  new_file?: string;
  data: Datum[];
  routines: Routine[];
  types: Routine[];
}
interface Instance {
  type: string;
  instance: string;
  status: Status;
  label?: string;
  attributes: { name: string; old: string | null; new: string | null }[];
  old_line?: number;
  new_line?: number;
}
type Status = "added" | "removed" | "changed";
interface Report {
  summary: Record<string, number>;
  tasks: { name: string; status: Status; modules: Module[] }[];
  config: { file: string; status: Status; instances: Instance[] }[];
  builtins: null | {
    old_robotware: string;
    new_robotware: string;
    changed: { name: string; kind: string; old: string; new: string }[];
  };
  ignored_moves: number;
}

/// One row of the view.
interface Row {
  label: string;
  description?: string;
  tooltip?: string;
  icon?: string;
  command?: vscode.Command;
  children: Row[];
}

/// The sides of the last comparison.
interface Compared {
  old: string;
  new: string;
}

class ChangesView implements vscode.TreeDataProvider<Row> {
  private rows: Row[] = [];
  private readonly changed = new vscode.EventEmitter<Row | undefined>();
  readonly onDidChangeTreeData = this.changed.event;

  show(rows: Row[]): void {
    this.rows = rows;
    this.changed.fire(undefined);
  }

  getTreeItem(row: Row): vscode.TreeItem {
    const state =
      row.children.length === 0
        ? vscode.TreeItemCollapsibleState.None
        : vscode.TreeItemCollapsibleState.Expanded;
    const item = new vscode.TreeItem(row.label, state);
    item.description = row.description;
    item.tooltip = row.tooltip;
    item.command = row.command;
    if (row.icon) {
      item.iconPath = new vscode.ThemeIcon(row.icon);
    }
    return item;
  }

  getChildren(row?: Row): Row[] {
    return row ? row.children : this.rows;
  }
}

/// Registers the command, the view and the report; `rapid` names the binary.
export function registerDiff(context: vscode.ExtensionContext, rapid: () => string): void {
  const view = new ChangesView();
  const tree = vscode.window.createTreeView("rapid.changes", { treeDataProvider: view });
  let last: Compared | undefined;
  context.subscriptions.push(
    tree,
    vscode.commands.registerCommand("rapid.compareWithBackup", async (target?: vscode.Uri) => {
      const now = target?.fsPath ?? current();
      if (!now) {
        void vscode.window.showErrorMessage("RAPID: Compare with backup: open a folder or a RAPID module first.");
        return;
      }
      const picked = await vscode.window.showOpenDialog({
        canSelectFiles: true,
        canSelectFolders: true,
        canSelectMany: false,
        defaultUri: vscode.Uri.file(path.dirname(now)),
        openLabel: "Compare with this backup",
        title: `Compare ${path.basename(now)} with a backup, task folder or module`,
      });
      if (!picked?.[0]) {
        return;
      }
      const compared = { old: picked[0].fsPath, new: now };
      const report = await vscode.window.withProgress(
        { location: { viewId: "rapid.changes" }, title: "Comparing" },
        () => runDiff(rapid(), compared, "json"),
      );
      if (report === undefined) {
        return;
      }
      last = compared;
      view.show(rowsOf(JSON.parse(report) as Report, compared));
      tree.title = `RAPID Changes: ${path.basename(compared.old)} → ${path.basename(compared.new)}`;
      tree.message = summary(JSON.parse(report) as Report);
      await vscode.commands.executeCommand("setContext", "rapid.changesShown", true);
      await vscode.commands.executeCommand("rapid.changes.focus");
    }),
    vscode.commands.registerCommand("rapid.changesReport", async () => {
      if (!last) {
        void vscode.window.showErrorMessage("RAPID: Open Changes Report: compare with a backup first.");
        return;
      }
      const markdown = await runDiff(rapid(), last, "markdown");
      if (markdown === undefined) {
        return;
      }
      const doc = await vscode.workspace.openTextDocument({ language: "markdown", content: markdown });
      await vscode.commands.executeCommand("markdown.showPreview", doc.uri);
    }),
  );
}

/// The folder to compare when the command is not run on one: the
/// workspace folder of the active file, else the first one.
function current(): string | undefined {
  const active = vscode.window.activeTextEditor?.document.uri;
  const folder = (active && vscode.workspace.getWorkspaceFolder(active)) ?? vscode.workspace.workspaceFolders?.[0];
  return folder?.uri.fsPath ?? (active?.scheme === "file" ? active.fsPath : undefined);
}

/// `rapid diff OLD NEW --format FORMAT`: its output, or undefined after
/// showing why it failed.
function runDiff(rapid: string, sides: Compared, format: string): Promise<string | undefined> {
  return new Promise((resolve) => {
    execFile(
      rapid,
      ["diff", sides.old, sides.new, "--format", format],
      { maxBuffer: 256 * 1024 * 1024 },
      (err, stdout, stderr) => {
        if (err && !stdout) {
          void vscode.window.showErrorMessage(`rapid diff failed: ${(stderr || err.message).trim()}`);
          resolve(undefined);
          return;
        }
        resolve(stdout);
      },
    );
  });
}

function amount(x: number): string {
  if (x > 0 && x < 0.0005) {
    return "<0.001";
  }
  return String(Number(x.toFixed(3)));
}

/// How far a datum moved: `12.3 mm, 2°, conf …`.
export function motionWords(m: Motion): string {
  const parts: string[] = [];
  const turned = (m.rotation_deg ?? 0) > 0;
  if (m.translation_mm !== undefined && (m.translation_mm > 0 || !turned)) {
    parts.push(`${amount(m.translation_mm)} mm`);
  }
  if (turned) {
    parts.push(`${amount(m.rotation_deg ?? 0)}°`);
  }
  if (m.joints_deg !== undefined) {
    parts.push(`joints up to ${amount(m.joints_deg)}°`);
  }
  if (m.conf) {
    parts.push(`conf ${m.conf[0]} → ${m.conf[1]}`);
  }
  for (const e of m.external_axes ?? []) {
    parts.push(`${e.path.split(".").pop()} ${e.old} → ${e.new}`);
  }
  if (m.reach) {
    parts.push(m.reach.reachable ? `reachable (${m.reach.detail})` : `not reachable: ${m.reach.detail}`);
  }
  return parts.join(", ");
}

function summary(r: Report): string {
  const s = r.summary;
  const parts: string[] = [];
  const count = (n: number | undefined, one: string, many: string) => {
    if (n) parts.push(`${n} ${n === 1 ? one : many}`);
  };
  count(s.modules_added, "module added", "modules added");
  count(s.modules_removed, "module removed", "modules removed");
  count(s.modules_changed, "module changed", "modules changed");
  count(s.routines, "routine", "routines");
  count(s.moves, "position moved", "positions moved");
  count(s.data, "datum", "data");
  count(s.types, "type", "types");
  count(s.config, "configuration entry", "configuration entries");
  count(s.builtins, "built-in signature", "built-in signatures");
  const text = parts.length ? parts.join(", ") : "No changes";
  const left = r.ignored_moves === 1 ? "1 smaller move left out" : `${r.ignored_moves} smaller moves left out`;
  return r.ignored_moves ? `${text}; ${left}` : text;
}

/// Opens `file` at a 1-based line.
function openAt(file: string, line?: number): vscode.Command {
  const at = Math.max(0, (line ?? 1) - 1);
  return {
    title: "Open",
    command: "vscode.open",
    arguments: [vscode.Uri.file(file), { selection: new vscode.Range(at, 0, at, 0) }],
  };
}

const ICONS: Record<Status, string> = { added: "diff-added", removed: "diff-removed", changed: "diff-modified" };

/// The rows of a report: tasks (unless there is only the folder itself),
/// modules, their data and routines, configuration, built-ins.
export function rowsOf(r: Report, sides: Compared): Row[] {
  const root = (side: string) => (fs.existsSync(side) && fs.statSync(side).isFile() ? path.dirname(side) : side);
  const oldFile = (m: Module) => (m.old_file ? path.join(root(sides.old), m.old_file) : undefined);
  const newFile = (m: Module) => (m.new_file ? path.join(root(sides.new), m.new_file) : undefined);
  const moduleRow = (m: Module): Row => {
    const [a, b] = [oldFile(m), newFile(m)];
    const children: Row[] = [];
    for (const d of m.data) {
      const moved = d.motion && (d.motion.translation_mm || d.motion.rotation_deg || d.motion.joints_deg || d.motion.conf || d.motion.external_axes?.length);
      const fields = (d.fields ?? []).map((f) => `${f.path || "value"} ${f.old} → ${f.new}`).join(", ");
      const declaration = d.changed.filter((c) => c !== "value").length
        ? `${d.old?.declaration} → ${d.new?.declaration}`
        : "";
      const words = [moved ? motionWords(d.motion ?? {}) : "", declaration, fields].filter((w) => w).join("; ");
      const description = d.status === "changed" ? words || `${d.old?.value ?? ""} → ${d.new?.value ?? ""}` : d.status;
      const side = d.new ?? d.old;
      children.push({
        label: d.name,
        description: d.derived ? `${description} (computed from changed data)` : description,
        tooltip: `${side?.declaration ?? d.name}\n${d.old?.value ?? ""}\n→ ${d.new?.value ?? ""}`,
        icon: moved ? "move" : ICONS[d.status],
        command: d.new && b ? openAt(b, d.new.line) : d.old && a ? openAt(a, d.old.line) : undefined,
        children: [],
      });
    }
    for (const x of [...m.types, ...m.routines]) {
      const lines = x.hunks.flatMap((h) => h.lines);
      const added = lines.filter((l) => l.tag === "added").length;
      const removed = lines.filter((l) => l.tag === "removed").length;
      const mark = { context: " ", removed: "-", added: "+" };
      children.push({
        label: `${x.kind} ${x.name}`,
        description: x.status === "changed" ? `+${added} −${removed}` : x.status,
        tooltip: lines.map((l) => `${mark[l.tag]} ${"  ".repeat(l.depth)}${l.text}`).join("\n"),
        icon: ICONS[x.status],
        command: x.new_line && b ? openAt(b, x.new_line) : x.old_line && a ? openAt(a, x.old_line) : undefined,
        children: [],
      });
    }
    const both = a && b;
    return {
      label: m.name,
      description: `${m.status} · ${m.new_file ?? m.old_file ?? ""}`,
      icon: ICONS[m.status],
      command: both
        ? {
            title: "Compare",
            command: "vscode.diff",
            arguments: [vscode.Uri.file(a), vscode.Uri.file(b), `${m.name} (backup ↔ current)`],
          }
        : openAt((b ?? a) as string),
      children: m.status === "changed" ? children : [],
    };
  };
  const rows: Row[] = [];
  for (const t of r.tasks) {
    const modules = t.modules.map(moduleRow);
    if (t.name === "." && r.tasks.length === 1) {
      rows.push(...modules);
    } else {
      rows.push({ label: `Task ${t.name}`, description: t.status, icon: "server-process", children: modules });
    }
  }
  if (r.config.length) {
    rows.push({
      label: "Configuration",
      icon: "settings-gear",
      children: r.config.map((c) => ({
        label: c.file,
        description: c.status,
        icon: ICONS[c.status],
        children: c.instances.map((i) => {
          const attrs = i.attributes
            .filter((a) => i.status === "changed" || a.name.toLowerCase() !== "name")
            .map((a) => (i.status === "changed" ? `${a.name} ${a.old ?? "(none)"} → ${a.new ?? "(none)"}` : `${a.name} ${a.old ?? a.new ?? ""}`))
            .join(", ");
          const file = path.join(root(i.status === "removed" ? sides.old : sides.new), c.file);
          return {
            label: `${i.type} ${i.instance}`,
            description: `${i.label && i.status === "changed" ? i.label : i.status}: ${attrs}`,
            icon: ICONS[i.status],
            command: openAt(file, i.status === "removed" ? i.old_line : i.new_line),
            children: [],
          };
        }),
      })),
    });
  }
  if (r.builtins?.changed.length) {
    const b = r.builtins;
    rows.push({
      label: `Built-ins (RobotWare ${b.old_robotware} → ${b.new_robotware})`,
      icon: "library",
      children: b.changed.map((c) => ({
        label: c.name,
        description: c.kind,
        tooltip: `${b.old_robotware}: ${c.old}\n${b.new_robotware}: ${c.new}`,
        icon: "symbol-method",
        children: [],
      })),
    });
  }
  return rows;
}
