// "RAPID: Compare with backup…" in the real editor: a backup of the
// workspace made before two changes (a target moved by 12.5 mm, a statement
// added) is chosen in the file dialog; the "RAPID Changes" view must show
// what `rapid diff BACKUP WORKSPACE --format json` says, a changed module
// opens VS Code's diff of its two files, and "RAPID: Open Changes Report"
// opens the Markdown report in a preview.
import { spawnSync } from "node:child_process";
import * as fs from "node:fs";
import * as path from "node:path";

/** Runs the checks; `ctx` holds run.mjs's helpers. */
export async function diffSteps(ctx) {
  const { page, ws, tmp, out, rapid, step, assert, runCommand, TIMEOUT } = ctx;
  // The backup: the workspace as it was before the two changes.
  const backup = path.join(tmp, "backup-before");
  fs.cpSync(ws, backup, { recursive: true });
  const main = path.join(backup, "MainModule.mod");
  const text = fs.readFileSync(main, "latin1");
  const before = text
    .replace("[[812.5,-402.1,455]", "[[800,-402.1,455]")
    .replace('        nPlaced := "none";\n', "");
  assert(before !== text, "the workspace's MainModule.mod changed: the backup's edits do not apply");
  fs.writeFileSync(main, before, "latin1");
  const r = spawnSync(rapid, ["diff", backup, ws, "--format", "json"], { encoding: "utf8" });
  assert(r.status === 0, `rapid diff: ${r.stderr}`);
  const report = JSON.parse(r.stdout);
  const module = report.tasks[0]?.modules.find((m) => m.name === "MainModule");
  const moved = module?.data.find((d) => d.name === "pPickAbove");
  assert(moved?.motion?.translation_mm === 12.5, `rapid diff says ${r.stdout}`);
  const routine = module.routines.find((x) => x.name === "GoHome");
  assert(routine, `rapid diff says ${r.stdout}`);

  const pane = page.locator(".pane", { has: page.locator(".pane-header", { hasText: /RAPID Changes/i }) });
  const rows = pane.locator(".monaco-list-row");

  await step("Compare with backup… shows the changes in the RAPID Changes view", async () => {
    await page.keyboard.press("Escape");
    // The simple file dialog checks the typed path asynchronously: on a busy
    // machine an Enter pressed too early is lost, so it is tried again.
    for (let attempt = 1; ; attempt++) {
      await runCommand("RAPID: Compare with backup…");
      const input = page.locator(".quick-input-widget input");
      await input.waitFor({ state: "visible" });
      // With a final `/` the dialog goes into the folder; its button then
      // accepts the folder it is in (Enter could take the folder above).
      await input.fill(`${backup}/`);
      await page.waitForTimeout(1500 * attempt);
      const accept = page.locator(".quick-input-widget .monaco-button", { hasText: "Compare with this backup" });
      if ((await accept.count()) > 0) {
        await accept.first().click();
      } else {
        await page.keyboard.press("Enter");
      }
      try {
        await rows.filter({ hasText: "pPickAbove" }).first().waitFor({ state: "visible", timeout: 20000 });
        break;
      } catch (e) {
        await page.screenshot({ path: path.join(out, `vscode-changes-failed-${attempt}.png`) }).catch(() => {});
        if (attempt >= 3) throw e;
        await page.keyboard.press("Escape");
      }
    }
    const title = await pane.locator(".pane-header").first().innerText();
    assert(/backup-before/i.test(title), `the view compares ${title}`);
    const texts = (await rows.allInnerTexts()).map((t) => t.replace(/\s+/g, " ").trim());
    await page.screenshot({ path: path.join(out, "vscode-changes.png") });
    const target = texts.find((t) => t.includes("pPickAbove"));
    assert(target?.includes("12.5 mm"), `the view shows ${JSON.stringify(texts)}`);
    assert(texts.some((t) => t.includes("PROC GoHome") && t.includes("+1")), `the view shows ${JSON.stringify(texts)}`);
    assert(texts.some((t) => t.startsWith("MainModule")), `the view shows ${JSON.stringify(texts)}`);
  });

  await step("a changed module opens the diff of its two files", async () => {
    await rows.filter({ hasText: /^MainModule/ }).first().click();
    const tab = page.locator(".tabs-container .tab", { hasText: "MainModule (backup ↔ current)" });
    await tab.first().waitFor({ state: "visible", timeout: TIMEOUT });
    await page.locator(".monaco-diff-editor").first().waitFor({ state: "visible" });
    await page.screenshot({ path: path.join(out, "vscode-changes-diff.png") });
  });

  await step("RAPID: Open Changes Report opens the Markdown report", async () => {
    await runCommand("RAPID: Open Changes Report");
    const preview = page.locator(".tabs-container .tab", { hasText: /Preview/ });
    await preview.first().waitFor({ state: "visible", timeout: TIMEOUT });
    // the report is the untitled Markdown document the preview shows
    const report = page.locator(".tabs-container .tab", { hasText: "### rapid diff" });
    await report.first().waitFor({ state: "visible", timeout: TIMEOUT });
    // the report itself is the untitled Markdown document beside it
    const markdown = spawnSync(rapid, ["diff", backup, ws, "--format", "markdown"], { encoding: "utf8" }).stdout;
    assert(markdown.includes("`pPickAbove` | 12.5 mm"), `rapid diff --format markdown: ${markdown}`);
    await page.screenshot({ path: path.join(out, "vscode-changes-report.png") });
  });
}
